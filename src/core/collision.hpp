#pragma once
// What a contact does to the balls' velocities and spins.

#include <termpool/ball.hpp>
#include <termpool/params.hpp>

namespace termpool::core {

/// Relative normal speed two balls (or a ball and a cushion) leave a contact with at least, m/s.
/// It keeps a pair that rounding left touching from being found in contact again at once.
inline constexpr double min_separation_speed = 1e-6;

/// Speed at which two balls that pushed each other part, m/s (see resolve_ball_ball).
inline constexpr double push_parting_speed = 0.001;

/// Resolves a contact between two touching balls; `a` and `b` get their new velocities and spins
/// (the motion states are settled afterwards by the caller).
void resolve_ball_ball(Ball& a, Ball& b, const PhysicsParams& params);

/// Resolves a contact of a ball with a cushion or jaw. `towards_cushion` is the unit vector in the
/// table plane from the ball's centre to the contact.
void resolve_cushion(Ball& ball, Vec2 towards_cushion, const PhysicsParams& params);

} // namespace termpool::core
