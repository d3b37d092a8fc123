#pragma once
// The figures of a finished game, for the game-over overlay: a few lines, one column of figures
// per player.

#include <string>
#include <termpool/stats.hpp>

namespace termpool {

/// Widest line of stats_summary, in columns.
inline constexpr int stats_summary_columns = 36;

/// The game's figures as '\n'-separated lines (no newline at the end), none wider than
/// `stats_summary_columns`: a header with both names (cut to fit), then racks won, balls
/// potted, pot success, fouls, longest run and break-and-runs. ASCII apart from the names.
std::string stats_summary(const std::string names[2], const PlayerStats s[2]);

/// "75%", rounded to the nearest percent, or "-" before the first pot attempt.
std::string pot_success_text(const PlayerStats& s);

} // namespace termpool
