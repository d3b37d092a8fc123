#pragma once
/// \file
/// The transcendental functions of the simulator, the rules and the computer player, computed
/// with IEEE-754 additions, multiplications, divisions and square roots only (each correctly
/// rounded on every conforming machine), in a fixed order. Built with -ffp-contract=off they
/// give the same bits everywhere, which the C library's exp, sin or atan2 do not promise: a
/// saved game replays the same on every machine and build.
///
/// Each is within a few units in the last place of the true value for the arguments termpool
/// uses (tests/test_portable_math.cpp measures the bound against the C library); none sets
/// errno or raises flags on purpose.

namespace termpool::portable {

/// e^x. Overflows to +inf above 709.78, 0 below -745.13; NaN gives NaN.
double exp(double x);

/// e^x - 1, accurate near 0 where exp(x) - 1 is not.
double expm1(double x);

/// Natural logarithm; -inf at 0, NaN below 0 and for NaN, +inf at +inf.
double log(double x);

/// log(1 + x), accurate near 0; -inf at -1, NaN below.
double log1p(double x);

/// Sine of `x` radians. The argument is reduced by pi/2 in three parts, exact for |x| up to
/// about 10^6; beyond, less accurate than the C library but still the same everywhere.
double sin(double x);

/// Cosine of `x` radians (the same reduction as `sin`).
double cos(double x);

/// Sine and cosine of `degrees`, reduced exactly by whole turns (fmod) and then by quarter
/// turns in degrees, so that multiples of 90 degrees give exactly 0 and +-1 and any finite
/// angle, however large, gives the sine and cosine of its exact remainder modulo 360. NaN for
/// a non-finite angle.
struct SinCos {
    double sin; ///< sine
    double cos; ///< cosine
};
/// \copydoc SinCos
SinCos sin_cos_degrees(double degrees);

/// Arc tangent, in (-pi/2, pi/2).
double atan(double x);

/// Angle of the point (x, y) from the x axis, in [-pi, pi], with the C library's conventions
/// for zeros (atan2(+-0, -0) = +-pi, atan2(+-0, +0) = +-0) and infinities.
double atan2(double y, double x);

} // namespace termpool::portable
