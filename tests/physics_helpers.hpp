#pragma once
// Small builders shared by the physics tests.

#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>
#include <vector>

namespace termpool::test {

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

} // namespace termpool::test
