#pragma once
// The parts of the computer's search that its pool and its snooker searches share: the spread
// of its stroke, the aim that allows for throw and squirt, and snooker's score of a shot.

#include <termpool/level.hpp>
#include <termpool/rules.hpp>

namespace termpool {

// The whole spread (one standard deviation) of the cue ball's direction under the execution
// noise of `level`, degrees: aim and squirt together.
double direction_sigma_deg(Level level);

// Noisy samples of each promising candidate at `level` (1, 3, 6, 10).
int samples_per_candidate(Level level);

// The ghost-ball aim of `strike` at `object`, turned by the object ball's error (throw, and the
// squirt of any side) so that it leaves towards `aim_point`, to first order; the strike's own
// aim when its first contact is not with `object`.
double corrected_aim_deg(const Game& game, const Strike& strike, const Ball& cue,
                         const Ball& object, Vec2 aim_point);

// Snooker: the best next pot for whoever is on now, each ball weighted by what it is worth.
double snooker_next_quality(const Game& game);

// Snooker: a simulated shot's worth from the shooter's side: points at their value, a kept
// table worth more with an easy ball to follow, a table handed over worth less the easier the
// opponent's pot (with `position`; without, the points and the turn only).
double snooker_score(const Verdict& v, int shooter, const Game& after, bool position);

} // namespace termpool
