#pragma once
// What a snooker table is worth to the computer after a shot: the chance of the next pot for
// whoever plays it, judged from the lines of the balls and the spread of the stroke, and the
// shot's worth in points and in the table it leaves.

#include <termpool/rules.hpp>

namespace termpool {

// What a ball on is worth taking next: a red 1 (it opens the way to the black), a colour 0.5
// to 1 by its value.
double snooker_ball_weight(int id);

// The chance that a direction spread normally by `sigma` (one standard deviation) falls within
// `half_window` either side of the middle.
double chance_within(double half_window, double sigma);

// The chance of potting `object` into `pocket` from `cue` (the ghost ball's line clear or not:
// the caller looks), for a stroke whose direction spreads by `sigma_deg` (one standard
// deviation): the cue ball's direction error is magnified by the distances and the cut into
// the object ball's, which the pocket accepts up to a tolerance (measured on the simulator's
// snooker pockets: about 25 mm either side at a corner, 31 mm at a middle pocket met square,
// less the more obliquely it is met).
double snooker_pot_chance(const Table& table, double R, Vec2 cue, Vec2 object, int pocket,
                          double sigma_deg);

// The best pot for the player on now in `game`: the chance of each ball on (with a clear
// line) into each pocket, times what the ball is worth taking (a red 1, a colour 0.5 to 1 by
// its value). 0 with no ball in sight or no cue ball on the table.
double snooker_best_chance(const Game& game, double sigma_deg);

// A simulated shot's worth to `shooter`, `after` it: the points scored and given away (12 a
// point), a foul's cost, and the table: kept, worth the best next pot at the shooter's
// spread `sigma_deg`; handed over, counted against by the opponent's best pot at the same
// spread, and for the shooter when the opponent is snookered or the cue ball left far from
// the balls on, on a cushion or in baulk.
double snooker_shot_value(const Verdict& v, int shooter, const Game& after, double sigma_deg);

// `s`, the worth of a table handed over to the opponent, from the player who left it, plus
// what the leave is worth to that player: a snooker, the cue ball far from the balls on, on a
// cushion, and in baulk (with `baulk_wants_distance` only while the balls on are more than a
// quarter of the table away).
double with_leave_worth(double s, const Game& after, bool baulk_wants_distance);

// True when the player to shoot (or to choose) in a snooker frame is behind by more than the
// points left with three reds or fewer on the table: snookers could still win it, but the
// frame is as good as lost, and the computer players concede it.
bool snooker_frame_lost(const Game& game);

} // namespace termpool
