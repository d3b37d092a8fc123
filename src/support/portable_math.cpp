// Range reduction to a small interval, then a Taylor or arctanh series evaluated by Horner's
// rule. Series rather than minimax polynomials: their coefficients are plain reciprocals that
// anyone can check, at the cost of a few more terms. Every constant is a double literal or a
// quotient of two that the compiler folds with correct rounding.

#include "portable_math.hpp"
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace termpool::portable {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ln 2 as a 32-bit head (k * ln2_hi is exact for |k| < 2^21) and the rest.
constexpr double ln2_hi = 0.6931471803691238;
constexpr double ln2_lo = 1.9082149292705877e-10;
constexpr double inv_ln2 = 1.4426950408889634;

// pi/2 in three 33-bit parts (Cody and Waite): k * part is exact for |k| < 2^20.
constexpr double pio2_1 = 1.5707963267341256;
constexpr double pio2_2 = 6.077100506303966e-11;
constexpr double pio2_3 = 2.0222662487959506e-21;
constexpr double two_over_pi = 0.6366197723675814;

// pi, pi/2 and pi/6 as the nearest double and the rest.
constexpr double pi_hi = 3.141592653589793;
constexpr double pi_lo = 1.2246467991473532e-16;
constexpr double pio2_hi = 1.5707963267948966;
constexpr double pio2_lo = 6.123233995736766e-17;
// atan(1/2) and atan(1) = pi/4, head and tail.
constexpr double atan_half_hi = 0.4636476090008061;
constexpr double atan_half_lo = 2.2698777452961687e-17;
constexpr double atan_one_hi = 0.7853981633974483;
constexpr double atan_one_lo = 3.061616997868383e-17;
constexpr double pi_over_180 = 0.017453292519943295;

// 2^k, for the exponents of normal numbers (-1022 <= k <= 1023), from its bits.
double power_of_two(int k) {
    return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

// y 2^k for y in [1/2, 2): std::scalbn's result, which is exact where it is a normal number and
// there a product with 2^k is the same, without the call into the C library.
double scaled(double y, int k) {
    return k > -1021 && k < 1023 ? y * power_of_two(k) : std::scalbn(y, k);
}

// An integer-valued k as by_quadrant takes it (which looks only at its residue modulo 4): k
// itself, cast, where it is well within a long long; beyond, its exact remainder by fmod.
long long quarter_turns(double k) {
    return static_cast<long long>(std::fabs(k) < 0x1p52 ? k : std::fmod(k, 4.0));
}

// The nearest integer of x (halves away from zero), as a double; |x| < 2^52.
double nearest_integer(double x) {
    return x >= 0 ? std::floor(x + 0.5) : -std::floor(0.5 - x);
}

// e^r - 1 for |r| <= ln2/2: sum of r^n/n! for n = 1..15 (the next term is below 2^-60 r).
double expm1_kernel(double r) {
    double p = 1.0 / 1307674368000; // 1/15!
    p = 1.0 / 87178291200 + r * p;
    p = 1.0 / 6227020800 + r * p;
    p = 1.0 / 479001600 + r * p;
    p = 1.0 / 39916800 + r * p;
    p = 1.0 / 3628800 + r * p;
    p = 1.0 / 362880 + r * p;
    p = 1.0 / 40320 + r * p;
    p = 1.0 / 5040 + r * p;
    p = 1.0 / 720 + r * p;
    p = 1.0 / 120 + r * p;
    p = 1.0 / 24 + r * p;
    p = 1.0 / 6 + r * p;
    p = 0.5 + r * p;
    return r + (r * r) * p;
}

// x = k ln2 + r with |r| <= ln2/2 (slightly more after rounding).
struct Reduced {
    double r;
    int k;
};
Reduced reduce_ln2(double x) {
    const double k = nearest_integer(x * inv_ln2);
    return {(x - k * ln2_hi) - k * ln2_lo, static_cast<int>(k)};
}

// sin r and cos r for |r| <= pi/4 (a little more after rounding): Taylor series to r^19 and
// r^20, whose next terms are below 2^-60.
double sin_kernel(double r) {
    const double z = r * r;
    double p = -1.0 / 121645100408832000; // -1/19!
    p = 1.0 / 355687428096000 + z * p;
    p = -1.0 / 1307674368000 + z * p;
    p = 1.0 / 6227020800 + z * p;
    p = -1.0 / 39916800 + z * p;
    p = 1.0 / 362880 + z * p;
    p = -1.0 / 5040 + z * p;
    p = 1.0 / 120 + z * p;
    p = -1.0 / 6 + z * p;
    return r + (r * z) * p;
}
double cos_kernel(double r) {
    const double z = r * r;
    double p = 1.0 / 2432902008176640000; // 1/20!
    p = -1.0 / 6402373705728000 + z * p;
    p = 1.0 / 20922789888000 + z * p;
    p = -1.0 / 87178291200 + z * p;
    p = 1.0 / 479001600 + z * p;
    p = -1.0 / 3628800 + z * p;
    p = 1.0 / 40320 + z * p;
    p = -1.0 / 720 + z * p;
    p = 1.0 / 24 + z * p;
    // 1 - z/2 loses the most; written so that its rounding is the last but one.
    return (1.0 - 0.5 * z) + (z * z) * p;
}

// sin and cos of r + k pi/2.
SinCos by_quadrant(double r, long long k) {
    const double s = sin_kernel(r), c = cos_kernel(r);
    switch (k & 3) {
    case 0:
        return {s, c};
    case 1:
        return {c, -s};
    case 2:
        return {-s, -c};
    default:
        return {-c, s};
    }
}

// x = r + k pi/2 with |r| <= pi/4 (a little more after rounding), x finite.
struct Quadrant {
    double r;
    long long k;
};
Quadrant reduce_pio2(double x) {
    const double k = nearest_integer(x * two_over_pi);
    return {((x - k * pio2_1) - k * pio2_2) - k * pio2_3, quarter_turns(k)};
}

// The series' coefficients (-1)^(i+1) / (2i + 3) for i = 0..28 (-1/3, 1/5, ... 1/59), worked out
// by the compiler: divided at run time, they cost as much as the rest of the function. The last,
// for t^61, is -1/61: the series' own sign is +, but the loop these replaced began from -1/61,
// and a term below 2^-60 t still moves a result's last bit now and then; kept, for those bits.
constexpr std::array<double, 30> atan_series = [] {
    std::array<double, 30> c{};
    for (int i = 0; i < 29; ++i)
        c[static_cast<std::size_t>(i)] = (i % 2 == 0 ? -1.0 : 1.0) / (2 * i + 3);
    c[29] = -1.0 / 61;
    return c;
}();
// atan t for |t| <= 7/16: t - t^3/3 + t^5/5 - ... to t^61 (t^2 <= 0.19, so the next term is
// below 2^-60 t).
double atan_kernel(double t) {
    const double z = t * t;
    double p = atan_series[29];
    for (std::size_t i = 29; i-- > 0;)
        p = atan_series[i] + z * p;
    return t + (t * z) * p;
}

// The series' coefficients 2 / (2i + 3) for i = 0..11 (2/3 up to 2/25), worked out by the
// compiler, as atan's are.
constexpr std::array<double, 12> log_series = [] {
    std::array<double, 12> c{};
    for (int i = 0; i < 12; ++i)
        c[static_cast<std::size_t>(i)] = 2.0 / (2 * i + 3);
    return c;
}();

} // namespace

double exp(double x) {
    if (std::isnan(x))
        return x;
    if (x > 709.782712893384)
        return infinity;
    if (x < -745.1332191019412)
        return 0;
    const Reduced red = reduce_ln2(x);
    return scaled(1.0 + expm1_kernel(red.r), red.k);
}

double expm1(double x) {
    if (std::isnan(x))
        return x;
    if (x > 709.782712893384)
        return infinity;
    if (x < -40)
        return -1;                           // e^x is below 2^-57: -1 is the nearest double
    if (std::fabs(x) <= 0.34657359027997264) // ln2 / 2
        return expm1_kernel(x);
    const Reduced red = reduce_ln2(x);
    if (red.k > 56)
        return scaled(1.0 + expm1_kernel(red.r), red.k);
    // 2^k (e^r - 1) + (2^k - 1): both terms exact, one rounding in the sum. (Here x >= -40, so
    // k >= -58.)
    const double two_k = power_of_two(red.k);
    return two_k * expm1_kernel(red.r) + (two_k - 1.0);
}

double log(double x) {
    if (std::isnan(x) || x < 0)
        return nan;
    if (x == 0)
        return -infinity;
    if (x == infinity)
        return x;
    // x = 2^e m with m in [sqrt(1/2), sqrt(2)); then log m = 2 atanh(s), s = (m-1)/(m+1).
    // The exponent and the significand from the bits of a normal x (what ilogb and scalbn give,
    // exactly), through the C library for a subnormal one.
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    const int biased = static_cast<int>(bits >> 52);
    int e = biased != 0 ? biased - 1023 : std::ilogb(x);
    double m = biased != 0 ? std::bit_cast<double>((bits & 0x000fffffffffffff) | 0x3ff0000000000000)
                           : std::scalbn(x, -e);
    if (m > 1.4142135623730951) {
        m *= 0.5;
        ++e;
    }
    const double f = m - 1.0; // exact (Sterbenz)
    const double s = f / (2.0 + f);
    const double z = s * s;
    // log m = 2 atanh(s) = 2s + s R with R = 2z/3 + 2z^2/5 + ... (z <= 0.0295, so the terms
    // past z^12 are below 2^-60), and 2s = f - s f, so log m = f - s (f - R): f is exact and the
    // rounded part is the small one.
    double p = log_series[11];
    for (std::size_t i = 11; i-- > 0;)
        p = log_series[i] + z * p;
    const double R = z * p;
    const double log_m = f - s * (f - R);
    const double k = e;
    return k * ln2_hi + (log_m + k * ln2_lo);
}

double log1p(double x) {
    if (std::isnan(x) || x < -1)
        return nan;
    if (x == -1)
        return -infinity;
    const double u = 1.0 + x;
    if (u == 1.0)
        return x; // |x| below half an ulp of 1: log(1 + x) = x to round-off
    if (u == infinity)
        return u;
    // log(u) (x / (u - 1)) corrects for the rounding of 1 + x (Goldberg 1991).
    return log(u) * (x / (u - 1.0));
}

namespace {

// sin of r + k pi/2 from the one series it needs (by_quadrant works out both): cos x is the sin
// of the next quadrant.
double sin_by_quadrant(double r, long long k) {
    switch (k & 3) {
    case 0:
        return sin_kernel(r);
    case 1:
        return cos_kernel(r);
    case 2:
        return -sin_kernel(r);
    default:
        return -cos_kernel(r);
    }
}

} // namespace

double sin(double x) {
    if (!std::isfinite(x))
        return nan;
    const Quadrant q = reduce_pio2(x);
    return sin_by_quadrant(q.r, q.k);
}

double cos(double x) {
    if (!std::isfinite(x))
        return nan;
    const Quadrant q = reduce_pio2(x);
    return sin_by_quadrant(q.r, q.k + 1);
}

SinCos sin_cos_degrees(double degrees) {
    if (!std::isfinite(degrees))
        return {nan, nan};
    // Whole turns first, by fmod, which is exact: any finite angle, 1e20 degrees too, points
    // where its exact remainder does (the quarter turns alone lose it once 90 k rounds, past
    // about 10^16 degrees). Below a turn fmod would return the angle itself (it is not called), and
    // up to 10^15 degrees the quarter turns alone were exact already: those angles keep their bits
    // (issue 28, tests/test_portable_math.cpp).
    const double turn = std::fabs(degrees) < 360 ? degrees : std::fmod(degrees, 360.0);
    const double k = nearest_integer(turn / 90);
    const double r = (turn - 90 * k) * pi_over_180;
    return by_quadrant(r, quarter_turns(k));
}

namespace {

// atan a for 0 <= a <= 1: atan a = atan c + atan((a - c) / (1 + a c)) around c = 1/2 and 1,
// where a - c is exact, and atan c is kept as head and tail.
double atan_unit(double a) {
    if (a <= 7.0 / 16)
        return atan_kernel(a);
    if (a <= 11.0 / 16)
        return atan_half_hi + (atan_kernel((a - 0.5) / (1.0 + 0.5 * a)) + atan_half_lo);
    return atan_one_hi + (atan_kernel((a - 1.0) / (a + 1.0)) + atan_one_lo);
}

// atan(num / den) for num, den >= 0, not both 0 or infinite, with one rounded division:
// beyond 1 it is pi/2 - atan(den / num).
double atan_of_ratio(double num, double den) {
    if (num > den)
        return pio2_hi - (atan_unit(den / num) - pio2_lo);
    return atan_unit(num / den);
}

} // namespace

double atan(double x) {
    if (std::isnan(x))
        return x;
    const double angle = atan_of_ratio(std::fabs(x), 1.0);
    return x < 0 ? -angle : angle;
}

double atan2(double y, double x) {
    if (std::isnan(x) || std::isnan(y))
        return nan;
    const bool y_negative = std::signbit(y);
    const double pi_signed = y_negative ? -pi_hi : pi_hi;
    if (y == 0) {
        if (std::signbit(x))
            return pi_signed;
        return y; // +-0
    }
    if (x == 0)
        return y_negative ? -pio2_hi : pio2_hi;
    if (std::isinf(x) && std::isinf(y)) {
        const double angle = x > 0 ? atan_one_hi : 3 * atan_one_hi;
        return y_negative ? -angle : angle;
    }
    const double t = atan_of_ratio(std::fabs(y), std::fabs(x));
    const double angle = x > 0 ? t : pi_hi - (t - pi_lo);
    return y_negative ? -angle : angle;
}

} // namespace termpool::portable
