#include "../support/portable_math.hpp"
#include <cmath>
#include <numbers>
#include <termpool/simulator.hpp>

#include "cloth_model.hpp"
#include "cue_impact.hpp"

namespace termpool {

// The ball stays on the cloth: the impulse's downward part goes into the slate, which gives it
// back vertically (strike_problem refuses strikes whose rebound would lift the ball), and the
// slate's impulse through the centre adds no spin. Classic cloths keep no spin, so there a
// raised cue only slows the ball (the horizontal part of the impulse) and squirt only turns it.
Ball strike_cue_ball(const Ball& cue, const Strike& strike, const PhysicsParams& params) {
    const core::ClothModel cloth = core::cloth_model(params.friction);
    const core::CueImpact impact = core::cue_impact(strike, cue.mass, params);
    Ball b = cue;
    b.velocity = planar(impact.velocity);
    b.angular_velocity = cloth.keeps_spin ? impact.angular_velocity : Vec3{};
    b.state = MotionState::sliding;
    cloth.settle_motion_state(b, params);
    return b;
}

double squirt_angle_deg(double side, double ball_mass, double end_mass) {
    return -portable::atan(core::squirt_ratio(side, 0, ball_mass, end_mass)) * 180.0 /
           std::numbers::pi;
}

} // namespace termpool
