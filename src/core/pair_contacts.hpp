#pragma once
// When two moving balls first touch, under each cloth model. Times are seconds from `now`,
// +infinity when the balls do not touch within `horizon`.

#include <termpool/params.hpp>

#include "classic_contacts.hpp"
#include "motion_piece.hpp"
#include "polynomial.hpp"

namespace termpool::core {

/// The physical model's contact of two pieces' balls (their parabolas' quartic), or a lower bound
/// on it when that is much cheaper (path_path_contact_estimate); no contact (+infinity, exact)
/// in place of a bound for two balls clearly_apart.
ContactEstimate physical_pair_contact(const MotionPiece& a, const MotionPiece& b, double now,
                                      double horizon, const PhysicsParams& params);

/// The physical model's contact itself, for a pair that holds only a bound.
double physical_pair_contact_time(const MotionPiece& a, const MotionPiece& b, double now,
                                  double horizon, const PhysicsParams& params);

/// A classic model's contact (classic_pair_contact_time on the balls' states now); always exact.
ContactEstimate classic_pair_contact(const MotionPiece& a, const MotionPiece& b, double now,
                                     double horizon, const ClassicMotion& motion);

} // namespace termpool::core
