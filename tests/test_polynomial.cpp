#include "core/polynomial.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

using termpool::core::first_contact_estimate;
using termpool::core::first_contact_time;
using termpool::core::Polynomial4;
using termpool::core::solve_quadratic;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kBallRadius = 0.028575; // pool ball, m

struct Vec2 {
    double x = 0.0;
    double y = 0.0;
};

double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}

// Gap |d + v t + a t^2|^2 - (2R)^2 for relative position d, velocity v and half the relative
// acceleration a, i.e. the polynomial the simulator builds for two balls.
Polynomial4 ball_gap(Vec2 d, Vec2 v, Vec2 half_acc, double radius = kBallRadius) {
    const double contact = 2.0 * radius;
    return Polynomial4{{dot(d, d) - contact * contact, 2.0 * dot(d, v),
                        dot(v, v) + 2.0 * dot(d, half_acc), 2.0 * dot(v, half_acc),
                        dot(half_acc, half_acc)}};
}

// Rounding-error scale of evaluating f at t, independent of the implementation under test.
double eval_noise(const Polynomial4& f, double t) {
    double s = 0.0;
    for (int k = 4; k >= 0; --k)
        s = s * t + std::fabs(f.c[static_cast<std::size_t>(k)]);
    return 4.0 * kEps * s;
}

double derivative_scale(const Polynomial4& f, double t) {
    return std::fabs(f.c[1]) + 2.0 * std::fabs(f.c[2]) * t + 3.0 * std::fabs(f.c[3]) * t * t +
           4.0 * std::fabs(f.c[4]) * t * t * t;
}

// Bisection on a sign change f(lo) > 0 >= f(hi), down to adjacent doubles.
double bisect(const Polynomial4& f, double lo, double hi) {
    for (int i = 0; i < 2000; ++i) {
        const double mid = lo + 0.5 * (hi - lo);
        if (!(mid > lo && mid < hi))
            break;
        if (f.evaluate(mid) > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

bool close_rel(double got, double want, double rel) {
    return std::fabs(got - want) <= rel * std::fabs(want);
}

} // namespace

TEST_CASE("solve_quadratic: ordinary, ordered and degenerate cases", "[polynomial]") {
    double r[2] = {0.0, 0.0};

    REQUIRE(solve_quadratic(1.0, -3.0, 2.0, r) == 2);
    CHECK(r[0] == 1.0);
    CHECK(r[1] == 2.0);

    REQUIRE(solve_quadratic(-1.0, 3.0, -2.0, r) == 2); // negative leading coefficient
    CHECK(r[0] == 1.0);
    CHECK(r[1] == 2.0);

    REQUIRE(solve_quadratic(1.0, 0.0, -4.0, r) == 2); // b == 0
    CHECK(r[0] == -2.0);
    CHECK(r[1] == 2.0);

    REQUIRE(solve_quadratic(2.0, -3.0, 0.0, r) == 2); // c == 0: a root exactly at 0
    CHECK(r[0] == 0.0);
    CHECK(r[1] == 1.5);

    CHECK(solve_quadratic(1.0, 0.0, 1.0, r) == 0); // complex pair

    REQUIRE(solve_quadratic(1.0, -2.0, 1.0, r) == 1); // double root
    CHECK(r[0] == 1.0);

    REQUIRE(solve_quadratic(0.0, 2.0, -1.0, r) == 1); // linear
    CHECK(r[0] == 0.5);

    CHECK(solve_quadratic(0.0, 0.0, 1.0, r) == 0); // nonzero constant
    CHECK(solve_quadratic(0.0, 0.0, 0.0, r) == 0); // zero polynomial: no finite answer
}

TEST_CASE("solve_quadratic: numerically stable", "[polynomial]") {
    double r[2] = {0.0, 0.0};

    // Widely separated roots: the textbook formula loses the small root to cancellation.
    REQUIRE(solve_quadratic(1.0, -1e8, 1.0, r) == 2);
    CHECK(close_rel(r[0], 1e-8, 4 * kEps));
    CHECK(close_rel(r[1], 1e8, 4 * kEps));

    // Tiny leading coefficient (almost linear): the finite root must stay accurate.
    REQUIRE(solve_quadratic(1e-30, 2.0, -1.0, r) == 2);
    CHECK(close_rel(r[1], 0.5, 4 * kEps));

    // Roots 1 and 1 + 2^-26 with exactly representable coefficients: b^2 - 4ac = 2^-52 is lost
    // entirely by a naively rounded discriminant, which then reports a double root.
    const double d = std::ldexp(1.0, -26);
    REQUIRE(solve_quadratic(1.0, -(2.0 + d), 1.0 + d, r) == 2);
    CHECK(r[0] == 1.0);
    CHECK(r[1] == 1.0 + d);

    // Huge and tiny scales: b^2 would overflow / underflow without rescaling.
    REQUIRE(solve_quadratic(1e200, -3e200, 2e200, r) == 2);
    CHECK(close_rel(r[0], 1.0, 4 * kEps));
    CHECK(close_rel(r[1], 2.0, 4 * kEps));
    REQUIRE(solve_quadratic(1e-200, -3e-200, 2e-200, r) == 2);
    CHECK(close_rel(r[0], 1.0, 4 * kEps));
    CHECK(close_rel(r[1], 2.0, 4 * kEps));
}

TEST_CASE("Polynomial4 evaluation helpers", "[polynomial]") {
    const Polynomial4 f{{1.0, -2.0, 3.0, -4.0, 5.0}};
    CHECK(f.evaluate(2.0) == 1.0 - 4.0 + 12.0 - 32.0 + 80.0);
    CHECK(f.derivative(2.0) == -2.0 + 12.0 - 48.0 + 160.0);
    CHECK(f.second_derivative(2.0) == 6.0 - 48.0 + 240.0);
    const Polynomial4 df = f.derivative_polynomial();
    CHECK(df.evaluate(2.0) == f.derivative(2.0));
    CHECK(df.c[4] == 0.0);
}

TEST_CASE("first_contact_time: straight-line head-on approach", "[polynomial]") {
    // Ball 1 m away closing at 2 m/s: contact when the centre distance is 2R.
    const Polynomial4 f = ball_gap({1.0, 0.0}, {-2.0, 0.0}, {0.0, 0.0});
    const double expected = (1.0 - 2.0 * kBallRadius) / 2.0;
    const double t = first_contact_time(f, 10.0);
    CHECK(close_rel(t, expected, 1e-12));
    CHECK(f.evaluate(t) >= -eval_noise(f, t)); // not past contact beyond rounding

    // Fast and slow, far and near.
    for (double speed : {0.01, 0.3, 5.0, 20.0}) {
        for (double dist : {0.06, 0.5, 2.5}) {
            const Polynomial4 g = ball_gap({0.0, dist}, {0.0, -speed}, {0.0, 0.0});
            const double want = (dist - 2.0 * kBallRadius) / speed;
            INFO("speed " << speed << " dist " << dist);
            CHECK(close_rel(first_contact_time(g, 1000.0), want, 1e-12));
        }
    }
}

TEST_CASE("first_contact_time: oblique and decelerating approaches", "[polynomial]") {
    // Impact parameter b < 2R: contact when the along-line separation is sqrt(4R^2 - b^2).
    const double b = 1.3 * kBallRadius;
    const double along = 0.8;
    const double speed = 1.7;
    const Polynomial4 f = ball_gap({along, b}, {-speed, 0.0}, {0.0, 0.0});
    const double want = (along - std::sqrt(4.0 * kBallRadius * kBallRadius - b * b)) / speed;
    CHECK(close_rel(first_contact_time(f, 5.0), want, 1e-12));

    // Head-on with constant deceleration: separation x(t) = x0 - v t + (alpha/2) t^2 reaches 2R
    // at the smaller root of the quadratic, computed here independently in long double.
    const double x0 = 1.2;
    const double v = 1.5;
    const double alpha = 0.6;
    const Polynomial4 g = ball_gap({x0, 0.0}, {-v, 0.0}, {0.5 * alpha, 0.0});
    const long double A = 0.5L * alpha;
    const long double B = -static_cast<long double>(v);
    const long double C = static_cast<long double>(x0) - 2.0L * kBallRadius;
    const long double root = (-B - std::sqrt(B * B - 4.0L * A * C)) / (2.0L * A);
    const double stop = v / alpha; // the ball stops at 2.5 s, after contact
    CHECK(close_rel(first_contact_time(g, stop), static_cast<double>(root), 1e-12));
}

TEST_CASE("first_contact_time: dip the local quadratic model does not see", "[polynomial]") {
    // 1 - 1.4 t + 0.5 t^2 - 0.1 t^3 + 0.01 t^4 is convex everywhere (f'' = 1 - 0.6 t + 0.12 t^2
    // has no real root) and its Taylor quadratic at 0 never reaches zero (1.4^2 < 2), yet the
    // cubic term pulls it below zero just after t = 1.
    const Polynomial4 f{{1.0, -1.4, 0.5, -0.1, 0.01}};
    REQUIRE(f.evaluate(1.0) > 0.0);
    REQUIRE(f.evaluate(1.2) < 0.0);
    REQUIRE(f.evaluate(6.0) > 0.0);
    const double want = bisect(f, 1.0, 1.2);
    CHECK(std::fabs(first_contact_time(f, 6.0) - want) <= 1e-14);
    CHECK(first_contact_time(f, 1.0) == kInf);
}

TEST_CASE("first_contact_time: misses and separating pairs", "[polynomial]") {
    // Grazing miss: impact parameter a hair more than 2R.
    const double b = 2.0 * kBallRadius * (1.0 + 1e-9);
    CHECK(first_contact_time(ball_gap({0.7, b}, {-1.0, 0.0}, {0.0, 0.0}), 10.0) == kInf);
    // Clear miss.
    CHECK(first_contact_time(ball_gap({0.7, 0.2}, {-1.0, 0.0}, {0.0, 0.0}), 10.0) == kInf);
    // Separating pair, apart and just touching.
    CHECK(first_contact_time(ball_gap({0.3, 0.1}, {1.0, 0.5}, {-0.1, -0.05}), 1.0) == kInf);
    CHECK(first_contact_time(ball_gap({2.0 * kBallRadius, 0.0}, {1.0, 0.0}, {0.0, 0.0}), 1.0) ==
          kInf);
    // Stationary pair, and the zero polynomial (f' is never negative).
    CHECK(first_contact_time(ball_gap({0.3, 0.0}, {0.0, 0.0}, {0.0, 0.0}), 100.0) == kInf);
    CHECK(first_contact_time(Polynomial4{}, 100.0) == kInf);
}

TEST_CASE("first_contact_time: already touching or overlapping", "[polynomial]") {
    // Touching and approaching: exactly 0.
    CHECK(first_contact_time(Polynomial4{{0.0, -1.0, 1.0, 0.0, 0.0}}, 1.0) == 0.0);
    CHECK(first_contact_time(Polynomial4{{-1e-15, -1e-3, 0.0, 0.0, 0.0}}, 1.0) == 0.0);
    CHECK(first_contact_time(Polynomial4{{0.0, -1.0, 0.0, 0.0, 0.0}}, 0.0) == 0.0);
    // f'(0) == 0 but decreasing right after 0 (second, third and fourth order).
    CHECK(first_contact_time(Polynomial4{{0.0, 0.0, -1.0, 0.0, 0.0}}, 1.0) == 0.0);
    CHECK(first_contact_time(Polynomial4{{-1e-12, 0.0, -1.0, 5.0, 0.0}}, 1.0) == 0.0);
    CHECK(first_contact_time(Polynomial4{{0.0, 0.0, 0.0, -1.0, 0.0}}, 1.0) == 0.0);
    CHECK(first_contact_time(Polynomial4{{0.0, 0.0, 0.0, 0.0, -1.0}}, 1.0) == 0.0);
    // f'(0) == 0 and increasing right after: touching at rest relative to each other, opening.
    CHECK(first_contact_time(Polynomial4{{0.0, 0.0, 1.0, 0.0, 0.0}}, 1.0) == kInf);
    CHECK(first_contact_time(Polynomial4{{0.0, 0.0, 0.0, 1.0, 0.0}}, 1.0) == kInf);
}

TEST_CASE("first_contact_time: overlap left by rounding while separating", "[polynomial]") {
    const double overlap = 1e-12;
    // Separating forever: +inf.
    CHECK(first_contact_time(Polynomial4{{-overlap, 0.5, 1.0, 0.0, 0.0}}, 10.0) == kInf);
    CHECK(first_contact_time(ball_gap({2.0 * kBallRadius - 1e-13, 0.0}, {0.4, 0.0}, {0.0, 0.0}),
                             10.0) == kInf);

    // Separating, then pulled back: f = -overlap + t - t^2 crosses zero going up near 1e-12 and
    // comes back down at the larger root of t^2 - t + overlap.
    {
        const Polynomial4 f{{-overlap, 1.0, -1.0, 0.0, 0.0}};
        const double back = 1.0 - overlap / (1.0 - overlap); // larger root, stably
        CHECK(close_rel(first_contact_time(f, 10.0), back, 1e-12));
        CHECK(first_contact_time(f, 0.9) == kInf);
    }

    // Never gets positive: the local maximum t_m = 0.25 of -overlap + 1e-14 (t - 2 t^2) is <= 0,
    // after which f decreases while still overlapping, so t_m is the answer.
    {
        const Polynomial4 f{{-overlap, 1e-14, -2e-14, 0.0, 0.0}};
        CHECK(close_rel(first_contact_time(f, 10.0), 0.25, 1e-12));
        CHECK(first_contact_time(f, 0.2) == kInf);
    }

    // Same with a quartic whose maximum (t_m = 1) touches exactly 0: f = -(t - 1)^2 (t^2 + 1).
    {
        const Polynomial4 f{{-1.0, 2.0, -2.0, 2.0, -1.0}};
        CHECK(close_rel(first_contact_time(f, 3.0), 1.0, 1e-7));
    }
}

TEST_CASE("first_contact_time: horizon cuts and decelerating balls", "[polynomial]") {
    // Ball rolls toward another and stops 5 cm short: the horizon is the stop time.
    const double v = 1.0;
    const double alpha = 0.5;                  // deceleration, m/s^2
    const double travel = v * v / (2 * alpha); // 1 m
    const double x0 = travel + 2.0 * kBallRadius + 0.05;
    const Polynomial4 f = ball_gap({x0, 0.0}, {-v, 0.0}, {0.5 * alpha, 0.0});
    CHECK(first_contact_time(f, v / alpha) == kInf);

    // Constant-speed approach with contact at 1.5 s: cut off just before, found just after.
    const Polynomial4 g = ball_gap({1.5 + 2.0 * kBallRadius, 0.0}, {-1.0, 0.0}, {0.0, 0.0});
    CHECK(first_contact_time(g, 1.4999) == kInf);
    CHECK(close_rel(first_contact_time(g, 1.5001), 1.5, 1e-12));
    // Unbounded horizon.
    CHECK(close_rel(first_contact_time(g, kInf), 1.5, 1e-12));
    CHECK(first_contact_time(g, -1.0) == kInf);
}

TEST_CASE("first_contact_time: two close roots", "[polynomial]") {
    // (t - r)(t - r - 1e-9)(t^2 + 1): a dip only 1e-9 wide. Sampling would step over it.
    for (double r : {1e-3, 2e-3, 5e-4}) {
        const double delta = 1e-9;
        const double s = 2.0 * r + delta; // sum of the close roots
        const double p = r * (r + delta); // product
        // (t^2 - s t + p)(t^2 + 1)
        const Polynomial4 f{{p, -s, 1.0 + p, -s, 1.0}};
        const double t = first_contact_time(f, 1.0);
        INFO("r " << r << " t - r " << (t - r));
        // The roots of the rounded coefficients move by about noise / |f'| ~ 1e-12.
        CHECK(std::fabs(t - r) < 2e-11);
        CHECK(t < r + 0.5 * delta);
    }

    // The same dip preceded by a bump that stays positive: the first descending root is still r.
    {
        const double r = 0.2;
        const double delta = 1e-7;
        const Polynomial4 f{{r * (r + delta), -(2 * r + delta), 1.0, 0.0, 0.0}};
        CHECK(std::fabs(first_contact_time(f, 1.0) - r) < 1e-10);
    }
}

TEST_CASE("first_contact_time: degenerate degrees", "[polynomial]") {
    // Linear.
    CHECK(close_rel(first_contact_time(Polynomial4{{1.0, -1.0, 0.0, 0.0, 0.0}}, 2.0), 1.0, 1e-15));
    CHECK(first_contact_time(Polynomial4{{1.0, -1.0, 0.0, 0.0, 0.0}}, 0.5) == kInf);
    CHECK(first_contact_time(Polynomial4{{-1.0, 1.0, 0.0, 0.0, 0.0}}, 5.0) == kInf);
    // Constants.
    CHECK(first_contact_time(Polynomial4{{-1.0, 0.0, 0.0, 0.0, 0.0}}, 5.0) == kInf);
    CHECK(first_contact_time(Polynomial4{{1.0, 0.0, 0.0, 0.0, 0.0}}, 5.0) == kInf);
    // Quadratic: ball 0.5 m from a cushion line at speed 2 m/s decelerating at 0.4 m/s^2
    // (distance minus radius).
    {
        const double y0 = 0.5;
        const double v = 2.0;
        const double a = 0.4;
        const Polynomial4 f{{y0 - kBallRadius, -v, 0.5 * a, 0.0, 0.0}};
        const double c = y0 - kBallRadius;
        const double disc = v * v - 2.0 * a * c;
        const double want = 2.0 * c / (v + std::sqrt(disc));
        CHECK(close_rel(first_contact_time(f, 3.0), want, 1e-14));
    }
    // Quadratic with roots 0.5 and 1.5.
    CHECK(close_rel(first_contact_time(Polynomial4{{0.75, -2.0, 1.0, 0.0, 0.0}}, 3.0), 0.5, 1e-15));
    // Cubic: -(t - 1)(t - 2)(t - 3) is 6 at 0 and falls through 1.
    CHECK(
        close_rel(first_contact_time(Polynomial4{{6.0, -11.0, 6.0, -1.0, 0.0}}, 5.0), 1.0, 1e-15));
    // Cubic (t - 1)(t - 2)(t - 3) starts at -6 rising: first descending stretch is after the
    // local maximum near 1.42 where f > 0, so the answer is the descending root 2.
    CHECK(
        close_rel(first_contact_time(Polynomial4{{-6.0, 11.0, -6.0, 1.0, 0.0}}, 5.0), 2.0, 1e-15));
}

TEST_CASE("first_contact_time: coefficient scales", "[polynomial]") {
    const Polynomial4 base = ball_gap({0.9, 0.01}, {-3.0, 0.05}, {0.4, -0.1});
    const double t0 = first_contact_time(base, 2.0);
    REQUIRE(t0 < 2.0);
    // Scaling f does not move its roots.
    for (double scale : {1e-200, 1e-30, 1e30, 1e200}) {
        Polynomial4 f = base;
        for (double& ck : f.c)
            ck *= scale;
        INFO("scale " << scale);
        CHECK(close_rel(first_contact_time(f, 2.0), t0, 1e-13));
    }
    // Rescaling time: f(t / tau) has its root at tau * t0, even for nanosecond horizons.
    for (double tau : {1e-9, 1e-4, 1e2}) {
        Polynomial4 f = base;
        for (int k = 0; k < 5; ++k)
            f.c[static_cast<std::size_t>(k)] /= std::pow(tau, k);
        INFO("tau " << tau);
        CHECK(close_rel(first_contact_time(f, 2.0 * tau), tau * t0, 1e-12));
    }
}

namespace {

// Outcome of checking one random case against the dense-scan reference.
struct RandomCheck {
    bool ok = true;
    bool compared = false; // a clear crossing (or clear miss) was compared exactly
    std::string why;
};

RandomCheck check_against_scan(const Polynomial4& f, double horizon, double got) {
    constexpr int kSamples = 256;
    RandomCheck out;
    const double dt = horizon / kSamples;
    const double c2 = std::fabs(f.c[2]);
    const double c3 = std::fabs(f.c[3]);
    const double c4 = std::fabs(f.c[4]);
    // |f''| bound on [0, H]: between samples f stays above the chord minus max|f''| dt^2 / 8.
    const double sag =
        (2.0 * c2 + 6.0 * c3 * horizon + 12.0 * c4 * horizon * horizon) * dt * dt / 8.0;
    const double g_sag = (2.0 * c2 + 6.0 * c3 * horizon + 12.0 * c4 * horizon * horizon) * dt;

    if (got != kInf) {
        if (!(got >= 0.0 && got <= horizon)) {
            out.ok = false;
            out.why = "result outside [0, H]";
            return out;
        }
        // Never clearly positive, never clearly increasing.
        if (f.evaluate(got) > 64.0 * eval_noise(f, got)) {
            out.ok = false;
            out.why = "f clearly positive at result";
            return out;
        }
        if (f.derivative(got) > 1e-6 * derivative_scale(f, got)) {
            out.ok = false;
            out.why = "f clearly increasing at result";
            return out;
        }
    }

    const double f0 = f.c[0];
    const double g0 = f.c[1];
    if (f0 <= 0.0 && g0 < 0.0) {
        out.compared = true;
        if (got != 0.0) {
            out.ok = false;
            out.why = "approaching overlap must return 0";
        }
        return out;
    }

    // Dense scan: every sample clearly in S bounds the answer from above; with f(0) clearly
    // positive, the first clear sign change is the reference crossing.
    bool all_clearly_positive = true;
    double prev_t = 0.0;
    double prev_f = f0;
    bool prefix_positive = f0 > sag + eval_noise(f, 0.0);
    for (int i = 1; i <= kSamples; ++i) {
        const double t = i == kSamples ? horizon : dt * i;
        const double ft = f.evaluate(t);
        const double gt = f.derivative(t);
        const double nz = eval_noise(f, t);
        if (ft < -64.0 * nz && gt < -1e-6 * derivative_scale(f, t) && got > t) {
            out.ok = false;
            out.why = "missed a sample that is clearly in S";
            return out;
        }
        if (!(ft > sag + nz))
            all_clearly_positive = false;
        if (prefix_positive && ft <= 0.0 && prev_f > 0.0) {
            // Clear crossing: f' stays negative over the whole interval, so the root is unique.
            const double r = bisect(f, prev_t, t);
            const double gr = f.derivative(r);
            if (gr < -1.01 * g_sag && ft < -nz) {
                out.compared = true;
                const double tol = 8.0 * eval_noise(f, r) / std::fabs(gr) + 8.0 * kEps * r;
                if (!(std::fabs(got - r) <= tol)) {
                    std::ostringstream os;
                    os.precision(17);
                    os << "crossing mismatch: reference " << r << " tol " << tol;
                    out.ok = false;
                    out.why = os.str();
                }
            }
            return out;
        }
        if (prefix_positive && !(ft > sag + nz))
            prefix_positive = false;
        prev_t = t;
        prev_f = ft;
    }
    if (f0 > 0.0 && all_clearly_positive && prefix_positive) {
        out.compared = true;
        if (got != kInf) {
            out.ok = false;
            out.why = "reference sees no contact";
        }
    }
    return out;
}

// Counts the random cases of one test and reports each failure with the case that caused it.
struct ScanTally {
    int compared = 0;
    int failures = 0;

    void fail(const std::string& why, int n, double horizon, double got, const Polynomial4& f) {
        ++failures;
        std::ostringstream os;
        os.precision(17);
        os << why << "\n  case " << n << " horizon " << horizon << " got " << got << "\n  c = {"
           << f.c[0] << ", " << f.c[1] << ", " << f.c[2] << ", " << f.c[3] << ", " << f.c[4] << "}";
        FAIL_CHECK(os.str());
    }

    // first_contact_time's answer `got` against the dense scan.
    void check(int n, const Polynomial4& f, double horizon, double got) {
        const RandomCheck r = check_against_scan(f, horizon, got);
        if (r.compared)
            ++compared;
        if (!r.ok)
            fail(r.why, n, horizon, got, f);
    }
};

} // namespace

TEST_CASE("first_contact_time: random ball trajectories against a dense scan, and "
          "first_contact_estimate against first_contact_time",
          "[polynomial]") {
    std::mt19937_64 rng(0x5eedc0ffeeULL);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
    auto direction = [&]() {
        const double a = 2.0 * std::numbers::pi * unit(rng);
        return Vec2{std::cos(a), std::sin(a)};
    };

    constexpr int kCases = 200000;
    ScanTally tally;
    int hits = 0;
    int bounds = 0;
    for (int n = 0; n < kCases && tally.failures < 5; ++n) {
        const int kind = static_cast<int>(unit(rng) * 4.0);
        Vec2 d;
        Vec2 v;
        Vec2 half_acc;
        double horizon = 0.0;
        if (kind <= 1) {
            // Aimed shot: relative velocity points at the other ball with an offset up to 3R.
            const Vec2 u = direction();
            const double dist = 2.0 * kBallRadius + log_uniform(1e-4, 2.5);
            d = {u.x * dist, u.y * dist};
            const double offset = (unit(rng) * 2.0 - 1.0) * 3.0 * kBallRadius;
            const double speed = log_uniform(0.01, 20.0);
            v = {(-u.x * dist - u.y * offset) / dist * speed,
                 (-u.y * dist + u.x * offset) / dist * speed};
            const double acc = log_uniform(0.1, 2.0);
            const Vec2 ad = kind == 0 ? direction() : Vec2{v.x / speed, -v.y / speed};
            half_acc = {0.5 * acc * ad.x, 0.5 * acc * ad.y};
            horizon = kind == 0 ? log_uniform(1e-3, 10.0) : std::min(10.0, speed / acc);
        } else if (kind == 2) {
            // Random positions and motions on a table, any horizon.
            d = {(unit(rng) - 0.5) * 2.24, (unit(rng) - 0.5) * 1.12};
            const Vec2 u = direction();
            const double speed = log_uniform(1e-3, 20.0);
            v = {u.x * speed, u.y * speed};
            const Vec2 a = direction();
            const double acc = log_uniform(0.1, 2.0);
            half_acc = {0.5 * acc * a.x, 0.5 * acc * a.y};
            horizon = log_uniform(1e-9, 100.0);
        } else {
            // Starting at or just inside contact (rounding overlap), moving any way.
            const Vec2 u = direction();
            const double dist = 2.0 * kBallRadius * (1.0 + (unit(rng) - 0.7) * 1e-12);
            d = {u.x * dist, u.y * dist};
            const Vec2 w = direction();
            const double speed = log_uniform(1e-3, 5.0);
            v = {w.x * speed, w.y * speed};
            const Vec2 a = direction();
            const double acc = log_uniform(0.1, 2.0);
            half_acc = {0.5 * acc * a.x, 0.5 * acc * a.y};
            horizon = log_uniform(1e-6, 5.0);
        }
        const Polynomial4 f = ball_gap(d, v, half_acc);
        const double got = first_contact_time(f, horizon);
        if (got != kInf)
            ++hits;
        // The estimate is either the same answer or a time no later than it.
        const termpool::core::ContactEstimate estimate = first_contact_estimate(f, horizon);
        bounds += estimate.exact ? 0 : 1;
        if (estimate.exact ? estimate.time != got : !(estimate.time >= 0 && estimate.time <= got)) {
            tally.fail("estimate " + std::to_string(estimate.time) +
                           (estimate.exact ? " (exact)" : " (bound)") + ", kind " +
                           std::to_string(kind),
                       n, horizon, got, f);
        }
        tally.check(n, f, horizon, got);
    }
    INFO("compared " << tally.compared << " hits " << hits << " bounds " << bounds);
    CHECK(tally.failures == 0);
    // The generator must actually exercise both outcomes and mostly clear cases.
    CHECK(hits > kCases / 10);
    CHECK(bounds > kCases / 20);
    CHECK(tally.compared > kCases / 2);
}

TEST_CASE("first_contact_time: random quartics against a dense scan", "[polynomial]") {
    // Shapes that ball trajectories rarely produce: products of quadratics with close, double or
    // complex roots, arbitrary coefficient signs, and extrema within a hair of zero.
    std::mt19937_64 rng(0xfeedbeefULL);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
    constexpr int kCases = 60000;
    ScanTally tally;
    for (int n = 0; n < kCases && tally.failures < 5; ++n) {
        const int kind = static_cast<int>(unit(rng) * 3.0);
        Polynomial4 f;
        double horizon = log_uniform(1e-3, 10.0);
        const double H = horizon;
        const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
        if (kind == 0) {
            auto quadratic = [&](double& a0, double& a1) {
                const double r = unit(rng) * 1.2 * H;
                const double sep = unit(rng) < 0.3 ? H * log_uniform(1e-9, 1e-3) : unit(rng) * H;
                if (unit(rng) < 0.3) { // complex pair r +- i sep
                    a1 = -2.0 * r;
                    a0 = r * r + sep * sep;
                } else { // real roots r and r + sep
                    a1 = -(2.0 * r + sep);
                    a0 = r * (r + sep);
                }
            };
            double p0 = 0.0, p1 = 0.0, q0 = 0.0, q1 = 0.0;
            quadratic(p0, p1);
            quadratic(q0, q1);
            f = Polynomial4{{sign * p0 * q0, sign * (p0 * q1 + p1 * q0), sign * (p0 + q0 + p1 * q1),
                             sign * (p1 + q1), sign}};
        } else if (kind == 1) {
            for (int k = 0; k < 5; ++k) {
                const double mag = log_uniform(1e-3, 1e3) / std::pow(H, k);
                f.c[static_cast<std::size_t>(k)] =
                    (unit(rng) < 0.5 ? -mag : mag) * (unit(rng) < 0.15 ? 0.0 : 1.0);
            }
        } else {
            // sign (t - m)^2 (t^2 + k) + e: a double root at m nudged to a graze, a narrow dip or
            // a local maximum just above or below zero.
            const double m = unit(rng) * H;
            const double k = log_uniform(1e-3, 10.0) * H * H;
            const double e = (unit(rng) - 0.5) * log_uniform(1e-14, 1e-2) * H * H * k;
            f = Polynomial4{{sign * m * m * k + e, sign * (-2.0 * m * k), sign * (k + m * m),
                             sign * (-2.0 * m), sign}};
        }
        tally.check(n, f, horizon, first_contact_time(f, horizon));
    }
    CHECK(tally.failures == 0);
    CHECK(tally.compared > kCases / 4);
}

TEST_CASE("first_contact_time: random quadratics (a ball against a line) against a dense scan",
          "[polynomial]") {
    // Degree <= 2 takes a closed-form path: check it keeps the general search's conventions,
    // including opening overlaps (f(0) <= 0) and concave gaps.
    std::mt19937_64 rng(0x11feULL);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
    auto signed_mag = [&](double lo, double hi) {
        return (unit(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(lo, hi);
    };
    constexpr int kCases = 40000;
    ScanTally tally;
    for (int n = 0; n < kCases && tally.failures < 5; ++n) {
        const double horizon = log_uniform(1e-3, 10.0);
        Polynomial4 f;
        f.c[0] = signed_mag(1e-6, 1.0);
        f.c[1] = signed_mag(1e-4, 20.0);
        f.c[2] = unit(rng) < 0.1 ? 0.0 : signed_mag(1e-3, 5.0);
        tally.check(n, f, horizon, first_contact_time(f, horizon));
    }
    CHECK(tally.failures == 0);
    CHECK(tally.compared > kCases / 4);
}
