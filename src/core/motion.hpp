#pragma once
// Motion of a single ball between events, for every friction model.

#include <termpool/ball.hpp>
#include <termpool/params.hpp>

namespace termpool::core {

/// Velocity of the ball's contact point with the cloth (the slip), m/s.
Vec2 slip_velocity(const Ball& ball, double radius);

/// True when the friction model is a classic one, the seed report's (translation only, no spin).
inline bool is_classic_friction(const PhysicsParams& params) {
    return params.friction.kind != FrictionKind::physical;
}

/// Constant acceleration of the centre during the ball's current motion state (physical model).
Vec2 physical_acceleration(const Ball& ball, const PhysicsParams& params);

/// Seconds until the ball's motion state changes by itself (slide to roll, roll to stop, spin to
/// rest, or a classic model's stop), +infinity for a ball that never changes.
double time_to_transition(const Ball& ball, const PhysicsParams& params);

/// The ball `dt` seconds later, 0 <= dt <= time_to_transition; the motion state is unchanged.
Ball advance(const Ball& ball, double dt, const PhysicsParams& params);

/// The ball after its transition: `ball` must be the state at the transition time.
Ball apply_transition(const Ball& ball, const PhysicsParams& params);

/// Puts a ball whose velocities were just changed (strike, collision) into the motion state that
/// matches them: rolling when there is no slip, spinning or stationary when it does not move.
void settle_motion_state(Ball& ball, const PhysicsParams& params);

} // namespace termpool::core
