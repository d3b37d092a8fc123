// The project's own transcendental functions (src/core/portable_math.cpp) against the C
// library's, in units in the last place, over the ranges termpool uses and beyond; and the
// values that must be exact; and their bits, pinned over every binade.
#include "support/portable_math.hpp"
#include "support/random.hpp"
#include "support/state_digest.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace portable = termpool::portable;

namespace {

// Distance of a from b in units in the last place of b (b's ulp; 0 when both are equal).
double ulps(double a, double b) {
    if (a == b)
        return 0;
    const double ulp =
        std::nextafter(std::fabs(b), std::numeric_limits<double>::infinity()) - std::fabs(b);
    return std::fabs(a - b) / ulp;
}

// Largest error over `n` arguments drawn uniformly from [lo, hi].
template <class Ours, class Theirs>
double worst_ulps(Ours ours, Theirs theirs, double lo, double hi, int n = 200000) {
    termpool::Random rng(7);
    double worst = 0;
    for (int i = 0; i < n; ++i) {
        const double x = lo + (hi - lo) * rng.uniform();
        worst = std::max(worst, ulps(ours(x), theirs(x)));
    }
    return worst;
}

constexpr double bound = 2.0; // ulps; the C library's own error is part of what is measured

} // namespace

TEST_CASE("portable exp, expm1, log and log1p are within 2 ulp of the C library",
          "[portable-math]") {
    auto e = [](double x) { return portable::exp(x); };
    auto em1 = [](double x) { return portable::expm1(x); };
    auto l = [](double x) { return portable::log(x); };
    auto l1p = [](double x) { return portable::log1p(x); };
    auto std_exp = [](double x) { return std::exp(x); };
    auto std_expm1 = [](double x) { return std::expm1(x); };
    auto std_log = [](double x) { return std::log(x); };
    auto std_log1p = [](double x) { return std::log1p(x); };
    CHECK(worst_ulps(e, std_exp, -30, 30) <= bound);
    CHECK(worst_ulps(e, std_exp, -700, 700) <= bound);
    CHECK(worst_ulps(em1, std_expm1, -1, 1) <= bound);
    CHECK(worst_ulps(em1, std_expm1, -1e-6, 1e-6) <= bound);
    CHECK(worst_ulps(em1, std_expm1, -40, 40) <= bound);
    CHECK(worst_ulps(l, std_log, 1e-6, 10) <= bound);
    CHECK(worst_ulps(l, std_log, 0.5, 2) <= bound);
    CHECK(worst_ulps(l, std_log, 1, 1e300) <= bound);
    CHECK(worst_ulps(l1p, std_log1p, -0.999, 1) <= bound);
    CHECK(worst_ulps(l1p, std_log1p, -1e-8, 1e-8) <= bound);
}

TEST_CASE("portable sin, cos, atan and atan2 are within 2 ulp of the C library",
          "[portable-math]") {
    auto s = [](double x) { return portable::sin(x); };
    auto c = [](double x) { return portable::cos(x); };
    auto a = [](double x) { return portable::atan(x); };
    auto std_sin = [](double x) { return std::sin(x); };
    auto std_cos = [](double x) { return std::cos(x); };
    auto std_atan = [](double x) { return std::atan(x); };
    CHECK(worst_ulps(s, std_sin, -7, 7) <= bound);
    CHECK(worst_ulps(c, std_cos, -7, 7) <= bound);
    CHECK(worst_ulps(s, std_sin, -1e-3, 1e-3) <= bound);
    CHECK(worst_ulps(s, std_sin, -1000, 1000) <= bound);
    CHECK(worst_ulps(c, std_cos, -1000, 1000) <= bound);
    CHECK(worst_ulps(a, std_atan, -3, 3) <= bound);
    CHECK(worst_ulps(a, std_atan, -1e6, 1e6) <= bound);
    termpool::Random rng(3);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const double y = 2 * rng.uniform() - 1, x = 2 * rng.uniform() - 1;
        worst = std::max(worst, ulps(portable::atan2(y, x), std::atan2(y, x)));
    }
    CHECK(worst <= bound);
}

TEST_CASE("portable functions give exact values where the maths is exact", "[portable-math]") {
    CHECK(portable::exp(0) == 1);
    CHECK(portable::expm1(0) == 0);
    CHECK(portable::log(1) == 0);
    CHECK(portable::log1p(0) == 0);
    CHECK(portable::sin(0) == 0);
    CHECK(portable::cos(0) == 1);
    CHECK(portable::atan(0) == 0);
    for (int quarter = -8; quarter <= 8; ++quarter) {
        const portable::SinCos sc = portable::sin_cos_degrees(90.0 * quarter);
        const int q = ((quarter % 4) + 4) % 4;
        CHECK(sc.sin == (q == 1 ? 1.0 : q == 3 ? -1.0 : 0.0));
        CHECK(sc.cos == (q == 0 ? 1.0 : q == 2 ? -1.0 : 0.0));
    }
    CHECK(portable::atan2(0.0, -1.0) == std::atan2(0.0, -1.0));
    CHECK(portable::atan2(-0.0, -1.0) == std::atan2(-0.0, -1.0));
    CHECK(portable::atan2(1.0, 0.0) == std::atan2(1.0, 0.0));
    CHECK(std::signbit(portable::atan2(-0.0, 1.0)));
}

TEST_CASE("portable functions handle the edges as the C library does", "[portable-math]") {
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(portable::exp(1000) == inf);
    CHECK(portable::exp(-1000) == 0);
    CHECK(portable::expm1(-1000) == -1);
    CHECK(portable::log(0) == -inf);
    CHECK(std::isnan(portable::log(-1)));
    CHECK(portable::log(inf) == inf);
    CHECK(portable::log1p(-1) == -inf);
    CHECK(std::isnan(portable::sin(inf)));
    CHECK(portable::atan(inf) == std::atan(inf));
    CHECK(portable::atan2(inf, inf) == std::atan2(inf, inf));
    CHECK(portable::atan2(-inf, -inf) == std::atan2(-inf, -inf));
    CHECK(ulps(portable::exp(-740), std::exp(-740)) <= bound); // subnormal
    CHECK(ulps(portable::log(5e-324), std::log(5e-324)) <= bound);
}

TEST_CASE("sin_cos_degrees agrees with sin and cos of the angle in radians", "[portable-math]") {
    termpool::Random rng(5);
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        const double deg = 720 * rng.uniform() - 360;
        const portable::SinCos sc = portable::sin_cos_degrees(deg);
        const double rad = deg * (M_PI / 180);
        worst =
            std::max({worst, std::fabs(sc.sin - std::sin(rad)), std::fabs(sc.cos - std::cos(rad))});
    }
    CHECK(worst < 1e-15);
}

namespace {

// The digest of sin_cos_degrees over angles within +-10^6 degrees, quarter-turn boundaries and
// their neighbours included: what issue 28's whole-turn reduction must leave alone.
std::uint64_t digest_of_moderate_angles() {
    termpool::StateDigest d;
    const auto add = [&](double deg) {
        const portable::SinCos sc = portable::sin_cos_degrees(deg);
        d.add(sc.sin);
        d.add(sc.cos);
    };
    termpool::Random rng(28);
    for (int i = 0; i < 200000; ++i)
        add(rng.uniform(-720, 720));
    for (int i = 0; i < 200000; ++i)
        add(rng.uniform(-1e6, 1e6));
    for (int eighth = -20000; eighth <= 20000; ++eighth) {
        double up = 45.0 * eighth, down = up;
        for (int step = 0; step < 4; ++step) {
            add(up);
            add(down);
            up = std::nextafter(up, HUGE_VAL);
            down = std::nextafter(down, -HUGE_VAL);
        }
    }
    return d.value();
}

} // namespace

TEST_CASE("sin_cos_degrees gives moderate angles the bits it gave before issue 28",
          "[portable-math]") {
    CHECK(termpool::digest_hex(digest_of_moderate_angles()) == "32ac89a0f925e0e2");
}

TEST_CASE("sin_cos_degrees of any finite angle is that of its exact remainder modulo 360",
          "[portable-math]") {
    // Issue 28: 1e20 degrees gave 0 degrees; it is 360 k + 280 exactly.
    const auto same = [](double a, double b) {
        const portable::SinCos x = portable::sin_cos_degrees(a), y = portable::sin_cos_degrees(b);
        return std::memcmp(&x.sin, &y.sin, sizeof x.sin) == 0 &&
               std::memcmp(&x.cos, &y.cos, sizeof x.cos) == 0;
    };
    CHECK(same(1e20, 280));
    CHECK(same(-1e20, -280));
    CHECK(same(1e300, std::fmod(1e300, 360.0)));
    CHECK(same(std::numeric_limits<double>::max(),
               std::fmod(std::numeric_limits<double>::max(), 360.0)));
    const portable::SinCos huge = portable::sin_cos_degrees(1e20);
    CHECK(std::fabs(huge.cos - std::cos(280 * M_PI / 180)) < 1e-15);
    CHECK(std::fabs(huge.sin - std::sin(280 * M_PI / 180)) < 1e-15);
    // 360 k + a is a double exactly for these k and a (a has two bits after the point, and
    // 360 k + a stays below 2^51).
    for (const double k : {1.0, 7.0, 1024.0, 1e6, 0x1p30, 0x1p42})
        for (const double a : {0.0, 0.25, 37.25, 45.0, 89.75, 90.0, 135.5, 280.0, 359.75}) {
            INFO(k << " turns and " << a);
            CHECK(same(360 * k + a, a));
            CHECK(same(-(360 * k + a), -a));
        }
    // A negative angle points where the positive remainder does.
    const portable::SinCos minus = portable::sin_cos_degrees(-80),
                           plus = portable::sin_cos_degrees(280);
    CHECK(std::fabs(minus.sin - plus.sin) < 1e-16);
    CHECK(std::fabs(minus.cos - plus.cos) < 1e-16);
    CHECK(std::isnan(portable::sin_cos_degrees(std::numeric_limits<double>::infinity()).sin));
    CHECK(std::isnan(portable::sin_cos_degrees(-std::numeric_limits<double>::infinity()).cos));
    CHECK(std::isnan(portable::sin_cos_degrees(std::numeric_limits<double>::quiet_NaN()).sin));
}

namespace {

// The digest of exp, expm1, log, log1p, sin, cos and sin_cos_degrees over arguments from every
// binade, subnormal to the largest, of both signs, and over the ranges the simulator uses.
std::uint64_t digest_of_every_binade() {
    termpool::StateDigest d;
    const auto add = [&](double x) {
        d.add(portable::exp(x));
        d.add(portable::expm1(x));
        d.add(portable::log(x));
        d.add(portable::log1p(x));
        d.add(portable::sin(x));
        d.add(portable::cos(x));
        const portable::SinCos sc = portable::sin_cos_degrees(x);
        d.add(sc.sin);
        d.add(sc.cos);
    };
    termpool::Random rng(27);
    for (int i = 0; i < 100000; ++i) {
        const int binade = static_cast<int>(rng.below(2098)) - 1074;
        const double x = std::ldexp(rng.uniform(1, 2), binade);
        add(x);
        add(-x);
    }
    for (int i = 0; i < 100000; ++i)
        add(rng.uniform(-800, 800));
    return d.value();
}

// The same for atan and atan2 (and for sin and cos again, each on its own since they work out
// only the series their quadrant needs).
std::uint64_t atan_digest_of_every_binade() {
    termpool::StateDigest d;
    termpool::Random rng(28);
    for (int i = 0; i < 100000; ++i) {
        const int binade = static_cast<int>(rng.below(2098)) - 1074;
        const double x = std::ldexp(rng.uniform(1, 2), binade);
        const double y = std::ldexp(rng.uniform(1, 2), static_cast<int>(rng.below(64)) - 32);
        for (const double v : {x, -x}) {
            d.add(portable::atan(v));
            d.add(portable::atan2(v, y));
            d.add(portable::atan2(y, v));
            d.add(portable::sin(v));
            d.add(portable::cos(v));
        }
    }
    return d.value();
}

} // namespace

TEST_CASE("portable atan, atan2, sin and cos give the bits they gave before their series tables",
          "[portable-math]") {
    // Issue 27: atan's and log's series read their coefficients from tables the compiler works
    // out rather than divide in the loop, and sin and cos alone work out one series: the same
    // bits (the digest was taken with the code before).
    CHECK(termpool::digest_hex(atan_digest_of_every_binade()) == "a51b0811d16d6452");
    // Two of the few arguments (about 4 in 10^8 near 0.43) whose last bit the series' last
    // term moves: its coefficient is the loop's -1/61, not the series' +1/61.
    CHECK(portable::atan(0x1.bc132fb01c5adp-2) == 0x1.a3025a3155ec4p-2);
    CHECK(portable::atan2(0x1.bc132fb01c5adp-2, 1.0) == 0x1.a3025a3155ec4p-2);
    CHECK(portable::atan(0x1.ba5a12e4b0a8ap-2) == 0x1.a18ed6a8fa1c6p-2);
}

TEST_CASE("portable functions give the bits they gave with the C library's scalbn, ilogb and "
          "fmod",
          "[portable-math]") {
    // Issue 27: those calls became bit operations where the result is a normal number and a
    // cast where a quarter turn fits a long long (exact in both, so the bits must not move);
    // the digest was taken with the calls.
    CHECK(termpool::digest_hex(digest_of_every_binade()) == "c87995b4c47765ac");
}
