#include "cue_impact.hpp"

#include "../support/portable_math.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>

namespace termpool::core {
namespace {

// The cue's axis and two directions across it, for a cue at `elevation` (radians) aimed along
// the horizontal unit vector `aim`. The tip offsets are measured in the plane across the cue,
// as a player sighting along the cue sees the tip on the ball.
struct CueFrame {
    Vec3 along; // the way the cue moves: forward and, when raised, down
    Vec3 right; // horizontal, to the right seen from behind the cue ball
    Vec3 up;    // across the cue, upwards (tilted forwards when the cue is raised)
};

CueFrame cue_frame(Vec2 aim, double elevation_deg) {
    const portable::SinCos e = portable::sin_cos_degrees(elevation_deg);
    const double c = e.cos;
    const double s = e.sin;
    const Vec3 along{aim.x * c, aim.y * c, -s};
    const Vec3 right{aim.y, -aim.x, 0};
    return {along, right, cross(right, along)};
}

} // namespace

// Squirt (after Alciatore, "The Physics of Pocket Billiards", TP A.31). The tip meets the ball
// at p = R (a right + b up - s along), s = sqrt(1 - a^2 - b^2), and does not slip on it while
// they touch. Across the cue the tip carries only the shaft's effective end mass m_e, so the
// impulse J = J_c along + J_r right has a sideways part J_r, with -J_r / m_e the tip's
// sideways velocity. The ball's contact point moves at J / m + w x p with w = p x J / I and
// I = 2 m R^2 / 5; its sideways part is J_r / m + (R^2 J_r - (p . J)(p . right)) / I, and
// with p . J = R (a J_r - s J_c), p . right = R a this is
//     J_r / m + (5 / 2) ((1 - a^2) J_r + a s J_c) / m.
// Setting it equal to -J_r / m_e:
//     J_r / J_c = -(5/2) a s / (1 + m / m_e + (5/2)(1 - a^2)),
// which for b = 0 is TP A.31's tan(squirt) = (5/2)(b/R) sqrt(1 - (b/R)^2) /
// (1 + m / m_e + (5/2)(1 - (b/R)^2)) with its b/R our a. A massless end (m_e -> 0) has no
// sideways impulse: no squirt.
double squirt_ratio(double side, double follow, double ball_mass, double end_mass) {
    if (!(end_mass > 0))
        return 0;
    const double s = std::sqrt(std::max(0.0, 1.0 - side * side - follow * follow));
    return -2.5 * side * s / (1.0 + ball_mass / end_mass + 2.5 * (1.0 - side * side));
}

CueImpact cue_impact(const Strike& strike, double ball_mass, const PhysicsParams& params) {
    const CueFrame cue = cue_frame(unit_from_degrees(strike.angle_deg), strike.elevation_deg);
    const double a = strike.side;
    const double b = strike.follow;
    const double s = std::sqrt(std::max(0.0, 1.0 - a * a - b * b));
    const double r = params.ball_radius;
    const Vec3 contact = (cue.right * a + cue.up * b + cue.along * -s) * r;
    const double k = squirt_ratio(a, b, ball_mass, params.cue_end_mass);
    // `speed` is the speed the whole impulse gives a free ball, so that a level cue sends the
    // ball off at exactly that speed, squirt or not.
    const double along = strike.speed / std::sqrt(1.0 + k * k);
    const Vec3 velocity = cue.along * along + cue.right * (k * along);
    // w = p x J / I with J / m = velocity and I / m = 2 R^2 / 5.
    return {velocity, cross(contact, velocity) * (2.5 / (r * r))};
}

} // namespace termpool::core
