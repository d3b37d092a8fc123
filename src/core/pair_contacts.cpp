#include "pair_contacts.hpp"

#include "classic_contacts.hpp"
#include "contact_time.hpp"

namespace termpool::core {

ContactEstimate physical_pair_contact(const MotionPiece& a, const MotionPiece& b, double now,
                                      double horizon, const PhysicsParams& params) {
    return path_path_contact_estimate(path_from(a, now), path_from(b, now), 2 * params.ball_radius,
                                      horizon);
}

double physical_pair_contact_time(const MotionPiece& a, const MotionPiece& b, double now,
                                  double horizon, const PhysicsParams& params) {
    return path_path_contact_time(path_from(a, now), path_from(b, now), 2 * params.ball_radius,
                                  horizon);
}

ContactEstimate classic_pair_contact(const MotionPiece& a, const MotionPiece& b, double now,
                                     double horizon, const ClassicMotion& motion) {
    const PhysicsParams& params = *motion.params;
    return {classic_pair_contact_time(state_at(a, now, motion.advance, params),
                                      state_at(b, now, motion.advance, params),
                                      2 * params.ball_radius, horizon, motion),
            true};
}

} // namespace termpool::core
