#pragma once
// What the cue tip gives the cue ball, in three dimensions: the velocity the impulse would give
// a free ball (its downward part goes into the slate) and the spin about the centre. Shared by
// strike_cue_ball (the ball on the cloth) and strike_problem (the jump-shot limit).

#include <termpool/simulator.hpp>
#include <termpool/vec.hpp>

namespace termpool::core {

/// The tip's impulse on a free ball, per unit of the ball's mass.
struct CueImpact {
    Vec3 velocity;         ///< m/s; z < 0 when the cue is raised (towards the slate)
    Vec3 angular_velocity; ///< rad/s, about the ball's centre
};

/// The impulse of `strike` on a ball of `ball_mass` (kg), with the cue's end mass from `params`.
CueImpact cue_impact(const Strike& strike, double ball_mass, const PhysicsParams& params);

/// The tip's sideways impulse over its impulse along the cue (negative: away from the side
/// struck), for tip offsets `side` and `follow` (fractions of R) across the cue.
double squirt_ratio(double side, double follow, double ball_mass, double end_mass);

} // namespace termpool::core
