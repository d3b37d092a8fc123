#pragma once
/// \file
/// The balls a table is played with: pool tables take pool balls (57.15 mm, 170 g, the
/// defaults of PhysicsParams), the snooker table snooker balls (52.5 mm, 142 g). Only the size
/// and the mass change, so that every cloth, collision and cushion model works unchanged.

#include <termpool/params.hpp>
#include <termpool/table.hpp>

namespace termpool {

/// `base` with the balls of a table of size `size`: on the snooker table the ball radius and
/// mass become snooker's (`snooker_ball_radius`, `snooker_ball_mass`); a cue ball mass set in
/// `base` (a heavier cue ball) is kept. On a pool table `base` is returned unchanged.
PhysicsParams physics_for_table(TableSize size, PhysicsParams base = {});

} // namespace termpool
