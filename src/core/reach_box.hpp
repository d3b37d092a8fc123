#pragma once
// Boxes a ball's centre stays in over a stretch of its motion: the contact searches cull with
// them before they solve anything.

#include <algorithm>
#include <limits>
#include <termpool/vec.hpp>

#include "contact_time.hpp"
#include "motion_piece.hpp"

namespace termpool::core {

/// An axis-aligned box in the table plane.
struct Box {
    Vec2 min, max;
};

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
