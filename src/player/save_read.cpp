#include "player/save_read.hpp"

#include "files/file_limits.hpp"
#include "files/read_file.hpp"

namespace termpool {

std::variant<Match, RecordError> load_game(const std::string& text) {
    auto parsed = parse_record(text);
    if (auto* bad = std::get_if<RecordError>(&parsed))
        return *bad;
    return Match::replay(std::get<GameRecord>(parsed));
}

bool finished(const Match& game) {
    return game.pending().kind == Pending::over;
}

SaveContents read_save(const std::string& path) {
    SaveContents save;
    // A regular file only (a FIFO in a save's place cannot hang the listing), bounded.
    save.text = read_whole_file(path, save.error, max_save_bytes);
    if (!save.text)
        return save;
    auto loaded = load_game(*save.text);
    if (auto* bad = std::get_if<RecordError>(&loaded))
        save.problem = *bad;
    else
        save.game.emplace(std::move(std::get<Match>(loaded)));
    return save;
}

} // namespace termpool
