#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>

namespace termpool {

PhysicsParams physics_for_table(TableSize size, PhysicsParams base) {
    if (size == TableSize::snooker) {
        base.ball_radius = snooker_ball_radius;
        base.ball_mass = snooker_ball_mass;
    }
    return base;
}

} // namespace termpool
