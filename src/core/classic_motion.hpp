#pragma once
// The classic cloth laws (the seed report's) as constants: a ball moves on a straight line, its
// speed decaying at rate K while K v > A, then falling at A. The decay law is the case A = 0, the
// constant law K = 0. The contact searches split a ball's motion into its phases, in each of which
// the centre is a closed form the polynomial solvers handle.

#include "../support/portable_math.hpp"
#include <cmath>
#include <limits>
#include <termpool/vec.hpp>

namespace termpool::core {

/// A classic law's constants.
struct ClassicLaw {
    double decay_rate = 0;   ///< K, 1/s; 0 for the constant law
    double deceleration = 0; ///< A, m/s^2; 0 for the decay law
};

/// The part of its law a moving classic ball is in.
enum class ClassicPhase {
    decaying,     ///< v' = -K v: x(t) = x0 + v0 (1 - e^(-K t)) / K
    decelerating, ///< v' = -A v/|v|: x(t) = x0 + v0 t - A v0/|v0| t^2 / 2
};

/// The phase of a ball moving at `speed`, m/s: decaying while the decay slows it more than A.
inline ClassicPhase classic_phase(double speed, const ClassicLaw& law) {
    return law.decay_rate > 0 && speed > law.deceleration / law.decay_rate
               ? ClassicPhase::decaying
               : ClassicPhase::decelerating;
}

/// Seconds until a ball moving at `speed` leaves the decaying phase (0 when it is not in it,
/// +infinity when the law has no other phase).
inline double classic_switch_time(double speed, const ClassicLaw& law) {
    if (classic_phase(speed, law) != ClassicPhase::decaying)
        return 0;
    if (law.deceleration <= 0)
        return std::numeric_limits<double>::infinity();
    const double K = law.decay_rate;
    return portable::log(speed / (law.deceleration / K)) / K;
}

/// The centre's acceleration of a ball moving at `velocity` under `law`, m/s^2.
inline Vec2 classic_acceleration(Vec2 velocity, const ClassicLaw& law) {
    const double speed = length(velocity);
    if (speed == 0)
        return {};
    if (classic_phase(speed, law) == ClassicPhase::decaying)
        return velocity * -law.decay_rate;
    return velocity * (-law.deceleration / speed);
}

} // namespace termpool::core
