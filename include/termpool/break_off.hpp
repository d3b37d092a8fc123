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
