#pragma once
/// \file
/// The state of one ball.

#include <termpool/enum_names.hpp>
#include <termpool/vec.hpp>

namespace termpool {

/// What a ball is doing between events.
enum class MotionState {
    stationary, ///< at rest, no spin
    spinning,   ///< at rest on the table, turning about the vertical axis
    sliding,    ///< the contact point slips on the cloth
    rolling,    ///< rolling without slip
    pocketed,   ///< in a pocket, out of play
};

/// A ball at one instant. ID 0 is the cue ball, 1..15 the object balls.
struct Ball {
    int id = 0;                                  ///< ball number
    Vec2 position;                               ///< centre, m
    Vec2 velocity;                               ///< m/s
    Vec3 angular_velocity;                       ///< rad/s
    double mass = 0.170;                         ///< kg
    MotionState state = MotionState::stationary; ///< current motion
    int pocket = 0;                              ///< pocket number 1..6 once pocketed, else 0
    /// Exact equality, for determinism checks.
    bool operator==(const Ball&) const = default;
};

/// The motion states' names, in the simulator's output.
inline constexpr NameRow<MotionState> motion_state_names[] = {
    {MotionState::stationary, "stationary"}, {MotionState::spinning, "spinning"},
    {MotionState::sliding, "sliding"},       {MotionState::rolling, "rolling"},
    {MotionState::pocketed, "pocketed"},
};
static_assert(names_in_order(motion_state_names));

/// Name of a motion state as used in the simulator's output ("sliding", ...).
const char* motion_state_name(MotionState state);

} // namespace termpool
