#include <numbers>
#include <termpool/simulator.hpp>

#include "core/motion.hpp"

namespace termpool {

Ball strike_cue_ball(const Ball& cue, const Strike& strike, const PhysicsParams& params) {
    Ball b = cue;
    const Vec2 direction = unit_from_angle(strike.angle_deg * std::numbers::pi / 180.0);
    b.velocity = direction * strike.speed;
    if (core::is_classic_friction(params)) {
        b.angular_velocity = {};
    } else {
        // Point impact: a tip offset of `o` R gives spin 5 v o / (2 R). Follow turns the ball
        // forward about the horizontal axis across the shot, right english clockwise from above.
        const double spin_per_offset = 5.0 * strike.speed / (2.0 * params.ball_radius);
        const Vec2 follow_axis = perpendicular(direction);
        b.angular_velocity =
            lift(follow_axis * (strike.follow * spin_per_offset), -strike.side * spin_per_offset);
    }
    b.state = MotionState::sliding;
    core::settle_motion_state(b, params);
    return b;
}

} // namespace termpool
