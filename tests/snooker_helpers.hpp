#pragma once
// Builders shared by the snooker tests: the table, a ball on it, the colours on their spots,
// and a frame from a hand-made position.

#include <termpool/rules.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table.hpp>
#include <termpool/table_physics.hpp>
#include <utility>
#include <vector>

#include "physics_helpers.hpp"

namespace termpool::test {

/// The snooker table, made once.
inline const Table& snooker_table() {
    static const Table table = make_table(TableSize::snooker, snooker_ball_radius);
    return table;
}

/// Snooker ball `id` at `p`.
inline Ball snooker_ball(int id, Vec2 p) {
    return ball_at(id, p.x, p.y, snooker_ball_mass);
}

/// The colours on their spots, the reds given (id and place), the cue ball at `cue`.
inline std::vector<Ball> colours_on_spots(Vec2 cue, const std::vector<std::pair<int, Vec2>>& reds) {
    std::vector<Ball> balls{snooker_ball(0, cue)};
    for (const auto& [id, p] : reds)
        balls.push_back(snooker_ball(id, p));
    for (int colour = snooker_yellow; colour <= snooker_black; ++colour)
        balls.push_back(snooker_ball(colour, snooker_spot(snooker_table(), colour)));
    return balls;
}

/// A frame of `balls` with player 1 to shoot, in `state`, with `in_hand`.
inline Game snooker_frame(std::vector<Ball> balls, const SnookerState& state,
                          BallInHand in_hand = BallInHand::none) {
    return Game::from_snooker_position(snooker_table(), physics_for_table(TableSize::snooker),
                                       std::move(balls), 1, state, in_hand);
}

} // namespace termpool::test
