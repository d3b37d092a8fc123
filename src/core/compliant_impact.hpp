#pragma once
// Stronge's compliant frictional impact of a sphere on a rigid surface (W. J. Stronge, "Impact
// Mechanics", Cambridge University Press, 2000: impact with discrete normal and tangential
// compliance): the stronge cushion.

namespace termpool::core {

/// The contact point's velocity when a compliant impact ends, in units of the normal approach
/// speed V.
struct CompliantImpact {
    double tangential; ///< along the initial slip (negative: the slip reversed)
    double normal;     ///< along the normal, away from the surface: e
};

/// The end of a collinear compliant impact with friction. The contact has a normal spring (stiff
/// k_n while it compresses, k_n / e^2 while it restitutes, so the normal velocity ends at e V)
/// and a tangential spring whose foot sticks to the surface until the spring's force reaches
/// mu times the normal force, then slips. The ball vibrates on them at w_n and w_t (normal and
/// tangential), `frequency_ratio` = w_t / w_n, between 1 and 2 (both excluded).
///
/// `slip` is the tangential speed of the contact point at first touch over V (>= 0), `friction`
/// mu (>= 0), `restitution` e (0 to 1), `inertia_ratio` beta_t / beta_n (3.5 for a solid
/// sphere: a tangential impulse P changes the contact point's velocity by 3.5 P / m, a normal one
/// by P / m). Slip and stick phases follow in their closed forms (the slip-to-stick instants from
/// an arc cosine); a stick ends where the spring force reaches the friction limit, an instant
/// with no closed form, found by bisection to the last bit.
CompliantImpact compliant_impact(double slip, double friction, double restitution,
                                 double frequency_ratio, double inertia_ratio);

} // namespace termpool::core
