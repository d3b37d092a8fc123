// The hall core's state folder: each table saved after every change, all restored when
// the server starts again.

#include <limits>
#include <sys/stat.h>

#include "hall/hall_core.hpp"

namespace termpool::hall {

// `table` as it is with `match` in place of its own, as it is saved.
SavedTable HallCore::saved_form(const Table& table, const Match& match) {
    SavedTable stored{table.number, match.record(), {}};
    for (int s = 0; s < 2; ++s)
        stored.seat_tokens[s] = table.seats[s].token_hash;
    return stored;
}

// "" or why not (the file and the system's reason). A failed save is remembered (unsaved_):
// save_all tries it again at the end, and the hall does not go idle on it.
std::string HallCore::save(const Table& table) {
    if (options_.state_dir.empty())
        return {};
    std::string problem = save_table(options_.state_dir, saved_form(table, table.match));
    if (problem.empty()) {
        unsaved_.erase(table.number);
        return {};
    }
    unsaved_.insert(table.number);
    log("cannot save table " + std::to_string(table.number) + ": " + problem);
    return problem;
}

void HallCore::restore(Clock::time_point now, std::chrono::system_clock::time_point wall_now) {
    if (options_.state_dir.empty())
        return;
    std::vector<std::string> problems;
    for (SavedTable& stored : load_tables(options_.state_dir, problems)) {
        // A restored computer starts a new stream, as a resumed local game's does.
        auto replayed =
            Match::replay(stored.record, std::numeric_limits<std::size_t>::max(), {}, random_());
        if (!std::holds_alternative<Match>(replayed))
            continue;
        Table table{stored.number,
                    std::move(std::get<Match>(replayed)),
                    {},
                    ++last_ticket_,
                    false,
                    {},
                    0,
                    0};
        const auto away_since = file_changed(stored.number, now, wall_now);
        table.last_move = away_since;
        for (int s = 0; s < 2; ++s) {
            table.seats[s].computer = stored.record.computers[s].has_value();
            // Nobody is connected yet: a seat of a game not started is nobody's.
            if (started(table)) {
                table.seats[s].token_hash = stored.seat_tokens[s];
                table.seats[s].away_since = away_since;
            }
        }
        tables_.emplace(stored.number, std::move(table));
    }
    for (const std::string& problem : problems)
        log("not restored: " + problem);
    table_count_ = tables_.size();
    expire_away(now);
    std::vector<int> numbers;
    for (const auto& [number, table] : tables_)
        numbers.push_back(number);
    for (const int number : numbers)
        forget_if_idle(tables_.at(number));
    log("restored " + serving::tables_count(tables_.size()));
    for (auto& [number, table] : tables_)
        think(table, now);
}

// When table `number`'s file last changed, on the steady clock: a restored away seat went
// away then at the latest (the file is rewritten on every change of the table).
HallCore::Clock::time_point
HallCore::file_changed(int number, Clock::time_point now,
                       std::chrono::system_clock::time_point wall_now) const {
    struct stat info {};
    if (::stat(table_path(options_.state_dir, number).c_str(), &info) != 0)
        return now;
    const auto changed = std::chrono::system_clock::from_time_t(info.st_mtim.tv_sec);
    const auto age = wall_now - changed;
    return age > Clock::duration::zero() ? now - std::chrono::duration_cast<Clock::duration>(age)
                                         : now;
}

} // namespace termpool::hall
