#pragma once
// The snooker lines of the panel, as text: the frame score of a match, the score and highest
// break of a player, and what the player at the table is on with the break and the points left.

#include <string>

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
/// "break 12  on red  67 left" (the break only while there is one), the pieces separated by
/// `gap`.
std::string snooker_status(const View& v, const std::string& gap = "  ");

} // namespace termpool::tui
