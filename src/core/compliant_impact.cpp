// Stronge's compliant frictional impact (compliant_impact.hpp), phase by phase.
//
// Time is theta = w_n t, velocities are in units of the approach speed V and the tangential
// spring's deflection u in V / w_n. The normal force is F_max sin(phi): the phase phi runs with
// theta from 0 to pi/2 while the normal spring compresses, then at 1/e the rate to pi while it
// restitutes, the contact point's normal velocity being -cos(phi), then -e cos(phi). The largest
// deflection friction allows, mu F_n / k_t, is then mu eta^2 sin(phi), eta^2 = k_n / k_t =
// beta_t / (beta_n r^2) for r = w_t / w_n.
//
// Slipping along sigma (the spring's foot sliding that way, friction -sigma mu F_n on the ball):
// u = sigma mu eta^2 sin(phi), and v = v_a - sigma mu b (v_n - v_n(theta_a)), b = beta_t / beta_n.
// The foot stops when sigma (v - u') = C + k cos(phi) reaches 0, C = sigma v_a + mu b v_n(theta_a),
// k = mu (b - eta^2) compressing and mu (b e - eta^2 / e) restituting: an arc cosine.
// Stuck: u'' = -r^2 u, a harmonic motion, until |u| reaches mu eta^2 sin(phi).

#include "compliant_impact.hpp"

#include "../support/portable_math.hpp"
#include <algorithm>
#include <cmath>

namespace termpool::core {
namespace {

constexpr double half_pi = 1.57079632679489661923;

struct Contact {
    double mu;   // friction
    double e;    // restitution
    double r;    // w_t / w_n
    double b;    // beta_t / beta_n
    double eta2; // k_n / k_t
    double end;  // theta at separation, (1 + e) pi / 2

    bool restituting(double theta) const { return theta > half_pi; }
    double phase(double theta) const {
        return restituting(theta) ? half_pi + (theta - half_pi) / e : theta;
    }
    double normal_velocity(double theta) const {
        const double c = portable::cos(phase(theta));
        return restituting(theta) ? -e * c : -c;
    }
    double limit(double theta) const { return mu * eta2 * portable::sin(phase(theta)); }
};

// Where the contact is: time, tangential velocity of the contact point, spring deflection.
struct State {
    double theta;
    double v;
    double u;
};

// When a slip with C (above) ends: the first theta from `from` where the foot stops, or the end.
double slip_end(const Contact& c, double from, double C) {
    for (const bool restitution : {false, true}) {
        const double lo = restitution ? std::max(from, half_pi) : from;
        const double hi = restitution ? c.end : half_pi;
        if (lo >= hi)
            continue;
        const double k = restitution ? c.mu * (c.b * c.e - c.eta2 / c.e) : c.mu * (c.b - c.eta2);
        // cos(phi) is 0 at the end of the compression and -1 at the separation.
        if ((restitution ? C - k : C) > 0)
            continue; // sigma (v - u') is monotone in phi on each half: still slipping at its end
        if (k == 0)
            return lo;
        const double x = std::clamp(-C / k, -1.0, 1.0);
        const double phi = portable::atan2(std::sqrt(1 - x * x), x); // arc cosine of x
        const double theta = restitution ? half_pi + (phi - half_pi) * c.e : phi;
        return std::clamp(theta, lo, hi);
    }
    return c.end;
}

State stuck_at(const State& s, double r, double theta) {
    const double a = r * (theta - s.theta);
    const double cs = portable::cos(a), sn = portable::sin(a);
    return {theta, s.v * cs - r * s.u * sn, s.u * cs + s.v / r * sn};
}

// When a stick from `s` ends: the last theta before the spring's force first exceeds the
// friction limit (sampled, then halved to the last bit), or the end.
double stick_end(const Contact& c, const State& s) {
    constexpr int samples = 256;
    const auto over = [&](double theta) {
        return std::abs(stuck_at(s, c.r, theta).u) - c.limit(theta);
    };
    double lo = s.theta;
    for (int i = 1; i <= samples; ++i) {
        double hi = i == samples ? c.end : s.theta + (c.end - s.theta) * i / samples;
        if (over(hi) > 0) {
            for (;;) {
                const double mid = lo + (hi - lo) / 2;
                if (mid <= lo || mid >= hi)
                    break;
                (over(mid) > 0 ? hi : lo) = mid;
            }
            return lo;
        }
        lo = hi;
    }
    return c.end;
}

} // namespace

CompliantImpact compliant_impact(double slip, double friction, double restitution,
                                 double frequency_ratio, double inertia_ratio) {
    const double e = restitution;
    if (!(slip > 0) || !(friction > 0))
        return {slip > 0 ? slip : 0, e};
    const Contact c{friction,
                    e,
                    frequency_ratio,
                    inertia_ratio,
                    inertia_ratio / (frequency_ratio * frequency_ratio),
                    (1 + e) * half_pi};
    State s{0, slip, 0};
    // The foot moves at slip - u'(0) = slip - mu eta^2 at first: it sticks if that is not > 0.
    bool stuck = slip <= c.mu * c.eta2;
    double sigma = 1;
    // Two or three phases in practice; the bound only makes sure the loop ends.
    for (int phase = 0; phase < 64 && s.theta < c.end; ++phase) {
        if (stuck) {
            const double theta = stick_end(c, s);
            s = stuck_at(s, c.r, theta);
            sigma = s.u < 0 ? -1.0 : 1.0;
            s.u = sigma * c.limit(theta);
        } else {
            const double from = c.normal_velocity(s.theta);
            const double theta = slip_end(c, s.theta, sigma * s.v + c.mu * c.b * from);
            const double to = theta >= c.end ? e : c.normal_velocity(theta);
            s = {theta, s.v - sigma * c.mu * c.b * (to - from), sigma * c.limit(theta)};
        }
        stuck = !stuck;
    }
    // Phases that make no headway (a stick that ends where it starts, over and over) cannot
    // happen but at a tangency; the contact would then slip to its end.
    if (s.theta < c.end)
        s.v -= sigma * c.mu * c.b * (e - c.normal_velocity(s.theta));
    return {s.v, e};
}

} // namespace termpool::core
