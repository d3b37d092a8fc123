#pragma once
/// \file
/// The snooker break-off a player would open with: soft, thin off the end red of the pack's
/// back row on the cue ball's side, so that the cue ball comes off the top and side cushions
/// back to baulk and the pack barely opens. A free function of the balls as they lie, for the
/// front end's opening aim and power (and for any game description that names a default break).

#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// The speed a snooker break-off is played at when no simulated candidate does better, m/s.
inline constexpr double break_off_speed = 3.0;

/// The end red of the pack on the cue ball's side: of the back row (the reds within a ball
/// radius `ball_radius`, m, of the one furthest up the table), the one furthest to the cue
/// ball's side of the pack (the low-y side when the cue ball is level with the pack's middle).
/// Null without a cue ball (id 0) or a red on the table.
const Ball* break_off_red(const std::vector<Ball>& balls, double ball_radius);

/// The aim, degrees counter-clockwise from +x, from the cue ball of `balls` along the line that
/// passes `offset_radii` ball radii (`ball_radius`, m) outside the centre of `break_off_red`, on
/// the side away from the pack's middle: 2 grazes it, less is a thin contact. 0 without a cue ball
/// or a red.
double break_off_aim_deg(const std::vector<Ball>& balls, double ball_radius, double offset_radii);

/// The break-off from the cue ball (id 0) as it lies in `balls`, on `table` under `params`.
/// The aim clips the end red of the back row of the triangle on the cue ball's side (ties on
/// the yellow's side) on its outer edge; a small set of speeds (about 2.5 to 4 m/s) and
/// thicknesses is simulated, and the strike taken is the one that hits a red first, fouls
/// nothing and leaves the cue ball nearest the baulk cushion behind the baulk line (softer
/// preferred on a tie). When none is legal it is the plain geometric one at `break_off_speed`.
/// No spin, a level cue. Without a cue ball or a red: `break_off_speed` along +x.
Strike break_off_strike(const Table& table, const PhysicsParams& params,
                        const std::vector<Ball>& balls);

} // namespace termpool
