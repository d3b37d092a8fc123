#pragma once
// The players' totals, kept between games in $XDG_STATE_HOME/termpool/stats: the text form,
// merging a finished game in, and reading and writing the file so that a damaged one is
// reported and kept aside, never lost.
//
// The text form (version 2): a header line, then one line per player and game type, in the
// order they first finished a game of it; '#' starts a comment line. A line is 'player', the
// game (its name in saved games, as --game takes it), that game's counts, and the name, which
// comes last and runs to the end of the line, so it may hold spaces and any printable UTF-8.
// Pool games and snooker keep different counts (see stats_figures.hpp):
//
//     termpool-stats 2
//     # player GAME COUNTS NAME; the counts of each game:
//     # 8ball 8ball-bar 9ball 10ball mixed: won played shots attempts pots potted fouls [...]
//     # snooker: won played shots attempts pots potted fouls points highest-break centuries
//     player 8ball 3 5 212 150 98 120 12 1 7 Ann Lee
//     player snooker 1 2 130 95 60 71 9 140 45 0 Ann Lee
//
// Version 1 kept one line per player, 'player' and the nine pool counts, with the racks and
// balls of every game type (snooker frames and reds too) added together. Such a file still
// reads: its lines become 'mixed' totals, shown apart from the per-game ones as they are
// (splitting them by game would be a guess), and written back as 'player mixed ...'.

#include <string>
#include <string_view>

#include "player/stats_figures.hpp"
#include <termpool/stats.hpp>
#include <variant>
#include <vector>

namespace termpool {

/// Version of the stats file written by this build.
inline constexpr int stats_version = 2;

/// One player's totals for one game type.
struct StatsEntry {
    std::string name;  ///< as shown; see stats_name
    StatsGame game;    ///< the game type (nothing: a version 1 file's mixed totals)
    PlayerStats stats; ///< its games added up
};

/// Every player's totals.
struct StatsStore {
    /// In the order each player first finished a game of each type; one per name and game.
    std::vector<StatsEntry> players;

    /// The totals of `name` for `game`, or null.
    const StatsEntry* find(std::string_view name, StatsGame game) const;
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

/// Reads the text form, version 1 or 2; an error names the line and the problem (not a stats
/// file, a newer version, an unknown game, a bad count, figures that contradict each other, a
/// name listed twice for one game).
std::variant<StatsStore, StatsError> parse_stats(std::string_view text);

/// Adds one finished game of `game`: each seat's figures go to the totals of its name for that
/// game (a new entry for a new name or game). Two seats with the same name share one entry.
void add_game(StatsStore& store, const std::string names[2], GameType game,
              const PlayerStats stats[2]);

/// Removes the totals of `name`, for every game; false when there are none.
bool remove_player(StatsStore& store, std::string_view name);

/// $XDG_STATE_HOME/termpool/stats, or ~/.local/state/termpool/stats.
std::string stats_path();

/// What reading the stats file found.
struct StatsFile {
    enum class State {
        missing,    ///< no file yet
        read,       ///< `store` holds it
        damaged,    ///< its text was refused: `problem` is "FILE:LINE: message", or it is
                    ///< over max_stats_bytes: "FILE: N bytes, more than the M allowed"
        unreadable, ///< it could not be read: `problem` says why
    };
    State state = State::missing; ///< which
    StatsStore store;             ///< the totals when read
    std::string problem;          ///< for damaged and unreadable
};

/// Reads and parses `path`, at most max_stats_bytes of it (a larger file is damaged, unread).
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

/// Adds one finished game of `game` to the totals in `path` and writes them atomically. Returns
/// what the player should be told, empty when all went well: a damaged file is reported as
/// "FILE:LINE: problem", moved aside (see keep_aside) and the totals start again from this
/// game; a file that cannot be read or moved aside is left alone and this game is not added.
std::string save_game_stats(const std::string& path, const std::string names[2], GameType game,
                            const PlayerStats stats[2]);

} // namespace termpool
