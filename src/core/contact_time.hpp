#pragma once
// When a moving ball first touches another ball, a cushion line, a jaw point or a capture line.
// Every function returns seconds from now, or +infinity when there is no contact within the
// horizon; a contact counts only while the two are approaching.

#include <cmath>
#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/vec.hpp>

#include "polynomial.hpp"

namespace termpool::core {

/// A ball centre moving with constant acceleration: r(t) = position + velocity t + acceleration
/// t^2 / 2 for 0 <= t <= duration (the physical friction model between two transitions).
struct Path {
    Vec2 position;     ///< at t = 0
    Vec2 velocity;     ///< at t = 0
    Vec2 acceleration; ///< constant
    double duration;   ///< how long the path is valid, s
};

/// First time two centres are `distance` apart and closing (degree-4 polynomial roots).
double path_path_contact_time(const Path& a, const Path& b, double distance, double horizon);

/// |dr + dv t + da t^2/2|^2 - distance^2 for the relative motion of two centres.
inline Polynomial4 pair_gap(const Path& a, const Path& b, double distance) {
    const Vec2 dr = a.position - b.position;
    const Vec2 dv = a.velocity - b.velocity;
    const Vec2 da = a.acceleration - b.acceleration;
    Polynomial4 f;
    f.c = {length_squared(dr) - distance * distance, 2 * dot(dr, dv),
           length_squared(dv) + dot(dr, da), dot(dv, da), 0.25 * length_squared(da)};
    return f;
}

/// Whether the two centres stay clearly more than `distance` apart over [0, horizon], told by
/// their separation across the relative velocity dv: along n = (-dv.y, dv.x), dr(t).n = dr.n +
/// da.n t^2 / 2 (dv.n is 0), and |dr(t)| is at least |dr(t).n| / |dv|. Most balls that pass
/// another at rest without touching are told so: a rolling ball's da is along its dv, and its
/// sideways distance stays what it is. "Clearly" is by a margin beyond the rounding of this
/// test, of the gap's quartic, and of the same paths brought to a later moment (a bound is
/// searched from the moment it comes first), where first_contact_time never returns a time, so
/// that the two give the same answer. `place` is at least |a.position.x| + |a.position.y| (b's
/// coordinates are within a's and dr). false for a `distance` not at least 0, a horizon not
/// finite, or scales where the squares below could leave the range of doubles.
inline bool clearly_apart(const Path& a, const Path& b, double distance, double horizon,
                          double place) {
    const Vec2 dr = a.position - b.position;
    const Vec2 dv = a.velocity - b.velocity;
    const Vec2 da = a.acceleration - b.acceleration;
    const double H2 = horizon * horizon;
    const double across = std::abs(cross(dr, dv)) - std::abs(cross(da, dv)) * (0.5 * H2);
    const double speed_squared = length_squared(dv);
    // Without the margin first: most pairs that meet are told here, before the rest.
    if (!(across > 0 && across * across > distance * distance * speed_squared))
        return false;
    // The rounding of this test and of the gap's quartic grows with the paths' sizes, that of
    // the paths brought to a later moment with their coordinates (a few units in the last place
    // of each): a micrometre for each metre of the first, a picometre of the second.
    const double scale = std::abs(dr.x) + std::abs(dr.y) +
                         (std::abs(dv.x) + std::abs(dv.y)) * horizon +
                         (std::abs(da.x) + std::abs(da.y)) * H2 + distance;
    if (!(distance >= 0 && scale > 1e-100 && scale < 1e100 && place < 1e100 &&
          speed_squared > 1e-200 && speed_squared < 1e200))
        return false;
    const double clear = distance + 1e-6 * scale + 1e-12 * place;
    return across * across > clear * clear * speed_squared;
}

/// path_path_contact_time, or a lower bound on it (seconds from now as well) when that is much
/// cheaper: see first_contact_estimate. Inline, as first_contact_estimate is: the pair search
/// asks it of every pair in reach.
inline ContactEstimate path_path_contact_estimate(const Path& a, const Path& b, double distance,
                                                  double horizon) {
    return first_contact_estimate(pair_gap(a, b, distance), horizon);
}

/// First time the centre comes within `offset` of the line through `point` (from the side
/// `normal` points to) while moving towards it.
double path_line_contact_time(const Path& a, Vec2 point, Vec2 normal, double offset,
                              double horizon);

/// First time the centre comes within `radius` of `point` while moving towards it.
double path_point_contact_time(const Path& a, Vec2 point, double radius, double horizon);

} // namespace termpool::core
