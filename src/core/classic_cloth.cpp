// The classic cloth models, the seed report's: a ball rolls on a straight line without spin,
// its speed following the model's law, and stops below the rest speed. Each law is a type
// (Decay, Constant, Combined) that the model's functions are instantiated with, so the law is
// chosen with the model, not looked up on every step.

#include "../support/portable_math.hpp"
#include <cmath>
#include <limits>
#include <termpool/simulator.hpp>

#include "classic_motion.hpp"
#include "cloth_model.hpp"
#include "collision.hpp"
#include "pair_contacts.hpp"
#include "table_contacts.hpp"

namespace termpool::core {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Speed after some time and distance covered in it.
struct Step {
    double speed;
    double distance;
};

Step exponential_step(double v, double t, double K) {
    return {v * portable::exp(-K * t), v * -portable::expm1(-K * t) / K};
}

Step linear_step(double v0, double a, double t) {
    return {v0 - a * t, v0 * t - 0.5 * a * t * t};
}

// The laws: a ball's step over dt from speed v, its time from speed v to the rest speed (v above
// the rest speed), and its constants for the contact searches.
struct Decay {
    static ClassicLaw law(const FrictionModel& f) { return {f.decay_rate, 0}; }
    static Step step(double v, double dt, const FrictionModel& f) {
        return exponential_step(v, dt, f.decay_rate);
    }
    static double stop_time(double v, const FrictionModel& f) {
        return portable::log(v / f.rest_speed) / f.decay_rate;
    }
};

struct Constant {
    static ClassicLaw law(const FrictionModel& f) { return {0, f.deceleration}; }
    static Step step(double v, double dt, const FrictionModel& f) {
        return linear_step(v, f.deceleration, dt);
    }
    static double stop_time(double v, const FrictionModel& f) {
        return (v - f.rest_speed) / f.deceleration;
    }
};

// Exponential decay slows more than A while K v > A.
struct Combined {
    static ClassicLaw law(const FrictionModel& f) { return {f.decay_rate, f.deceleration}; }
    static Step step(double v, double dt, const FrictionModel& f) {
        const double K = f.decay_rate, A = f.deceleration;
        const double switch_speed = A / K;
        if (v <= switch_speed)
            return linear_step(v, A, dt);
        const double t_switch = portable::log(v / switch_speed) / K;
        if (dt <= t_switch)
            return exponential_step(v, dt, K);
        const Step first = exponential_step(v, t_switch, K);
        const Step rest = linear_step(switch_speed, A, dt - t_switch);
        return {rest.speed, first.distance + rest.distance};
    }
    static double stop_time(double v, const FrictionModel& f) {
        const double K = f.decay_rate, A = f.deceleration, rest = f.rest_speed;
        const double switch_speed = A / K;
        if (v <= switch_speed || switch_speed <= rest)
            return v <= switch_speed ? (v - rest) / A : portable::log(v / rest) / K;
        return portable::log(v / switch_speed) / K + (switch_speed - rest) / A;
    }
};

template <class Law> double time_to_stop(const Ball& b, const PhysicsParams& p) {
    if (b.state != MotionState::rolling)
        return infinity;
    const double v = length(b.velocity);
    if (v <= p.friction.rest_speed)
        return 0;
    return Law::stop_time(v, p.friction);
}

template <class Law> Ball advance(const Ball& b, double dt, const PhysicsParams& p) {
    if (dt <= 0 || b.state != MotionState::rolling)
        return b;
    Ball out = b;
    const double v = length(b.velocity);
    const Vec2 direction = b.velocity / v;
    const Step step = Law::step(v, dt, p.friction);
    out.position = b.position + direction * step.distance;
    out.velocity = direction * step.speed;
    return out;
}

// A classic ball's only transition.
Ball stop(const Ball& b, const PhysicsParams&) {
    Ball out = b;
    out.velocity = {};
    out.angular_velocity = {};
    out.state = MotionState::stationary;
    return out;
}

void settle_motion_state(Ball& b, const PhysicsParams& p) {
    if (b.state == MotionState::pocketed)
        return;
    b.angular_velocity = {};
    if (length(b.velocity) <= p.friction.rest_speed) {
        b.velocity = {};
        b.state = MotionState::stationary;
    } else {
        b.state = MotionState::rolling;
    }
}

// The contact searches along straight lines: exact solves in each phase of the law.
template <class Law> ClassicMotion motion(const PhysicsParams& p) {
    return {Law::law(p.friction), advance<Law>, &p};
}

template <class Law> Box reach(const MotionPiece& piece, double duration, const PhysicsParams& p) {
    return classic_reach(piece, duration, p, advance<Law>);
}

template <class Law>
ContactEstimate pair_contact(const MotionPiece& a, const MotionPiece& b, double now, double horizon,
                             const PhysicsParams& p) {
    return classic_pair_contact(a, b, now, horizon, motion<Law>(p));
}

template <class Law>
double pair_contact_time(const MotionPiece& a, const MotionPiece& b, double now, double horizon,
                         const PhysicsParams& p) {
    return pair_contact<Law>(a, b, now, horizon, p).time;
}

template <class Law>
TableSearch table_event(const MotionPiece& piece, const Box& reach, double now, const Table& table,
                        const PhysicsParams& p) {
    return classic_table_event(piece, reach, now, table, motion<Law>(p));
}

template <class Law> void slow_pair_contact(Ball& a, Ball& b, Vec2 n, const PhysicsParams& p) {
    resolve_classic_push(a, b, n, p, Law::law(p.friction));
}

template <class Law> ClothModel classic_cloth() {
    return {
        .time_to_transition = time_to_stop<Law>,
        .advance = advance<Law>,
        .apply_transition = stop,
        .settle_motion_state = settle_motion_state,
        // A straight line: the world's parabola is not used.
        .acceleration = [](const Ball&, const PhysicsParams&) { return Vec2{}; },
        // No spin, so the tip gives none. A ball's deceleration points straight back along its
        // way, so it never drives it back into a cushion it leaves; two moving balls it can
        // drive into each other (slow_pair_contact).
        .keeps_spin = false,
        .holds_slow_balls = true,
        .slow_pair_contact = slow_pair_contact<Law>,
        .slow_cushion_contact = [](Ball&, Vec2, const PhysicsParams&) {},
        .towards_cushion = physical_towards_cushion,
        .reach = reach<Law>,
        .pair_contact = pair_contact<Law>,
        .pair_contact_time = pair_contact_time<Law>,
        .table_event = table_event<Law>,
    };
}

} // namespace

ClothModel decay_cloth() {
    return classic_cloth<Decay>();
}

ClothModel constant_cloth() {
    return classic_cloth<Constant>();
}

ClothModel combined_cloth() {
    return classic_cloth<Combined>();
}

} // namespace termpool::core
