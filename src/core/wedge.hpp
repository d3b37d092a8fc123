#pragma once
// A classic cloth stops a ball pushed slower than its rest speed at once, so a ball at rest is a
// wall to a slow push. A ball driven into the wedge between such a ball and a cushion (or a
// second such ball) would bounce between them, a contact every 1e-14 s or so, tens of thousands
// of times, until it crept out or the ball-ball friction had taken its speed. The contacts are
// simultaneous: they are resolved here in one event, on the velocity at that instant.

#include <optional>
#include <termpool/ball.hpp>
#include <termpool/event.hpp>
#include <termpool/params.hpp>
#include <termpool/table.hpp>
#include <vector>

#include "cloth_model.hpp"

namespace termpool::core {

/// Gap, m, up to which a ball counts as touching a cushion or another ball in a wedge: far more
/// than the round-off of positions (about 1e-15 m) and far less than anything a player sees.
inline constexpr double wedge_touch_gap = 1e-12;

/// Bounce pairs after which a ball still pressed into its wedge counts as jammed and stops.
/// A wedge as narrow as 1e-3 rad lets an elastic ball out after about 3000.
inline constexpr int max_wedge_turns = 10000;

/// A cushion feature a ball touches.
struct CushionTouch {
    Vec2 towards; ///< unit vector from the centre to the contact
    Event event;  ///< the event a contact with it is reported as (time 0, ball 0)
};

/// The rails, jaw lines and jaw points within `wedge_touch_gap` of a ball of radius `radius`
/// centred at `p`.
std::vector<CushionTouch> touching_cushions(const Table& table, Vec2 p, double radius);

/// What escaping a wedge touched, for the events.
struct WedgeContacts {
    std::vector<Event> cushions;    ///< the cushion features hit (time 0, ball 0)
    std::vector<std::size_t> balls; ///< indices into `held` of the balls hit
};

/// Resolves the contacts of `mover` with the cushions and held balls it touches, the ones it
/// presses into, again and again at this instant until it presses into none, or stops it as
/// jammed after max_wedge_turns. A held ball that a contact sets moving has given way and is a
/// wall no more. Every contact goes through resolve_cushion and resolve_ball_ball, so energy
/// is only lost.
WedgeContacts escape_wedge(Ball& mover, const std::vector<CushionTouch>& cushions,
                           std::vector<Ball>& held, const PhysicsParams& params,
                           const ClothModel& cloth);

} // namespace termpool::core
