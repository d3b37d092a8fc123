#pragma once
// The physical cloth model: a ball slides (friction against the slip of its contact point),
// rolls (rolling resistance) or spins in place, and its centre moves on a parabola between
// events. What other files need of it besides its ClothModel (physical_cloth()).

#include <termpool/ball.hpp>
#include <termpool/params.hpp>

namespace termpool::core {

/// Velocity of the ball's contact point with the cloth (the slip), m/s.
Vec2 slip_velocity(const Ball& ball, double radius);

/// Constant acceleration of the centre during the ball's current motion state.
Vec2 physical_acceleration(const Ball& ball, const PhysicsParams& params);

/// Puts a ball whose velocities were just changed (strike, collision) into the motion state that
/// matches them: rolling when there is no slip, spinning or stationary when it does not move.
void physical_settle_motion_state(Ball& ball, const PhysicsParams& params);

} // namespace termpool::core
