#pragma once
// When classic balls (classic_motion.hpp) first touch each other, a cushion line, a jaw point or
// a capture line: exact solves, as the physical model's. A ball's motion is split at its switch
// from decaying to decelerating; on each stretch the centre is a parabola in t (decelerating, the
// physical model's Path) or a straight line in u = 1 - e^(-K t) (decaying), so gaps are
// polynomials in t or u. Only a pair with one ball in each phase has a gap that is neither; it is
// solved by second-order conservative advancement, which cannot step over a contact.
//
// Every function takes the balls' states now, returns seconds from now or +infinity when there
// is no contact within `horizon`, and counts a contact only while the two are approaching.
// `advance` is the law's own (the world's), used to find the states at the switches.

#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/vec.hpp>

#include "classic_motion.hpp"
#include "motion_piece.hpp"

namespace termpool::core {

/// Everything a classic contact search needs of the law.
struct ClassicMotion {
    ClassicLaw law;              ///< its constants
    AdvanceFn advance;           ///< moves a ball as the world does
    const PhysicsParams* params; ///< for `advance`
};

/// First time the centres of balls a and b are `distance` apart and closing.
double classic_pair_contact_time(const Ball& a, const Ball& b, double distance, double horizon,
                                 const ClassicMotion& motion);

/// First time the centre comes within `offset` of the line through `point` (from the side
/// `normal` points to) while moving towards it.
double classic_line_contact_time(const Ball& ball, Vec2 point, Vec2 normal, double offset,
                                 double horizon, const ClassicMotion& motion);

/// First time the centre comes within `radius` of `point` while moving towards it.
double classic_point_contact_time(const Ball& ball, Vec2 point, double radius, double horizon,
                                  const ClassicMotion& motion);

// ---- the solvers of one stretch, for the tests

/// A centre decaying at rate K: x(t) = position + velocity (1 - e^(-K t)) / K.
struct DecayingPath {
    Vec2 position; ///< at t = 0, m
    Vec2 velocity; ///< at t = 0, m/s
};

/// First time two decaying centres (one rate K) are `distance` apart and closing: a quadratic in
/// u = 1 - e^(-K t).
double decaying_pair_contact_time(const DecayingPath& a, const DecayingPath& b, double K,
                                  double distance, double horizon);

/// First time a decaying centre comes within `offset` of a line (linear in u).
double decaying_line_contact_time(const DecayingPath& a, double K, Vec2 point, Vec2 normal,
                                  double offset, double horizon);

/// First time a decaying centre `a` and a centre `b` on a parabola (Path) are `distance` apart
/// and closing: second-order conservative advancement, then safeguarded Newton to round-off.
/// `b` must not turn back within the horizon (it is a decelerating ball before it stops).
/// `steps`, when given, receives how many advancement steps it took.
double mixed_pair_contact_time(const DecayingPath& a, double K, const Path& b, double distance,
                               double horizon, int* steps = nullptr);

} // namespace termpool::core
