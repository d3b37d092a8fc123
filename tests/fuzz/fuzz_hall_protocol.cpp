// libFuzzer target: the hall's line protocol, both directions. Each value has one text, so a
// line a parser accepts is exactly the line its message formats to; a name a hello accepts
// holds nothing hidden, and its key (the hall's comparison) is stable.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <termpool/name_characters.hpp>
#include <variant>

#include "hall/name_key.hpp"
#include "hall/protocol.hpp"

namespace {

void check_name(const std::string& name) {
    if (termpool::name_characters_problem(name))
        std::abort();
    const std::string key = termpool::hall::name_key(name);
    if (termpool::hall::name_key(key) != key) // NFKC_Casefold is its own fixed point
        std::abort();
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
    return 0;
}
