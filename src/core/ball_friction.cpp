#include "../support/portable_math.hpp"
#include <cmath>
#include <termpool/params.hpp>

namespace termpool {

double ball_friction_at(const BallFriction& friction, double sliding_speed) {
    if (friction.model == BallFrictionModel::constant)
        return friction.constant;
    return friction.a + friction.b * portable::exp(-friction.c * sliding_speed);
}

} // namespace termpool
