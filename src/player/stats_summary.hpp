#pragma once
// The figures of a finished game, for the game-over overlay: a few lines, one column of figures
// per player, in the words of the game played (racks for pool, frames for snooker).

#include <string>
#include <termpool/stats.hpp>

#include "player/stats_figures.hpp"

namespace termpool {

/// Widest line of stats_summary, in columns.
inline constexpr int stats_summary_columns = 36;

/// The figures of a game of `kind` as '\n'-separated lines (no newline at the end), none wider
/// than `stats_summary_columns`: a header with both names (cut to fit), then a row per figure
/// of the kind (see stats_figures: pool's racks won ... break-and-runs, snooker's frames won,
/// frame score, highest break, centuries ...). ASCII apart from the names.
std::string stats_summary(StatsKind kind, const std::string names[2], const BoxFigures f[2]);

/// The figures of the game or match `tally` has heard, the last frame's score included.
std::string stats_summary(const std::string names[2], const StatsTally& tally);

} // namespace termpool
