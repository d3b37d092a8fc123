#pragma once
// How a ball and the game's name look, shared by the table and the panel's legend.

#include <string>
#include <termpool/game_registry.hpp>
#include <termpool/rules.hpp>

#include "tui/view.hpp"

namespace termpool::tui {

/// Which set of balls a view holds (the registry's, as tui::BallSet too).
using termpool::BallSet;

/// The set of `v`'s balls: snooker when any of them, on the table or pocketed, is a snooker
/// colour (id 16..21), as only a snooker set has those; pool otherwise. Ids 1..15 alone cannot
/// tell, and pool balls keep their numbers.
BallSet ball_set(const View& v);

/// The colour of ball `id` (pool: 1 and 9 yellow, ..., 8 black; snooker: the reds red, the
/// colours their own); white for the cue ball.
Colour ball_colour(int id, BallSet set = BallSet::pool);

/// True for the stripes, 9..15.
bool is_stripe(int id);

/// True when the table is drawn large enough for two-cell labels: a ball is at least three
/// columns across, so that "10" and a blank column fit beside a touching ball.
bool wide_labels(double cells_per_metre, double ball_radius);

/// The label of a ball on the table and in the legend: "1".."9"; for 10..15 "10".."15" when
/// `wide`, else the single letters "A".."F" (a letter never reads as part of a neighbour's
/// number); "o" or "●" for the cue ball. In a snooker set a ball shows what it is worth, as a
/// snooker player counts it: every red "1", the colours "2" (yellow) to "7" (black), so each
/// colour reads in monochrome and ASCII too and no label is two cells wide.
std::string ball_label(int id, bool utf8, bool wide, BallSet set = BallSet::pool);

/// The glyph of a ball drawn without its label, where its number would run into another
/// ("•", "*" in ASCII); its style still says which ball it is, as the legend shows.
std::string ball_mark(bool utf8);

/// The style of object ball `id`, on the table and in the legend. Colour: solids dark bold
/// digits on their colour, the 8 a white digit on black, stripes the colour on white.
/// Monochrome: solids reversed, stripes bold, the 8 reversed and bold. Snooker: dark bold
/// digits on the ball's colour, the black's white; in monochrome the reds reversed and the
/// colours reversed and bold.
Style ball_style(int id, bool colour, BallSet set = BallSet::pool);

/// "8-ball", "8-ball, bar rules", "9-ball", "10-ball".
const char* game_title(GameType type);

} // namespace termpool::tui
