#include "pair_contacts.hpp"

#include <utility>

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

ContactEstimate classic_pair_contact(const MotionPiece& a_piece, const MotionPiece& b_piece,
                                     double now, double horizon, const PhysicsParams& params,
                                     AdvanceFn advance) {
    const Ball a = state_at(a_piece, now, advance, params);
    const Ball b = state_at(b_piece, now, advance, params);
    const double diameter = 2 * params.ball_radius;
    auto gap = [&](double t) {
        const Ball pa = advance(a, t, params), pb = advance(b, t, params);
        const Vec2 d = pb.position - pa.position;
        const double dist = length(d);
        return std::pair{dist - diameter, dot(d, pb.velocity - pa.velocity) / dist};
    };
    auto bound = [&](double t) {
        return length(advance(a, t, params).velocity) + length(advance(b, t, params).velocity);
    };
    return {advance_until_contact(gap, bound, horizon), true};
}

} // namespace termpool::core
