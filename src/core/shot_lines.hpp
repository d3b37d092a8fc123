#pragma once
// Lines of play on a table of balls, as the computer players see them: which ball is where,
// and whether a ball's path is clear.

#include <array>
#include <optional>
#include <termpool/ball.hpp>
#include <termpool/table.hpp>
#include <utility>
#include <vector>

namespace termpool {

// The ball `id` among `balls` while it is on the table; nullptr once it is pocketed or absent.
const Ball* ball_in_play(const std::vector<Ball>& balls, int id);

// True when a ball other than the two of `ignore` lies within a diameter (2 R) of the segment
// from a to b: a ball rolled along it would touch that ball.
bool path_blocked(const std::vector<Ball>& balls, Vec2 a, Vec2 b, std::pair<int, int> ignore,
                  double R);

// The line from the cue ball at `cue` to the ghost ball that sends `object` towards
// `aim_point`, when the cut is no thinner than `min_cut` (the cosine of its angle) and no other
// ball is in the way of either ball; nullopt otherwise.
std::optional<Vec2> open_pot_line(const std::vector<Ball>& balls, Vec2 cue, const Ball& object,
                                  Vec2 aim_point, double min_cut, double R);

// The direction of `v` as a strike's angle, degrees.
double aim_degrees(Vec2 v);

// The images of `point` in the four rails, moved in by R because a ball's centre turns R from
// the cushion: aiming at one plays a ball off that rail towards `point`.
std::array<Vec2, 4> rail_mirrors(const Table& table, Vec2 point, double R);

} // namespace termpool
