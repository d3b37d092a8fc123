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
/// ball's direction at contact). With `rebounds`, the cue ball's path goes on off that many
/// rails to its next contact (a kick, as the simulator plays it) and the lines after a ball
/// contact off as many cushions. A strike that strike_problem refuses gets preview_shot's
/// straight lines along the cue; a table without the cue ball gets nothing.
AimPreview preview_strike(const Table& table, const PhysicsParams& params,
                          const std::vector<Ball>& balls, const Strike& strike,
                          double aid_length = 0.6, int rebounds = 0);

/// The object ball's first direction under the standard assist, in ball diameters.
inline constexpr double standard_object_diameters = 3;

/// The aid as `assist` shows it, from the whole aid `full` (preview_strike with a rebound and
/// lines to the rails) on balls of radius `R`: guided all of it; standard the cue ball's path
/// to its first contact (the rail of a kick), the ghost ball and the object ball's first
/// `standard_object_diameters` ball diameters; pro the cue ball's path to its first contact
/// and nothing after it.
AimPreview shown_preview(const AimPreview& full, Assist assist, double R);

} // namespace termpool::tui
