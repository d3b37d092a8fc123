// The mirror cushion model: the whole motion reflected, spin included, so a rolling ball leaves
// along the mirror line and stays on it (ideal, which keeps the spin, curls off it).
#include "support/random.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <variant>

#include "cli/scenario.hpp"
#include "core/collision.hpp"
#include "core/physical_cloth.hpp"
#include "physics_helpers.hpp"
#include "stress_shots.hpp"

using namespace termpool;
using termpool::test::ball_at;
using termpool::test::step_until;

namespace {

constexpr double R = 0.028575;
constexpr double degrees = 180.0 / std::numbers::pi;

// Angle of `v` from the normal {0, 1} of the bottom rail, degrees: 30 for a ball leaving it at
// 30 degrees to the normal, towards +x.
double from_normal(Vec2 v) {
    return std::atan2(v.x, v.y) * degrees;
}

// A ball rolling into the bottom rail at `incidence` degrees from its normal, through a world:
// the angle it leaves at, the angle it rolls at once the cloth has had its way, and the worst
// distance of its later centre from the mirror line.
struct Rebound {
    double leaves = 0;
    double rolls = 0;
    double off_line = 0;
};

Rebound rebound(CushionModel model, double incidence) {
    const Table table = make_table(TableSize::nine_foot);
    PhysicsParams p;
    p.cushion = model;
    World world(table, p, {ball_at(0, 0.6, 0.6)});
    world.strike({1.5, -90 + incidence, 0, 0});
    step_until(world, EventKind::rolling);
    const Event hit = step_until(world, EventKind::cushion);
    Rebound r;
    const Ball at_rail = world.balls()[0];
    r.leaves = from_normal(at_rail.velocity);
    const Vec2 line = unit_from_angle((90 - incidence) / degrees); // the mirror line's direction
    auto off_line = [&](Vec2 p) { return std::abs(cross(line, p - at_rail.position)); };
    while (world.balls()[0].state != MotionState::rolling && world.step()) {
    }
    r.rolls = from_normal(world.balls()[0].velocity);
    // Until the next rail: the centre at every event on the way, and where it rests or meets it.
    while (const auto e = world.step()) {
        r.off_line = std::max(r.off_line, off_line(world.balls()[0].position));
        if (e->kind == EventKind::cushion || e->kind == EventKind::jaw)
            break;
    }
    CHECK(hit.time > 0);
    return r;
}

} // namespace

TEST_CASE("mirror cushion: a rolling ball leaves along the mirror line and rolls on it",
          "[physics][cushion]") {
    for (const double incidence : {30.0, 10.0, 45.0, 70.0}) {
        const Rebound r = rebound(CushionModel::mirror, incidence);
        INFO("incidence " << incidence);
        CHECK(r.leaves == Approx(incidence).margin(1e-9));
        CHECK(r.rolls == Approx(incidence).margin(1e-9));
        CHECK(r.off_line < 1e-9);
    }
}

TEST_CASE("ideal cushion keeps the spin: 30 degrees in, 30 out, then it curls to 53.4",
          "[physics][cushion]") {
    const Rebound r = rebound(CushionModel::ideal, 30);
    CHECK(r.leaves == Approx(30).margin(1e-9));
    CHECK(r.rolls == Approx(53.4).margin(0.05));
}

TEST_CASE("mirror cushion reflects the spin as an axial vector", "[physics][cushion]") {
    PhysicsParams p;
    p.cushion = CushionModel::mirror;
    Ball b = ball_at(0, 1, 1);
    b.velocity = {0.3, -1.2};
    b.angular_velocity = {11, -7, 23};
    b.state = MotionState::sliding;
    const double before = kinetic_energy(b, R);
    core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
    // The rail is the plane y = const: velocity y flips; spin keeps y, flips x and z.
    CHECK(b.velocity.x == 0.3);
    CHECK(b.velocity.y == 1.2);
    CHECK(b.angular_velocity.x == -11);
    CHECK(b.angular_velocity.y == -7);
    CHECK(b.angular_velocity.z == -23);
    CHECK(kinetic_energy(b, R) == Approx(before).epsilon(1e-15));
}

TEST_CASE("scenario: cushion mirror", "[scenario][cushion]") {
    const auto r = cli::parse_scenario("cushion mirror\n");
    REQUIRE(std::holds_alternative<cli::Scenario>(r));
    CHECK(std::get<cli::Scenario>(r).setup.physics.cushion == CushionModel::mirror);
    const auto bad = cli::parse_scenario("cushion bouncy\n");
    REQUIRE(std::holds_alternative<cli::ScenarioError>(bad));
    CHECK(std::get<cli::ScenarioError>(bad).message ==
          "unknown cushion model 'bouncy' (expected physical, ideal or mirror)");
    const auto collision = cli::parse_scenario("collision mirror\n");
    REQUIRE(std::holds_alternative<cli::ScenarioError>(collision));
    CHECK(std::get<cli::ScenarioError>(collision).message ==
          "unknown collision model 'mirror' (expected physical or ideal)");
}

TEST_CASE("random shots off mirror cushions: apart, on the table, no energy made, deterministic",
          "[physics][stress][cushion]") {
    int failures = 0, long_shots = 0;
    for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
        test::StressShot shot = test::make_stress_shot(seed);
        shot.params.cushion = CushionModel::mirror;
        const test::StressReport r = test::check_stress_shot(shot);
        INFO("seed " << seed << ": " << test::stress_failure_name(r.failure) << " " << r.detail);
        CHECK(r.failure == test::StressFailure::none);
        failures += r.failure != test::StressFailure::none;
        long_shots += r.events > test::long_shot_events;
    }
    CHECK(failures == 0);
    CHECK(long_shots == 0);
}
