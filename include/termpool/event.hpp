#pragma once
/// \file
/// What happens during a shot.

#include <termpool/enum_names.hpp>

namespace termpool {

/// Kinds of events, in the words of the simulator's output.
enum class EventKind {
    ball_ball, ///< two balls collide (ball, other = the two ids)
    cushion,   ///< a ball hits a rail (ball; other = rail index 0..5)
    jaw,       ///< a ball hits a pocket jaw or point (ball; other = pocket 1..6)
    pocket,    ///< a ball drops (ball; other = pocket 1..6)
    sliding,   ///< a ball starts sliding (the struck cue ball)
    rolling,   ///< a sliding ball starts rolling
    spinning,  ///< a ball stops moving but still spins about the vertical
    stopped,   ///< a ball comes to rest
    off_table, ///< a ball leaves the table (ball). The 2D simulator never produces it; the
               ///< referee's rules for it apply to hand-made event lists and future models.
};

/// One event of a shot.
struct Event {
    double time = 0;                     ///< seconds since the strike
    EventKind kind = EventKind::stopped; ///< what happened
    int ball = 0;                        ///< the ball (for ball_ball the lower id)
    int other = 0;                       ///< the other ball, rail or pocket; see EventKind
    /// Exact equality, for determinism checks.
    bool operator==(const Event&) const = default;
};

/// The event kinds' names, in the simulator's output.
inline constexpr NameRow<EventKind> event_kind_names[] = {
    {EventKind::ball_ball, "ball-ball"},
    {EventKind::cushion, "cushion"},
    {EventKind::jaw, "jaw"},
    {EventKind::pocket, "pocket"},
    {EventKind::sliding, "sliding"},
    {EventKind::rolling, "rolling"},
    {EventKind::spinning, "spinning"},
    {EventKind::stopped, "stopped"},
    {EventKind::off_table, "off-table"},
};
static_assert(names_in_order(event_kind_names));

/// Name of an event kind as used in the simulator's output ("ball-ball", ...).
const char* event_kind_name(EventKind kind);

} // namespace termpool
