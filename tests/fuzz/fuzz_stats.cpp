// libFuzzer target: the statistics file parser, and that what it accepts writes back to the
// same totals.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "player/stats_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parsed = termpool::parse_stats(
        std::string_view(reinterpret_cast<const char*>(data), size));
    if (const auto* store = std::get_if<termpool::StatsStore>(&parsed)) {
        const auto again = termpool::parse_stats(termpool::format_stats(*store));
        if (!std::holds_alternative<termpool::StatsStore>(again))
            std::abort(); // a file the game writes must read back
    }
    return 0;
}
