#pragma once
/// \file
/// Practice: one player at a table with no referee. Any ball may be picked up and put down
/// where it touches no other ball, the last shot may be taken again, and a new rack set up.
/// Shots are simulated as in a game; nothing is judged.

#include <cstdint>
#include <optional>
#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// The balls of a practice table and the position before the last shot.
class PracticeTable {
public:
    /// A new rack of `rack`, the one a game seeded with `seed` breaks first, with the cue ball
    /// on the head spot.
    PracticeTable(const Table& table, const PhysicsParams& params, RackType rack,
                  std::uint64_t seed);

    /// The balls, pocketed ones kept with state pocketed (like `Game::balls`).
    const std::vector<Ball>& balls() const { return balls_; }
    /// True until the rack has been broken: the first shot may be as hard as a break.
    bool is_break() const { return is_break_; }
    /// True when the last shot can be taken again.
    bool can_retake() const { return before_shot_.has_value(); }

    /// True when ball `id` may be put down at `spot`: on the cloth and touching no other ball
    /// on the table.
    bool can_put(int id, Vec2 spot) const;
    /// Puts ball `id` (on the table or pocketed) down at rest at `spot`. False, and nothing
    /// changed, when `can_put` says no or there is no such ball.
    bool put(int id, Vec2 spot);
    /// Where ball `id` goes instead of `wanted` when a ball covers it: the first free spot on
    /// the long string from `wanted` towards the foot, then back (as a ball is re-spotted).
    Vec2 free_spot_near(int id, Vec2 wanted) const;

    /// The strike to play from here: simulated, then the balls take their final places. A
    /// pocketed cue ball comes back to the head spot (or the free spot nearest it). Returns
    /// what the shot did; `trajectory`, when given, records the motion for the animation.
    ShotResult shoot(const Strike& strike, Trajectory* trajectory = nullptr);
    /// Puts the balls back where they were before the last shot. False when there was none.
    bool retake();
    /// A fresh rack, as the constructor's (the last shot cannot be taken again after it).
    void rerack(std::uint64_t seed);

private:
    Table table_;
    PhysicsParams params_;
    RackType rack_;
    std::vector<Ball> balls_;
    std::optional<std::vector<Ball>> before_shot_;
    bool is_break_ = true;
    bool was_break_ = true; // is_break_ before the last shot, for retake
};

} // namespace termpool
