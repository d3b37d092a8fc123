#include "physical_cloth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <termpool/simulator.hpp>

#include "cloth_model.hpp"
#include "collision.hpp"
#include "pair_contacts.hpp"
#include "table_contacts.hpp"

namespace termpool::core {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
// Slip and speed below this are rounding noise left by a collision, not motion (m/s).
constexpr double negligible_speed = 1e-12;

// Rate at which the vertical spin decays, rad/s^2.
double spin_decay_rate(const PhysicsParams& p) {
    return 5.0 * p.gravity * p.spin_friction / (2.0 * p.ball_radius);
}

double decayed_spin(double spin, double rate, double dt) {
    const double magnitude = std::max(0.0, std::abs(spin) - rate * dt);
    return std::copysign(magnitude, spin);
}

Vec3 rolling_spin(Vec2 velocity, double spin_z, double radius) {
    return {-velocity.y / radius, velocity.x / radius, spin_z};
}

double time_to_transition(const Ball& b, const PhysicsParams& p) {
    switch (b.state) {
    case MotionState::sliding:
        return 2.0 * length(slip_velocity(b, p.ball_radius)) /
               (7.0 * p.sliding_friction * p.gravity);
    case MotionState::rolling:
        return length(b.velocity) / (p.rolling_friction * p.gravity);
    case MotionState::spinning:
        return std::abs(b.angular_velocity.z) / spin_decay_rate(p);
    default:
        return infinity;
    }
}

Ball advance(const Ball& b, double dt, const PhysicsParams& p) {
    if (dt <= 0)
        return b;
    Ball out = b;
    const double spin_rate = spin_decay_rate(p);
    switch (b.state) {
    case MotionState::sliding: {
        const Vec2 slip_dir = normalized(slip_velocity(b, p.ball_radius));
        const double decel = p.sliding_friction * p.gravity;
        const Vec2 a = slip_dir * -decel;
        out.position = b.position + b.velocity * dt + a * (0.5 * dt * dt);
        out.velocity = b.velocity + a * dt;
        // Friction at the contact point turns the ball about the axis k x slip.
        const double spin_change = 5.0 * decel * dt / (2.0 * p.ball_radius);
        out.angular_velocity = {b.angular_velocity.x - slip_dir.y * spin_change,
                                b.angular_velocity.y + slip_dir.x * spin_change,
                                decayed_spin(b.angular_velocity.z, spin_rate, dt)};
        return out;
    }
    case MotionState::rolling: {
        const double speed = length(b.velocity);
        const Vec2 dir = b.velocity / speed;
        const double decel = p.rolling_friction * p.gravity;
        // Clamp so that rounding past the stop never reverses the ball.
        const double t = std::min(dt, speed / decel);
        out.position = b.position + b.velocity * t + dir * (-0.5 * decel * t * t);
        out.velocity = dir * std::max(0.0, speed - decel * t);
        out.angular_velocity = rolling_spin(
            out.velocity, decayed_spin(b.angular_velocity.z, spin_rate, dt), p.ball_radius);
        return out;
    }
    case MotionState::spinning:
        out.angular_velocity.z = decayed_spin(b.angular_velocity.z, spin_rate, dt);
        return out;
    default:
        return out;
    }
}

Ball apply_transition(const Ball& b, const PhysicsParams& p) {
    Ball out = b;
    switch (b.state) {
    case MotionState::sliding:
        // The slip has just vanished: make it exactly zero.
        out.angular_velocity = rolling_spin(b.velocity, b.angular_velocity.z, p.ball_radius);
        out.state = MotionState::rolling;
        physical_settle_motion_state(out, p);
        return out;
    case MotionState::rolling:
        out.velocity = {};
        out.angular_velocity = {0, 0, b.angular_velocity.z};
        out.state = out.angular_velocity.z != 0 ? MotionState::spinning : MotionState::stationary;
        return out;
    case MotionState::spinning:
        out.angular_velocity = {};
        out.state = MotionState::stationary;
        return out;
    default:
        return out;
    }
}

} // namespace

Vec2 slip_velocity(const Ball& b, double radius) {
    return {b.velocity.x - radius * b.angular_velocity.y,
            b.velocity.y + radius * b.angular_velocity.x};
}

Vec2 physical_acceleration(const Ball& b, const PhysicsParams& p) {
    switch (b.state) {
    case MotionState::sliding:
        return normalized(slip_velocity(b, p.ball_radius)) * (-p.sliding_friction * p.gravity);
    case MotionState::rolling:
        return normalized(b.velocity) * (-p.rolling_friction * p.gravity);
    default:
        return {};
    }
}

void physical_settle_motion_state(Ball& b, const PhysicsParams& p) {
    if (b.state == MotionState::pocketed)
        return;
    const double speed = length(b.velocity);
    const double slip = length(slip_velocity(b, p.ball_radius));
    if (slip <= negligible_speed) {
        if (speed <= negligible_speed) {
            b.velocity = {};
            b.angular_velocity = {0, 0, b.angular_velocity.z};
            b.state = b.angular_velocity.z != 0 ? MotionState::spinning : MotionState::stationary;
        } else {
            b.angular_velocity = rolling_spin(b.velocity, b.angular_velocity.z, p.ball_radius);
            b.state = MotionState::rolling;
        }
        return;
    }
    b.state = MotionState::sliding;
}

ClothModel physical_cloth() {
    return {
        .time_to_transition = time_to_transition,
        .advance = advance,
        .apply_transition = apply_transition,
        .settle_motion_state = physical_settle_motion_state,
        .acceleration = physical_acceleration,
        .keeps_spin = true,
        .holds_slow_balls = false,
        .slow_pair_contact = resolve_physical_push,
        .slow_cushion_contact = resolve_physical_slow_cushion,
        .towards_cushion = physical_towards_cushion,
        .reach = physical_reach,
        .pair_contact = physical_pair_contact,
        .pair_contact_time = physical_pair_contact_time,
        .table_event = physical_table_event,
    };
}

} // namespace termpool::core
