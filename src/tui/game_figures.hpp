#pragma once
// The players' figures in the box at the end of a game, a rack or a frame: pool's counts of
// racks and runs, snooker's frames, points and breaks.

#include <string>
#include <termpool/match.hpp>

namespace termpool::tui {

/// The figures of `match` so far as '\n'-separated lines (no newline at the end), a column per
/// player under their names. Pool: stats_summary (racks won, balls potted, pot success, fouls,
/// longest run, break-and-runs). Snooker: frames won, the frame's score (points), the highest
/// break and the centuries of the frame, then balls potted, pot success and fouls.
std::string game_figures_text(const Match& match);

} // namespace termpool::tui
