#include "pair_contacts.hpp"

#include <cmath>
#include <limits>

#include "classic_contacts.hpp"
#include "contact_time.hpp"

namespace termpool::core {

namespace {

// At least the coordinates' size |x| + |y| of a piece's centre at `now` (clearly_apart's
// `place`), from the piece as it is kept: only a bound needs it, and a path's own coordinates
// kept alive across the estimate cost every pair more.
double place_of(const MotionPiece& s, double now) {
    const double t = now - s.start;
    const Ball& b = s.ball;
    return std::abs(b.position.x) + std::abs(b.position.y) +
           (std::abs(b.velocity.x) + std::abs(b.velocity.y) +
            (std::abs(s.acceleration.x) + std::abs(s.acceleration.y)) * t) *
               t;
}

} // namespace

ContactEstimate physical_pair_contact(const MotionPiece& a, const MotionPiece& b, double now,
                                      double horizon, const PhysicsParams& params) {
    const double distance = 2 * params.ball_radius;
    const Path from_a = path_from(a, now), from_b = path_from(b, now);
    const ContactEstimate estimate = path_path_contact_estimate(from_a, from_b, distance, horizon);
    // A bound for two balls clearly apart is no contact: the search that would have found none
    // when the bound came first is left out (in a computer's search, nearly half of those
    // searches: a ball passing one at rest).
    if (!estimate.exact && clearly_apart(from_a, from_b, distance, horizon, place_of(a, now)))
        return {std::numeric_limits<double>::infinity(), true};
    return estimate;
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
