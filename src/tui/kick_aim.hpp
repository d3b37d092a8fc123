#pragma once
// A one-rail kick aimed as the simulator plays it. The mirror aim in the rail (rank_targets)
// ignores the cushion's rebound, throw and spin, so the real cue ball can miss the ball it was
// aimed at or meet another first; the kick proposed at a turn's opening is settled here.

#include <optional>
#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool::tui {

/// How far either side of the mirror aim the kick's aim is looked for, degrees. At a medium
/// speed the rail sends the ball off several degrees from the mirror: of 500 kicks on a grid
/// ('[.kick-measure]'), 3 degrees either side settled 449, 10 settled 468.
inline constexpr double kick_search_deg = 10.0;
/// The coarse scan's step, degrees: well under the window of aims that meet a ball.
inline constexpr double kick_scan_step_deg = 0.1;
/// The finest step the aim is settled to, degrees (the , and . keys' step).
inline constexpr double kick_resolution_deg = 0.01;

/// The aim within `kick_search_deg` of `strike.angle_deg` (the mirror aim) at which the cue ball
/// struck as `strike` (its speed, spin and elevation) meets exactly one cushion and then ball
/// `target` before any other ball, as the simulator plays it, on `balls` at rest (the cue ball
/// is id 0); of those it finds, the one nearest a full hit (to `kick_resolution_deg`, after a
/// scan every `kick_scan_step_deg`). Nothing when no aim looked at does. Deterministic.
std::optional<double> refine_kick(const Table& table, const PhysicsParams& params,
                                  const std::vector<Ball>& balls, const Strike& strike, int target);

} // namespace termpool::tui
