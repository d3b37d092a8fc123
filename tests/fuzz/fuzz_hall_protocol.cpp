// libFuzzer target: the hall's line protocol, both directions. Each value has one text, so a
// line a parser accepts is exactly the line its message formats to; a name a hello accepts
// holds nothing hidden, and its key (the hall's comparison) is stable. Read as a server's lines,
// the input goes through the client's bounds (small ones, to be reached) without a crash, and
// the client stops at the first line they refuse.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <termpool/name_characters.hpp>
#include <variant>

#include "hall/name_key.hpp"
#include "hall/protocol.hpp"
#include "hall/server_bounds.hpp"

namespace {

void check_name(const std::string& name) {
    if (termpool::name_characters_problem(name))
        std::abort();
    const std::string key = termpool::hall::name_key(name);
    if (termpool::hall::name_key(key) != key) // NFKC_Casefold is its own fixed point
        std::abort();
}

// Each line of `text` the server parser accepts goes to one ServerBounds, as a client takes
// them; the bounds are small so that the fuzzer reaches them.
void check_bounds(std::string_view text) {
    termpool::hall::ServerBoundLimits limits;
    limits.record_bytes = 4096;
    limits.record_lines = 16;
    limits.records_at_once = 2;
    limits.lobby_tables = 3;
    limits.lobby_players = 3;
    termpool::hall::ServerBounds bounds(limits);
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        const auto parsed = termpool::hall::parse_server(line);
        if (const auto* m = std::get_if<termpool::hall::ServerMessage>(&parsed))
            if (!bounds.check(*m).empty())
                return; // a client ends the connection here
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view line(reinterpret_cast<const char*>(data), size);
    // Any text's key, valid or not, is made without a crash.
    termpool::hall::name_key(line);
    const auto client = termpool::hall::parse_client(line);
    if (const auto* m = std::get_if<termpool::hall::ClientMessage>(&client)) {
        if (termpool::hall::format_client(*m) != std::string(line) + "\n")
            std::abort();
        if (const auto* hello = std::get_if<termpool::hall::Hello>(m))
            check_name(hello->name);
    }
    const auto server = termpool::hall::parse_server(line);
    if (const auto* m = std::get_if<termpool::hall::ServerMessage>(&server)) {
        if (termpool::hall::format_server(*m) != std::string(line) + "\n")
            std::abort();
    }
    check_bounds(line);
    return 0;
}
