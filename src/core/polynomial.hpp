#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace termpool::core {

/// Polynomial of degree <= 4 in t: c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4.
/// Used as the "gap" function between two moving objects (positive = apart); any leading
/// coefficients may be zero, so the same type carries degree 0..4.
struct Polynomial4 {
    /// Coefficients in ascending powers of t (c[k] multiplies t^k).
    std::array<double, 5> c{};

    /// Value at t (Horner's scheme).
    [[nodiscard]] constexpr double evaluate(double t) const noexcept {
        return (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0];
    }

    /// First derivative d/dt at t.
    [[nodiscard]] constexpr double derivative(double t) const noexcept {
        return ((4.0 * c[4] * t + 3.0 * c[3]) * t + 2.0 * c[2]) * t + c[1];
    }

    /// Second derivative d^2/dt^2 at t.
    [[nodiscard]] constexpr double second_derivative(double t) const noexcept {
        return (12.0 * c[4] * t + 6.0 * c[3]) * t + 2.0 * c[2];
    }

    /// Coefficients of the first derivative, as a polynomial of degree <= 3 (c[4] == 0).
    [[nodiscard]] constexpr Polynomial4 derivative_polynomial() const noexcept {
        return Polynomial4{{c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0}};
    }
};

/// Roots of a quadratic a t^2 + b t + c in ascending order (0, 1 or 2), numerically stable.
///
/// Writes the real roots to roots[0..n) in ascending order and returns n. Degenerates are
/// handled: a == 0 gives the linear root -c/b (n = 1), a == b == 0 gives n = 0 (also for the
/// all-zero polynomial, whose "every t is a root" has no finite answer). A double root (zero
/// discriminant) is reported once (n = 1). The discriminant is computed with an error-free
/// product when b^2 and 4ac nearly cancel, so near-tangent cases are decided from the exact
/// coefficients rather than from rounding noise; coefficients are rescaled by a power of two
/// when huge or tiny so b^2 cannot overflow or underflow. Coefficients must be finite.
int solve_quadratic(double a, double b, double c, double roots[2]) noexcept;

/// Earliest time t in [0, horizon] at which f(t) <= 0 while f is decreasing, i.e. the infimum of
/// S = { t in [0, horizon] : f(t) <= 0 and f'(t) < 0 }, or +infinity when S is empty.
///
/// f is a gap function (positive = apart), so this is the first moment two objects touch while
/// approaching. Conventions the caller can rely on:
/// - f(0) <= 0 and f decreasing at 0 (f'(0) < 0, or f'(0) == 0 with the first nonzero higher
///   derivative negative) returns exactly 0.0.
/// - A slight overlap that is opening (f(0) < 0, f'(0) > 0) is skipped; if f later turns down
///   while still <= 0 the turning point (local maximum) is returned, otherwise the next
///   descending root.
/// - Grazing contacts (f touches 0 with f' == 0 and does not go below) may return either the
///   touch time or +infinity; a time where f is clearly positive is never returned.
/// - A descending root is located to the precision f can be evaluated in double: the result t
///   satisfies |f(t)| <= about 8 eps * sum_k |c_k| t^k (the rounding level of Horner's scheme),
///   which is within a few ulps of the root when the crossing is well conditioned, and within
///   (that bound) / |f'(t)| in general. Either side of the root is possible at that level (f may
///   be a rounding-level negative); only when the bracket shrinks to adjacent doubles is the
///   side with f > 0 (just before contact) returned deliberately.
/// - Degenerate f (degree < 4, f == 0) is handled; f == 0 yields +infinity.
/// - horizon < 0 or NaN yields +infinity; horizon == +infinity searches all t >= 0.
///   Coefficients must be finite. No allocation, no recursion, bounded iteration count.
double first_contact_time(const Polynomial4& f, double horizon) noexcept;

/// Either the first contact time or, when settling it would take a full search, a lower bound
/// on it that costs almost nothing (see first_contact_estimate).
struct ContactEstimate {
    double time; ///< first_contact_time, or a time no later than it
    bool exact;  ///< true when `time` is first_contact_time itself
};

/// first_contact_time when cheap tests settle it, otherwise a lower bound on it. Over
/// [0, horizon] f stays above a quadratic (its cubic and quartic terms bounded by t^2 terms);
/// when that quadratic has no root there, there is no contact, and otherwise no contact comes
/// before its first root. A simulator can keep the bound and search only when it becomes the
/// earliest of all its events; most such contacts are overtaken by other events first.
// Inline: a break asks it about 700 times, and most calls end in its first few tests.
inline ContactEstimate first_contact_estimate(const Polynomial4& poly, double horizon) noexcept {
    const std::array<double, 5>& c = poly.c;
    const double H = horizon;
    // Only the common case takes the shortcut: apart now, a horizon in the range where
    // contact_time_in_range needs no rescaling, and a quartic (lines are solved in closed form
    // at once anyway).
    if (!(c[0] > 0.0 && H > 1e-30 && H < 1e30 && (c[3] != 0.0 || c[4] != 0.0)))
        return {first_contact_time(poly, horizon), true};
    // On [0, H], c3 t^3 >= min(0, c3) H t^2 and c4 t^4 >= min(0, c4) H^2 t^2, so f stays above
    // the quadratic q(t) = c0 + c1 t + q2 t^2, and nothing touches before q's first root.
    const double q2 = c[2] + std::min(0.0, c[3]) * H + std::min(0.0, c[4]) * H * H;
    const double b2 = c[1] * c[1];
    const double disc = b2 - 4.0 * q2 * c[0];
    // Near a double root of q its first root is ill-conditioned: then search at once.
    if (!(std::fabs(disc) > 1e-4 * b2))
        return {first_contact_time(poly, horizon), true};
    // No contact when q stays positive (disc < 0), has no positive root (c1 >= 0 with q convex:
    // the denominator of the stable form 2 c0 / (-c1 + sqrt(disc)) is then not positive), or
    // its first root is beyond the horizon. The three are one test rather than a branch after
    // each step: each is taken about as often as not, and a mispredicted branch costs more than
    // the square root and division done for nothing (GCC 12 still branches on the first before
    // the square root, and joins the other two). The square root of at least 0 never calls the
    // library for errno; a division by zero here is by a denominator the test refuses.
    const double root_den = std::sqrt(std::max(disc, 0.0)) - c[1];
    const double bound = 2.0 * c[0] / root_den;
    if ((disc < 0.0) | !(root_den > 0.0) | (bound > H))
        return {std::numeric_limits<double>::infinity(), true};
    // The margin covers the rounding of the bound, which the conditioning test keeps within a
    // few hundred eps.
    return {bound * (1.0 - 1e-12), false};
}

} // namespace termpool::core
