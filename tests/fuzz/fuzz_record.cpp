// libFuzzer target: the save parser and the replay of what it accepts.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <termpool/match.hpp>
#include <termpool/record.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto parsed = termpool::parse_record(text);
    if (const auto* record = std::get_if<termpool::GameRecord>(&parsed)) {
        // Long games only repeat what short ones test; keep each run quick.
        if (record->actions.size() <= 8)
            termpool::Match::replay(*record);
    }
    return 0;
}
