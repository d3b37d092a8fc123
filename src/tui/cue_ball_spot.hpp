#pragma once
// Where the cue ball in hand is first proposed, before the player moves it: one rule for the
// local game and the hall, and for the tests that pin it.

#include <termpool/rules.hpp>
#include <termpool/vec.hpp>

namespace termpool::tui {

/// The first spot of the cue ball in hand in `game`: in pool the head spot (`head_spot`, the
/// table's) when it is free, in snooker's D beside the brown towards the yellow (where a break
/// is played from); when that spot is not legal (a ball on it), the legal spot of
/// `game.legal_placements(24)` nearest it, and the wanted spot itself if there is none.
Vec2 first_cue_ball_spot(const Game& game, Vec2 head_spot);

} // namespace termpool::tui
