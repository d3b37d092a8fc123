#pragma once
// What the statistics of each kind of game show, in one place: the counts of a stats file line,
// the rows of the game-over box and the columns of `termpool stats`. Pool keeps racks and runs,
// snooker frames and breaks (see termpool/stats.hpp); the game type decides which, through
// stats_kind.

#include <optional>
#include <span>
#include <string>
#include <termpool/game_registry.hpp>
#include <termpool/rules.hpp>
#include <termpool/stats.hpp>
#include <vector>

namespace termpool {

/// The game types in the order `termpool stats` and the file list them: the registry's.
std::vector<GameType> stats_game_order();

/// What a set of totals covers: one game type, or nothing for the totals of a version 1 file,
/// which added all game types together ("mixed").
using StatsGame = std::optional<GameType>;

/// The figures `game` keeps; the mixed totals of a version 1 file keep pool's.
StatsKind stats_kind_of(StatsGame game);

/// The game's word in the stats file: "8ball", ..., "snooker" (as in saved games), or "mixed".
std::string stats_game_key(StatsGame game);
/// Reads stats_game_key back into `game`; false for an unknown word.
bool parse_stats_game_key(std::string_view key, StatsGame& game);

/// The title of the game's section in `termpool stats`: "8-ball", "Snooker", ...
std::string stats_game_title(StatsGame game);

/// One count of a stats file line.
struct StatsCount {
    const char* key;         ///< its word in the file's comment: "won", "highest-break"
    const char* name;        ///< its name in messages: "racks won", "highest break"
    int PlayerStats::*field; ///< the figure
};

/// One player's figures in the game-over box.
struct BoxFigures {
    PlayerStats stats;   ///< the game's, or the match's so far
    int frame_score = 0; ///< snooker: the score of the frame just played
};

/// A row of the game-over box: its label and how a player's figure reads.
struct StatsBoxRow {
    const char* label;                        ///< at most 14 columns
    std::string (*figure)(const BoxFigures&); ///< one player's figure
};

/// A column of `termpool stats`, after the player's name.
struct StatsColumn {
    const char* header;                        ///< its heading
    std::string (*figure)(const PlayerStats&); ///< one player's figure
};

/// What the statistics of one kind of game show.
struct StatsFigures {
    std::span<const StatsCount> counts; ///< the counts of its file line, in file order
    std::span<const StatsBoxRow> box;   ///< the rows of the game-over box
    std::span<const StatsColumn> table; ///< the columns of `termpool stats`
    const char* legend;                 ///< what those columns mean, '\n'-ended lines
    /// Why `stats` could come from no game (the file was edited or damaged), or nothing.
    std::optional<std::string> (*contradiction)(const PlayerStats& stats);
};

/// The figures of `kind`.
const StatsFigures& stats_figures(StatsKind kind);

/// "75%", rounded to the nearest percent, or "-" before the first pot attempt.
std::string pot_success_text(const PlayerStats& s);

} // namespace termpool
