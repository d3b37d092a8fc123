#pragma once
// When a moving ball first touches another ball, a cushion line, a jaw point or a capture line.
// Every function returns seconds from now, or +infinity when there is no contact within the
// horizon; a contact counts only while the two are approaching.

#include <algorithm>
#include <limits>
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

/// path_path_contact_time, or a lower bound on it (seconds from now as well) when that is much
/// cheaper: see first_contact_estimate.
ContactEstimate path_path_contact_estimate(const Path& a, const Path& b, double distance,
                                           double horizon);

/// First time the centre comes within `offset` of the line through `point` (from the side
/// `normal` points to) while moving towards it.
double path_line_contact_time(const Path& a, Vec2 point, Vec2 normal, double offset,
                              double horizon);

/// First time the centre comes within `radius` of `point` while moving towards it.
double path_point_contact_time(const Path& a, Vec2 point, double radius, double horizon);

/// The classic friction models (the seed report's) move balls on straight lines at non-polynomial
/// speeds: contacts are found by conservative advancement, stepping by the gap over an upper bound
/// of the closing speed (speeds never grow in these models), so that no contact is ever stepped
/// over. `gap(t)` returns the gap at time t and its rate of change; `closing_bound(t)` bounds how
/// fast the gap can shrink from t on.
template <class Gap, class Bound>
double advance_until_contact(Gap gap, Bound closing_bound, double horizon) {
    constexpr double tolerance = 1e-11; // m; contacts are taken this close, never overlapping
    constexpr int max_steps = 100000;
    double t = 0;
    for (int step = 0; step < max_steps && t <= horizon; ++step) {
        const auto [g, rate] = gap(t);
        if (g <= tolerance && rate < 0)
            return t;
        const double bound = closing_bound(t);
        if (!(bound > 0))
            break;
        t += std::max(g, tolerance) / bound;
    }
    return std::numeric_limits<double>::infinity();
}

} // namespace termpool::core
