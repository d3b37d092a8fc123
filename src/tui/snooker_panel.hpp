#pragma once
// The snooker lines of the panel, as text: the frame score of a match, the score and highest
// break of a player, and what the player at the table is on with the break and the points left.

#include <climits>
#include <string>
#include <vector>

#include "tui/view.hpp"

namespace termpool::tui {

/// True when the panel shows `v` as a snooker frame (not practice).
bool snooker_panel(const View& v);
/// "Frames 1-0 (best of 5)"; empty for a single frame.
std::string frames_text(const View& v);
/// "high break 23": `player`'s highest break of the frame; empty before the first point.
std::string high_break_text(const View& v, int player);
/// What the player at the table is on: "on red", "on a colour: blue" (the aimed colour
/// proposed), "nominated blue", "on yellow" (in order), "free ball: pink".
std::string ball_on_text(const View& v);
/// The pieces of the status line of the player at the table, in the order shown: "break 12"
/// (only while there is a break), what they are on (ball_on_text), "67 left" (the points still
/// on the table).
std::vector<std::string> snooker_status_pieces(const View& v);
/// "break 12  on red  67 left": the pieces of snooker_status_pieces separated by `gap`, as
/// many as fit `width` columns: the points left go first, then the break; what the player is
/// on stays, and nothing is returned when it alone is wider. A piece is never cut.
std::string snooker_status(const View& v, int width = INT_MAX, const std::string& gap = "  ");

} // namespace termpool::tui
