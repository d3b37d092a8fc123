#pragma once
// Small builders shared by the physics tests.

#include "support/random.hpp"
#include <numbers>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>
#include <vector>

namespace termpool::test {

/// A sliding ball at (1, 1) driven into a rail whose normal is +x: any direction into it, up to
/// 20 m/s, and any spin up to what the hardest strike at the edge of the ball gives; the
/// cushion models' energy tests draw their cases from it.
inline Ball random_cushion_approach(Random& rng, double radius);

inline Ball ball_at(int id, double x, double y, double mass = 0.170) {
    Ball b;
    b.id = id;
    b.position = {x, y};
    b.mass = mass;
    return b;
}

/// Steps the world until the first event of `kind` and returns it (or a default event).
inline Event step_until(World& world, EventKind kind) {
    while (const auto e = world.step())
        if (e->kind == kind)
            return *e;
    return {};
}

/// The ball with `id` in `balls`.
inline Ball find_ball(const std::vector<Ball>& balls, int id) {
    for (const Ball& b : balls)
        if (b.id == id)
            return b;
    return {};
}

inline double total_energy(const std::vector<Ball>& balls, double radius) {
    double e = 0;
    for (const Ball& b : balls)
        e += kinetic_energy(b, radius);
    return e;
}

/// A classic cloth model with random constants: `kind` 0 decay, 1 constant, else combined, with
/// K in 0.3..3 /s and A in 0.1..2 m/s^2 drawn from `rng` (the ranges the random-shot tests use).
inline FrictionModel random_classic_friction(Random& rng, std::uint64_t kind) {
    switch (kind) {
    case 0:
        return {FrictionKind::decay, rng.uniform(0.3, 3), 0, 0.005};
    case 1:
        return {FrictionKind::constant, 0, rng.uniform(0.1, 2), 0.005};
    default:
        return {FrictionKind::combined, rng.uniform(0.3, 3), rng.uniform(0.1, 2), 0.005};
    }
}

inline Ball random_cushion_approach(Random& rng, double radius) {
    Ball b = ball_at(0, 1, 1);
    b.velocity = unit_from_angle(rng.uniform(-std::numbers::pi / 2, std::numbers::pi / 2)) *
                 rng.uniform(0, 20);
    const double spin = 5 * 20 / (2 * radius);
    b.angular_velocity = {rng.uniform(-spin, spin), rng.uniform(-spin, spin),
                          rng.uniform(-spin, spin)};
    b.state = MotionState::sliding;
    return b;
}

} // namespace termpool::test
