#include "classic_contacts.hpp"

#include "../support/portable_math.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contact_time.hpp"
#include "polynomial.hpp"

namespace termpool::core {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double epsilon = std::numeric_limits<double>::epsilon();

// ---- decaying centres, in u = 1 - e^(-K t)

// The u a horizon of `horizon` seconds reaches (1 for an endless one).
double u_at(double K, double horizon) {
    return -portable::expm1(-K * horizon);
}

// Seconds until u: log1p keeps the precision of small u, where most contacts are.
double time_of_u(double u, double K, double horizon) {
    if (!(u < infinity))
        return infinity;
    return std::min(-portable::log1p(-u) / K, horizon);
}

// |dr + dw u|^2 - distance^2: the squared gap of two decaying centres, or of one and a fixed
// point, is a quadratic in u.
Polynomial4 decaying_gap(Vec2 dr, Vec2 dw, double distance) {
    Polynomial4 f;
    f.c = {length_squared(dr) - distance * distance, 2 * dot(dr, dw), length_squared(dw), 0, 0};
    return f;
}

// ---- one decaying centre and one parabola: conservative advancement

// The squared gap g = |d|^2 - distance^2 of the pair at some t, its slope, and what bounds its
// curvature from t on.
struct MixedSample {
    double t;
    double g;             // m^2
    double slope;         // dg/dt, m^2/s
    double separation;    // |d|, m
    double speeds;        // |v_a| + |v_b| at t, which bounds |d'| from t on (no speed grows), m/s
    double accelerations; // bounds |d''| from t on, m/s^2
};

struct MixedGap {
    DecayingPath a;
    double K;
    Path b;
    double distance;

    MixedSample at(double t) const {
        const double decay = portable::exp(-K * t);
        const Vec2 d = (a.position - b.position) + a.velocity * (-portable::expm1(-K * t) / K) -
                       (b.velocity * t + b.acceleration * (0.5 * t * t));
        const Vec2 va = a.velocity * decay;
        const Vec2 vb = b.velocity + b.acceleration * t;
        const double separation = length(d);
        const double speed_a = length(va);
        return {t,
                (separation - distance) * (separation + distance),
                2 * dot(d, va - vb),
                separation,
                speed_a + length(vb),
                K * speed_a + length(b.acceleration)};
    }
};

// A bound on |g''| = |2 |d'|^2 + 2 d.d''| over [s.t, end]: |d| grows at most at the speeds.
double curvature_bound(const MixedSample& s, double end) {
    const double farthest = s.separation + s.speeds * (end - s.t);
    return 2 * (s.speeds * s.speeds + farthest * s.accelerations);
}

// The descending root of g in [lo, hi] (g(lo) > 0 >= g(hi)) to round-off: Newton, replaced by
// bisection whenever it leaves the bracket or the bracket has not halved in two steps, so it
// ends once the bracket is down to adjacent doubles whatever g looks like.
double polish_root(const MixedGap& gap, MixedSample lo, MixedSample hi) {
    double a = lo.t, b = hi.t;
    double width_before = infinity, width = b - a;
    MixedSample s = hi;
    for (;;) {
        double x = s.t - s.g / s.slope;
        if (!(x > a && x < b) || width > 0.5 * width_before)
            x = a + 0.5 * (b - a);
        if (!(x > a && x < b))
            return a; // adjacent doubles: the side just before the contact
        s = gap.at(x);
        if (s.g > 0)
            a = x;
        else
            b = x;
        width_before = width;
        width = b - a;
        if (s.slope < 0 && std::abs(s.g / s.slope) <= 4 * epsilon * x)
            return x; // the next Newton step is below the time's precision
    }
}

// Overlapping at lo and still opening there (g <= 0, g' >= 0), closing at hi (g' < 0): the
// contact is where g turns down while <= 0, or the descending root if g gets positive between.
// Bisection on the slope (the case follows only a contact that rounding left overlapping).
double polish_turn(const MixedGap& gap, MixedSample lo, MixedSample hi) {
    for (;;) {
        const double x = lo.t + 0.5 * (hi.t - lo.t);
        if (!(x > lo.t && x < hi.t))
            return hi.t;
        const MixedSample s = gap.at(x);
        if (s.g > 0)
            return polish_root(gap, s, hi);
        if (s.slope < 0)
            hi = s;
        else
            lo = s;
    }
}

// How deep a contact the advancement may step over: 1e-12 m, far below every tolerance of the
// simulation. Stepping to the first root of the lower bound lowered by this much, rather than of
// the bound itself, is what keeps the step from shrinking without end near a tangency.
constexpr double skipped_depth = 1e-12; // m

} // namespace

double decaying_pair_contact_time(const DecayingPath& a, const DecayingPath& b, double K,
                                  double distance, double horizon) {
    const Polynomial4 f =
        decaying_gap(a.position - b.position, (a.velocity - b.velocity) * (1 / K), distance);
    return time_of_u(first_contact_time(f, u_at(K, horizon)), K, horizon);
}

double decaying_line_contact_time(const DecayingPath& a, double K, Vec2 point, Vec2 normal,
                                  double offset, double horizon) {
    Polynomial4 f;
    f.c = {dot(a.position - point, normal) - offset, dot(a.velocity, normal) / K, 0, 0, 0};
    return time_of_u(first_contact_time(f, u_at(K, horizon)), K, horizon);
}

double mixed_pair_contact_time(const DecayingPath& a, double K, const Path& b, double distance,
                               double horizon, int* steps) {
    if (steps)
        *steps = 0;
    if (!(horizon >= 0))
        return infinity;
    const double speed_b = length(b.velocity), deceleration_b = length(b.acceleration);
    if (speed_b == 0 && deceleration_b == 0) // b stands: a pair of decaying centres
        return decaying_pair_contact_time(a, {b.position, {}}, K, distance, horizon);
    double end = horizon;
    if (deceleration_b > 0) {
        end = std::min(end, speed_b / deceleration_b); // b stops (its parabola would turn back)
    } else if (!(end < infinity)) {
        // b on a straight line: it is farther than `distance` for good once it has gone past
        // the whole of a's way.
        end = (length(a.position - b.position) + length(a.velocity) / K + distance) / speed_b;
    }
    const MixedGap gap{a, K, b, distance};
    const double slack = 2 * distance * skipped_depth; // in g, m^2
    MixedSample s = gap.at(0);
    if (s.g <= 0 && s.slope < 0)
        return 0;
    for (int step = 1;; ++step) {
        if (steps)
            *steps = step;
        if (s.t >= end)
            return infinity;
        const double M = curvature_bound(s, end);
        if (!(M > 0))
            return infinity; // nothing moves: the gap stays as it is
        // g(s.t + h) >= g + g' h - M h^2 / 2 up to the first contact: step to where that bound,
        // lowered by the slack, first reaches zero. Within the step g stays above -slack.
        const double c = s.g + slack;
        double h;
        if (c > 0) {
            const double root = std::sqrt(s.slope * s.slope + 2 * M * c);
            h = s.slope >= 0 ? (s.slope + root) / M : 2 * c / (root - s.slope);
        } else {
            // Deeper in an opening overlap than the slack: step while g' cannot turn negative,
            // so the turn is not stepped over (never less than a millionth of the horizon, so
            // that the search ends).
            h = std::max(s.slope / M, end * 1e-6);
        }
        const double next_t = std::min(s.t + h, end);
        const MixedSample next = gap.at(next_t > s.t ? next_t : std::nextafter(s.t, infinity));
        if (next.g <= 0 && next.slope < 0)
            return s.g > 0 ? polish_root(gap, s, next) : polish_turn(gap, s, next);
        s = next;
    }
}

// ---- whole balls: their motion split at the switches

namespace {

DecayingPath decaying_path(const Ball& b) {
    return {b.position, b.velocity};
}

// A decelerating ball's centre over the next `duration` seconds.
Path decelerating_path(const Ball& b, const ClassicLaw& law, double duration) {
    const double speed = length(b.velocity);
    const Vec2 acceleration = speed > 0 ? b.velocity * (-law.deceleration / speed) : Vec2{};
    return {b.position, b.velocity, acceleration, duration};
}

Ball moved(const Ball& b, double dt, const ClassicMotion& m) {
    return dt > 0 ? m.advance(b, dt, *m.params) : b;
}

// Seconds until a ball leaves the decaying phase, 0 for one that is not in it (or stands).
double switch_time(const Ball& b, const ClassicLaw& law) {
    return is_moving(b) ? classic_switch_time(length(b.velocity), law) : 0;
}

// A contact of one ball with something fixed: `decaying(ball, horizon)` and
// `decelerating(ball, horizon)` solve one stretch.
template <class Decaying, class Decelerating>
double single_ball_contact(const Ball& ball, double horizon, const ClassicMotion& m,
                           Decaying decaying, Decelerating decelerating) {
    if (!is_moving(ball) || !(horizon >= 0))
        return infinity;
    const double switch_at = std::min(switch_time(ball, m.law), horizon);
    if (switch_at > 0) {
        const double dt = decaying(ball, switch_at);
        if (dt < infinity)
            return dt;
    }
    if (switch_at < horizon || (switch_at == 0 && horizon == 0)) {
        const double dt = decelerating(moved(ball, switch_at, m), horizon - switch_at);
        if (dt < infinity)
            return switch_at + dt;
    }
    return infinity;
}

} // namespace

double classic_line_contact_time(const Ball& ball, Vec2 point, Vec2 normal, double offset,
                                 double horizon, const ClassicMotion& m) {
    return single_ball_contact(
        ball, horizon, m,
        [&](const Ball& b, double h) {
            return decaying_line_contact_time(decaying_path(b), m.law.decay_rate, point, normal,
                                              offset, h);
        },
        [&](const Ball& b, double h) {
            return path_line_contact_time(decelerating_path(b, m.law, h), point, normal, offset, h);
        });
}

double classic_point_contact_time(const Ball& ball, Vec2 point, double radius, double horizon,
                                  const ClassicMotion& m) {
    return single_ball_contact(
        ball, horizon, m,
        [&](const Ball& b, double h) {
            return decaying_pair_contact_time(decaying_path(b), {point, {}}, m.law.decay_rate,
                                              radius, h);
        },
        [&](const Ball& b, double h) {
            return path_point_contact_time(decelerating_path(b, m.law, h), point, radius, h);
        });
}

double classic_pair_contact_time(const Ball& a, const Ball& b, double distance, double horizon,
                                 const ClassicMotion& m) {
    const bool a_moves = is_moving(a), b_moves = is_moving(b);
    if ((!a_moves && !b_moves) || !(horizon >= 0))
        return infinity;
    // Each ball is in one phase between the cuts; a ball that stands takes the other's.
    const double switch_a = switch_time(a, m.law), switch_b = switch_time(b, m.law);
    std::array<double, 4> cuts{0, std::clamp(switch_a, 0.0, horizon),
                               std::clamp(switch_b, 0.0, horizon), horizon};
    std::sort(cuts.begin(), cuts.end());
    const double K = m.law.decay_rate;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double start = cuts[k], end = cuts[k + 1];
        if (end <= start && !(k == 0 && horizon == 0))
            continue;
        const Ball sa = moved(a, start, m), sb = moved(b, start, m);
        const bool a_decays = a_moves && start < switch_a;
        const bool b_decays = b_moves && start < switch_b;
        const bool both_decay = (a_decays || !a_moves) && (b_decays || !b_moves);
        const bool neither_decays = !a_decays && !b_decays;
        const double length = end - start;
        double dt;
        if (both_decay) {
            dt = decaying_pair_contact_time(decaying_path(sa), decaying_path(sb), K, distance,
                                            length);
        } else if (neither_decays) {
            dt = path_path_contact_time(decelerating_path(sa, m.law, length),
                                        decelerating_path(sb, m.law, length), distance, length);
        } else if (a_decays) {
            dt = mixed_pair_contact_time(decaying_path(sa), K, decelerating_path(sb, m.law, length),
                                         distance, length);
        } else {
            dt = mixed_pair_contact_time(decaying_path(sb), K, decelerating_path(sa, m.law, length),
                                         distance, length);
        }
        if (dt < infinity)
            return start + dt;
    }
    return infinity;
}

} // namespace termpool::core
