#pragma once
// Boxes a ball's centre stays in over a stretch of its motion: the contact searches cull with
// them before they solve anything.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <termpool/vec.hpp>

#include "contact_time.hpp"
#include "motion_piece.hpp"

namespace termpool::core {

/// floor(x) as an integer, x clamped to +-1e9 first so that a wild coordinate cannot overflow:
/// the index of a grid cell or a strip, x in cells. By truncation and a correction: std::floor
/// is a call into libm on x86-64's baseline, and a search asks for several. `x` is not NaN.
inline std::int64_t floor_clamped(double x) {
    constexpr double limit = 1e9;
    const double t = std::clamp(x, -limit, limit);
    const auto toward_zero = static_cast<std::int64_t>(t);
    return toward_zero - (static_cast<double>(toward_zero) > t ? 1 : 0);
}

/// An axis-aligned box in the table plane.
struct Box {
    Vec2 min, max;
};

/// Where a moving centre can be, tighter than its box for a long diagonal path: within `bulge` of
/// the segment from `from` to `to`. A ball's pair search walks only the grid cells along it.
struct Capsule {
    Vec2 from, to;
    double bulge = 0; ///< m
};

/// The capsule of a centre on `path` over its first `duration` seconds: the chord of its parabola
/// and the parabola's greatest distance from it, |a| T^2 / 8. A classic ball moves on a straight
/// line no further than v T: the chord to where v T would take it holds its path.
/// (|a| is bounded by |a_x| + |a_y|, which needs no square root.)
inline Capsule capsule_of(const Path& path, double duration) {
    const double T = duration;
    const Vec2 a = path.acceleration;
    return {path.position, path.position + path.velocity * T + a * (0.5 * T * T),
            (std::abs(a.x) + std::abs(a.y)) * T * T / 8};
}
/// The capsule of a piece's centre over the first `duration` seconds of the piece.
inline Capsule capsule_of(const MotionPiece& piece, double duration) {
    const Ball& b = piece.ball;
    return capsule_of(Path{b.position, b.velocity, piece.acceleration, duration}, duration);
}

/// A box no overlap test reaches (min > max), a pocketed ball's.
inline Box empty_box() {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    return {{infinity, infinity}, {-infinity, -infinity}};
}

/// The box with corners a and b.
inline Box box_of(Vec2 a, Vec2 b) {
    return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}

/// Whether boxes a and b come within `margin` of each other.
inline bool boxes_within(const Box& a, const Box& b, double margin) {
    return a.min.x - margin <= b.max.x && b.min.x - margin <= a.max.x &&
           a.min.y - margin <= b.max.y && b.min.y - margin <= a.max.y;
}

/// Box of a centre moving along `path` for `duration` seconds.
Box path_box(const Path& path, double duration);

/// Box of a moving ball's centre over the first `duration` seconds of its piece, on the
/// physical model's parabola (the parameters are those of every model's reach).
Box physical_reach(const MotionPiece& piece, double duration, const PhysicsParams& params);

/// The same on a classic model's straight line, moved by `advance`.
Box classic_reach(const MotionPiece& piece, double duration, const PhysicsParams& params,
                  AdvanceFn advance);

} // namespace termpool::core
