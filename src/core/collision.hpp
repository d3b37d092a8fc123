#pragma once
// What a contact does to the balls' velocities and spins.

#include <termpool/ball.hpp>
#include <termpool/params.hpp>

#include "classic_motion.hpp"
#include "cloth_model.hpp"

namespace termpool::core {

/// Relative normal speed two balls (or a ball and a cushion) leave a contact with at least, m/s.
/// It keeps a pair that rounding left touching from being found in contact again at once.
inline constexpr double min_separation_speed = 1e-6;

/// Speed at which two balls that pushed each other part, m/s (see resolve_physical_push).
inline constexpr double push_parting_speed = 0.001;

/// Resolves a contact between two touching balls on `cloth`; `a` and `b` get their new
/// velocities, spins and motion states.
void resolve_ball_ball(Ball& a, Ball& b, const PhysicsParams& params, const ClothModel& cloth);

/// Resolves a contact of a ball with a cushion or jaw on `cloth`. `towards_cushion` is the unit
/// vector in the table plane from the ball's centre to the contact.
void resolve_cushion(Ball& ball, Vec2 towards_cushion, const PhysicsParams& params,
                     const ClothModel& cloth);

/// The physical cloth's part in a slow ball-ball contact (ClothModel::slow_pair_contact): two
/// balls it presses together are resolved as a push.
void resolve_physical_push(Ball& a, Ball& b, Vec2 n, const PhysicsParams& params);

/// A classic cloth's part in a slow ball-ball contact (ClothModel::slow_pair_contact) under
/// `law`: two moving balls it drives into each other are pushed to one speed along `n` and, if
/// still pressed together, parted.
void resolve_classic_push(Ball& a, Ball& b, Vec2 n, const PhysicsParams& params,
                          const ClassicLaw& law);

/// The physical cloth's part in a slow cushion contact (ClothModel::slow_cushion_contact).
void resolve_physical_slow_cushion(Ball& ball, Vec2 towards_cushion, const PhysicsParams& params);

} // namespace termpool::core
