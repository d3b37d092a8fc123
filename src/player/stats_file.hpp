#pragma once
// The players' totals, kept between games in $XDG_STATE_HOME/termpool/stats: the text form,
// merging a finished game in, and reading and writing the file so that a damaged one is
// reported and kept aside, never lost.
//
// The text form (version 1): a header line, then one line per player, in the order they first
// finished a game; '#' starts a comment line. The name comes last and runs to the end of the
// line, so it may hold spaces and any printable UTF-8:
//
//     termpool-stats 1
//     # won played shots attempts pots potted fouls break-and-runs longest-run name
//     player 3 5 212 150 98 120 12 1 7 Ann Lee

#include <string>
#include <string_view>
#include <termpool/stats.hpp>
#include <variant>
#include <vector>

namespace termpool {

/// Version of the stats file written by this build.
inline constexpr int stats_version = 1;

/// One player's totals.
struct StatsEntry {
    std::string name;  ///< as shown; see stats_name
    PlayerStats stats; ///< all games added up
};

/// Every player's totals.
struct StatsStore {
    std::vector<StatsEntry> players; ///< in the order they first finished a game

    /// The entry named `name`, or null.
    const StatsEntry* find(std::string_view name) const;
};

/// Why a stats text was refused.
struct StatsError {
    int line = 0;        ///< 1-based line
    std::string message; ///< what is wrong
};

/// `name` as the store keeps it: invalid UTF-8 and control characters (which would break the
/// line or the terminal) become '?', spaces at both ends go; a blank name becomes "?".
std::string stats_name(std::string_view name);

/// The text form.
std::string format_stats(const StatsStore& store);

/// Reads the text form; an error names the line and the problem (not a stats file, a newer
/// version, a bad count, figures that contradict each other, a name listed twice).
std::variant<StatsStore, StatsError> parse_stats(std::string_view text);

/// Adds one finished game: each seat's figures go to the totals of its name (a new entry for
/// a new name). Two seats with the same name share one entry.
void add_game(StatsStore& store, const std::string names[2], const PlayerStats stats[2]);

/// Removes the totals of `name`; false when there are none.
bool remove_player(StatsStore& store, std::string_view name);

/// $XDG_STATE_HOME/termpool/stats, or ~/.local/state/termpool/stats.
std::string stats_path();

/// What reading the stats file found.
struct StatsFile {
    enum class State {
        missing,    ///< no file yet
        read,       ///< `store` holds it
        damaged,    ///< its text was refused: `problem` is "FILE:LINE: message"
        unreadable, ///< it could not be read: `problem` says why
    };
    State state = State::missing; ///< which
    StatsStore store;             ///< the totals when read
    std::string problem;          ///< for damaged and unreadable
};

/// Reads and parses `path`.
StatsFile read_stats_file(const std::string& path);

/// Holds an exclusive lock beside `path` (`path`.lock) while it lives, so that two games
/// ending at once do not lose one another's figures. Without a lock file (before the first
/// save makes the directory, or in a read-only one) the work goes on unlocked: the write
/// itself is still atomic.
class StatsLock {
public:
    /// Waits for the lock on `path`.
    explicit StatsLock(const std::string& path);
    ~StatsLock();
    StatsLock(const StatsLock&) = delete;
    StatsLock& operator=(const StatsLock&) = delete;

private:
    int fd_ = -1;
};

/// Adds one finished game to the totals in `path` and writes them atomically. Returns what the
/// player should be told, empty when all went well: a damaged file is reported as
/// "FILE:LINE: problem", moved aside (see keep_aside) and the totals start again from this
/// game; a file that cannot be read or moved aside is left alone and this game is not added.
std::string save_game_stats(const std::string& path, const std::string names[2],
                            const PlayerStats stats[2]);

} // namespace termpool
