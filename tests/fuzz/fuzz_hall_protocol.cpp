// libFuzzer target: the hall's line protocol, both directions; what a parser accepts formats
// back to a line it reads the same way.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "hall/protocol.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view line(reinterpret_cast<const char*>(data), size);
    const auto client = termpool::hall::parse_client(line);
    if (const auto* m = std::get_if<termpool::hall::ClientMessage>(&client)) {
        const std::string again = termpool::hall::format_client(*m);
        const auto reread =
            termpool::hall::parse_client(std::string_view(again).substr(0, again.size() - 1));
        if (!std::holds_alternative<termpool::hall::ClientMessage>(reread))
            std::abort();
    }
    const auto server = termpool::hall::parse_server(line);
    if (const auto* m = std::get_if<termpool::hall::ServerMessage>(&server)) {
        const std::string again = termpool::hall::format_server(*m);
        const auto reread =
            termpool::hall::parse_server(std::string_view(again).substr(0, again.size() - 1));
        if (!std::holds_alternative<termpool::hall::ServerMessage>(reread))
            std::abort();
    }
    return 0;
}
