#pragma once
// How a ball and the game's name look, shared by the table and the panel's legend.

#include <string>
#include <termpool/rules.hpp>

#include "tui/view.hpp"

namespace termpool::tui {

/// The colour of ball `id` (1 and 9 yellow, ..., 8 black); white for the cue ball.
Colour ball_colour(int id);

/// True for the stripes, 9..15.
bool is_stripe(int id);

/// True when the table is drawn large enough for two-cell labels: a ball is at least three
/// columns across, so that "10" and a blank column fit beside a touching ball.
bool wide_labels(double cells_per_metre, double ball_radius);

/// The label of a ball on the table and in the legend: "1".."9"; for 10..15 "10".."15" when
/// `wide`, else the single letters "A".."F" (a letter never reads as part of a neighbour's
/// number); "o" or "●" for the cue ball.
std::string ball_label(int id, bool utf8, bool wide);

/// The style of object ball `id`, on the table and in the legend. Colour: solids dark bold
/// digits on their colour, the 8 a white digit on black, stripes the colour on white.
/// Monochrome: solids reversed, stripes bold, the 8 reversed and bold.
Style ball_style(int id, bool colour);

/// "8-ball", "8-ball, bar rules", "9-ball", "10-ball".
const char* game_title(GameType type);

} // namespace termpool::tui
