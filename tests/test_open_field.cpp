// The open field: the boxes of a table where the table search culls every rail and pocket, so
// that a moving ball whose reach lies in one has its transition for its next event without a
// search (World takes that shortcut). Checked against the search itself, in every cloth model.
#include "support/random.hpp"
#include <catch2/catch.hpp>
#include <termpool/table_physics.hpp>

#include "core/cloth_model.hpp"
#include "core/table_contacts.hpp"
#include "physics_helpers.hpp"

using namespace termpool;

namespace {

// Whether box a lies in box b.
bool inside(const core::Box& a, const core::Box& b) {
    return a.min.x >= b.min.x && a.max.x <= b.max.x && a.min.y >= b.min.y && a.max.y <= b.max.y;
}

// A moving ball anywhere on the bed of `table`, sliding or rolling, at up to 12 m/s.
Ball random_moving_ball(Random& rng, const Table& table, double radius) {
    Ball b = test::ball_at(0, rng.uniform(radius, table.length - radius),
                           rng.uniform(radius, table.width - radius));
    b.velocity = unit_from_angle(rng.uniform(-3.2, 3.2)) * rng.uniform(0.01, 12);
    const double spin = rng.uniform(0, 1) < 0.5 ? 0 : 200;
    b.angular_velocity = {rng.uniform(-spin, spin), rng.uniform(-spin, spin),
                          rng.uniform(-spin, spin)};
    b.state = MotionState::sliding;
    return b;
}

} // namespace

TEST_CASE("the open field of every table is the bed between its pockets, inside its rails") {
    for (const auto& row : table_size_names) {
        const TableSize size = row.value;
        const char* name = row.name;
        INFO(name);
        const Table table = make_table(size);
        const PhysicsParams params = physics_for_table(size);
        const double R = params.ball_radius;
        const core::OpenField field = core::open_field(table, R);
        // The long band between the pockets and the two halves either side of the middle ones.
        REQUIRE(field.count == 3);
        const core::Box bed{{R, R}, {table.length - R, table.width - R}};
        for (int k = 0; k < field.count; ++k)
            CHECK(inside(field.boxes[k], bed));
        // Its middle is open; the pockets are not, nor a path to within a radius of a rail.
        const Vec2 middle{table.length / 2, table.width / 2};
        CHECK(field.holds({middle, middle}));
        for (const Pocket& pocket : table.pockets)
            CHECK_FALSE(field.holds({pocket.position, pocket.position}));
        const double x = table.length / 4;
        CHECK(field.holds({{x, R + 0.001}, {x, table.width / 2}}));
        CHECK_FALSE(field.holds({{x, R}, {x, table.width / 2}}));
    }
}

TEST_CASE("a ball whose reach lies in the open field has its transition next, as the table "
          "search finds, in every cloth model") {
    Random rng(27);
    int held = 0, searched = 0;
    for (const auto& row : table_size_names) {
        const TableSize size = row.value;
        const char* name = row.name;
        const Table table = make_table(size);
        for (std::uint64_t kind = 0; kind < 4; ++kind) {
            INFO(name << ", cloth " << kind);
            PhysicsParams params = physics_for_table(size);
            if (kind > 0) // the classic models: decay, constant, combined
                params.friction = test::random_classic_friction(rng, kind - 1);
            const core::ClothModel cloth = core::cloth_model(params.friction);
            const core::OpenField field = core::open_field(table, params.ball_radius);
            for (int n = 0; n < 500; ++n) {
                Ball b = random_moving_ball(rng, table, params.ball_radius);
                cloth.settle_motion_state(b, params);
                if (!core::is_moving(b))
                    continue;
                const double now = rng.uniform(0, 10);
                const double duration = cloth.time_to_transition(b, params);
                const core::MotionPiece piece{b, now, now + duration,
                                              cloth.acceleration(b, params)};
                const core::Box reach = cloth.reach(piece, duration, params);
                const core::TableSearch found = cloth.table_event(piece, reach, now, table, params);
                ++searched;
                if (!field.holds(reach))
                    continue;
                ++held;
                CHECK(found.event.kind == core::TableEventKind::transition);
                CHECK(found.event.time == piece.end);
                CHECK(inside(found.to_event, reach));
                CHECK(inside(reach, found.to_event));
            }
        }
    }
    // Both sides were seen: balls in the field and balls that reach the table.
    CHECK(held > searched / 10);
    CHECK(held < searched * 9 / 10);
}

TEST_CASE("a table whose rails are not along its axes has no open field") {
    Table table = make_table(TableSize::nine_foot);
    table.cushions[2].normal = normalized(Vec2{0.1, 1});
    CHECK(core::open_field(table, 0.028575).count == 0);
    CHECK_FALSE(core::open_field(table, 0.028575).holds({{1.2, 0.6}, {1.2, 0.6}}));
}
