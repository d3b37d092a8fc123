#pragma once
// Position play for pool: how likely a pot is for a player of a given spread of direction, and
// what a leave is worth to the player who shoots from it, found by playing the best next pots
// from it (two shots ahead).

#include <termpool/rules.hpp>

#include "shot_trial.hpp"

namespace termpool {

/// The chance that a pot of `object` into `pocket` goes in for a player whose cue ball leaves
/// with a direction error of `sigma_deg` (one standard deviation, degrees), the cue ball at
/// `cue`: the object ball's miss at the pocket grows with both distances and with the cut
/// (|miss| = d1 d2 e / (2 R cos cut) for a direction error e), and the pocket takes a miss up
/// to a tolerance that shrinks as the ball comes in across its mouth. 0 for cuts past 80 deg.
double pot_chance(const Table& table, double R, Vec2 cue, const Ball& object, int pocket,
                  double sigma_deg);

/// The best pot_chance over the legal balls and pockets of `game` with nothing in the way, for
/// its shooter; 1 with the cue ball in hand (as good as it gets), 0 with nothing to pot.
double best_pot_chance(const Game& game, double sigma_deg);

/// What `game` (the shooter to play, no choice owed, no winner) is worth to its shooter, 0..1:
/// the best of its few likeliest pots, each played without noise at a few paces and spins
/// (`trials` are re-based on `game`), worth its chance times what the table it leaves is
/// worth (best_pot_chance there, a win as 1). `simulations` counts the shots played.
double leave_value(const Game& game, double sigma_deg, ShotTrial& trials,
                   std::uint64_t& simulations);

} // namespace termpool
