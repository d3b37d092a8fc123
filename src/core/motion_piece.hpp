#pragma once
// A ball's current piece of motion: what the world keeps per ball between two of its events.

#include <algorithm>
#include <limits>
#include <termpool/ball.hpp>
#include <termpool/params.hpp>

#include "contact_time.hpp"

namespace termpool::core {

/// Moves a ball `dt` seconds on under one cloth model, its motion state unchanged.
using AdvanceFn = Ball (*)(const Ball& ball, double dt, const PhysicsParams& params);

/// True for a ball whose centre moves (it slides or rolls).
inline bool is_moving(const Ball& b) {
    return b.state == MotionState::sliding || b.state == MotionState::rolling;
}

/// A ball's motion from `start` to `end` (absolute times), until its next transition.
struct MotionPiece {
    Ball ball;                                            ///< the state at `start`
    double start = 0;                                     ///< when the piece began, s
    double end = std::numeric_limits<double>::infinity(); ///< the next transition, s
    Vec2 acceleration; ///< physical model: the centre's, constant over the piece
};

/// The piece's ball at `now`, moved by `advance` (no further than the piece's end).
inline Ball state_at(const MotionPiece& s, double now, AdvanceFn advance,
                     const PhysicsParams& params) {
    return advance(s.ball, std::min(now, s.end) - s.start, params);
}

/// The piece's centre from `now` on, as the parabola the physical model moves it on.
inline Path path_from(const MotionPiece& s, double now) {
    const double t = now - s.start;
    return {s.ball.position + s.ball.velocity * t + s.acceleration * (0.5 * t * t),
            s.ball.velocity + s.acceleration * t, s.acceleration, s.end - now};
}

} // namespace termpool::core
