#include <numbers>
#include <termpool/simulator.hpp>

#include "cloth_model.hpp"

namespace termpool {

Ball strike_cue_ball(const Ball& cue, const Strike& strike, const PhysicsParams& params) {
    const core::ClothModel cloth = core::cloth_model(params.friction);
    Ball b = cue;
    const Vec2 direction = unit_from_angle(strike.angle_deg * std::numbers::pi / 180.0);
    b.velocity = direction * strike.speed;
    b.angular_velocity = cloth.tip_spin(strike, direction, params);
    b.state = MotionState::sliding;
    cloth.settle_motion_state(b, params);
    return b;
}

} // namespace termpool
