// libFuzzer target: the save parser and the replay of what it accepts. What reads writes a
// text that reads back to itself; a record of version 6 holds each action in its one text, and
// one whose replay passes its running check passes it again once written back.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <termpool/match.hpp>
#include <termpool/record.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto parsed = termpool::parse_record(text);
    const auto* record = std::get_if<termpool::GameRecord>(&parsed);
    if (!record)
        return 0;
    const std::string written = termpool::format_record(*record);
    const auto again = termpool::parse_record(written);
    const auto* reread = std::get_if<termpool::GameRecord>(&again);
    if (!reread || termpool::format_record(*reread) != written)
        std::abort();
    // Long games only repeat what short ones test; keep each run quick.
    if (record->actions.size() > 8)
        return 0;
    const auto replayed = termpool::Match::replay(*record);
    const auto* match = std::get_if<termpool::Match>(&replayed);
    if (match && record->check && record->check->running &&
        match->check_hash() != record->check->hash)
        std::abort(); // the reader let a different game through
    if (match && record->check) {
        const auto saved = termpool::parse_record(termpool::format_record(match->record()));
        const auto* back = std::get_if<termpool::GameRecord>(&saved);
        if (!back || !std::holds_alternative<termpool::Match>(termpool::Match::replay(*back)))
            std::abort();
    }
    return 0;
}
