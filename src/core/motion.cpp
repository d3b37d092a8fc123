#include "core/motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// The classic models (the seed report's): speed after dt and distance covered in dt, starting at
// speed v.
struct ClassicStep {
    double speed;
    double distance;
};

ClassicStep classic_step(double v, double dt, const FrictionModel& f) {
    const double K = f.decay_rate, A = f.deceleration;
    auto exponential = [&](double t) {
        const double decay = std::exp(-K * t);
        return ClassicStep{v * decay, v * (1 - decay) / K};
    };
    auto linear = [](double v0, double a, double t) {
        return ClassicStep{v0 - a * t, v0 * t - 0.5 * a * t * t};
    };
    switch (f.kind) {
    case FrictionKind::decay:
        return exponential(dt);
    case FrictionKind::constant:
        return linear(v, A, dt);
    case FrictionKind::combined: {
        // Exponential decay slows more than A while K v > A.
        const double switch_speed = A / K;
        if (v <= switch_speed)
            return linear(v, A, dt);
        const double t_switch = std::log(v / switch_speed) / K;
        if (dt <= t_switch)
            return exponential(dt);
        const ClassicStep first = exponential(t_switch);
        const ClassicStep rest = linear(switch_speed, A, dt - t_switch);
        return {rest.speed, first.distance + rest.distance};
    }
    case FrictionKind::physical:
        break;
    }
    return {v, v * dt};
}

double classic_stop_time(double v, const FrictionModel& f) {
    const double K = f.decay_rate, A = f.deceleration, rest = f.rest_speed;
    if (v <= rest)
        return 0;
    switch (f.kind) {
    case FrictionKind::decay:
        return std::log(v / rest) / K;
    case FrictionKind::constant:
        return (v - rest) / A;
    case FrictionKind::combined: {
        const double switch_speed = A / K;
        if (v <= switch_speed || switch_speed <= rest)
            return v <= switch_speed ? (v - rest) / A : std::log(v / rest) / K;
        return std::log(v / switch_speed) / K + (switch_speed - rest) / A;
    }
    case FrictionKind::physical:
        break;
    }
    return infinity;
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

double time_to_transition(const Ball& b, const PhysicsParams& p) {
    if (is_classic_friction(p)) {
        return b.state == MotionState::rolling ? classic_stop_time(length(b.velocity), p.friction)
                                               : infinity;
    }
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
    if (is_classic_friction(p)) {
        if (b.state != MotionState::rolling)
            return out;
        const double v = length(b.velocity);
        const Vec2 direction = b.velocity / v;
        const ClassicStep step = classic_step(v, dt, p.friction);
        out.position = b.position + direction * step.distance;
        out.velocity = direction * step.speed;
        return out;
    }
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
    if (is_classic_friction(p)) {
        out.velocity = {};
        out.angular_velocity = {};
        out.state = MotionState::stationary;
        return out;
    }
    switch (b.state) {
    case MotionState::sliding:
        // The slip has just vanished: make it exactly zero.
        out.angular_velocity = rolling_spin(b.velocity, b.angular_velocity.z, p.ball_radius);
        out.state = MotionState::rolling;
        settle_motion_state(out, p);
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

void settle_motion_state(Ball& b, const PhysicsParams& p) {
    if (b.state == MotionState::pocketed)
        return;
    if (is_classic_friction(p)) {
        b.angular_velocity = {};
        if (length(b.velocity) <= p.friction.rest_speed) {
            b.velocity = {};
            b.state = MotionState::stationary;
        } else {
            b.state = MotionState::rolling;
        }
        return;
    }
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

} // namespace termpool::core
