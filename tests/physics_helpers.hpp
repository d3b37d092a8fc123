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

/// True when a ball centre is where the cushions and jaws allow it: on the playing surface or in
/// a pocket's mouth (in front of its capture line).
inline bool within_cushions(const Table& table, Vec2 p) {
    const double margin = 1e-9;
    if (p.x >= -margin && p.x <= table.length + margin && p.y >= -margin &&
        p.y <= table.width + margin)
        return true;
    for (const Pocket& pocket : table.pockets) {
        const bool in_box =
            p.x >= pocket.region_min.x - margin && p.x <= pocket.region_max.x + margin &&
            p.y >= pocket.region_min.y - margin && p.y <= pocket.region_max.y + margin;
        if (in_box && dot(p - pocket.capture_point, pocket.capture_normal) >= -margin)
            return true;
    }
    return false;
}

} // namespace termpool::test
