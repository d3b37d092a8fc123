#pragma once
// The aiming aid as the simulator plays the strike: the cue ball's own path to its first
// contact, so that squirt turns it and swerve curves it as they turn and curve the shot.

#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

#include "tui/aim.hpp"

namespace termpool::tui {

/// Chords drawn for each piece of the cue ball's motion (a sliding piece with a tilted spin
/// axis is a curve).
inline constexpr int aid_chords_per_piece = 16;

/// The aid for `strike` on `balls` (the cue ball is id 0): the cue ball's centre from its spot
/// along the path the simulator gives it, up to its first contact with a ball, a rail, a jaw or
/// a pocket, or to where it stops short of all of them; after a ball contact the object ball's
/// line of centres and the cue ball's tangent line (add_contact_lines, taken along the cue
/// ball's direction at contact). A strike that strike_problem refuses gets preview_shot's
/// straight lines along the cue; a table without the cue ball gets nothing.
AimPreview preview_strike(const Table& table, const PhysicsParams& params,
                          const std::vector<Ball>& balls, const Strike& strike,
                          double aid_length = 0.6);

} // namespace termpool::tui
