// Ball-ball and ball-cushion contacts, checked through the world as a shot would meet them.
#include "support/random.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/collision.hpp"
#include "core/physical_cloth.hpp"
#include "physics_helpers.hpp"

using namespace termpool;
using termpool::test::ball_at;
using termpool::test::find_ball;
using termpool::test::step_until;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double R = 0.028575;
constexpr double degrees = 180.0 / std::numbers::pi;

double angle_deg(Vec2 v) {
    return std::atan2(v.y, v.x) * degrees;
}

// Cue ball on the long axis, an object ball `gap` ahead of contact and `offset` across.
World straight_setup(const PhysicsParams& p, double gap, double offset = 0, double m0 = 0.170,
                     double m1 = 0.170) {
    return World(table, p,
                 {ball_at(0, 0.5, 0.635, m0), ball_at(1, 0.5 + 2 * R + gap, 0.635 + offset, m1)});
}

} // namespace

TEST_CASE("ideal head-on hit between equal balls exchanges velocities", "[physics][collision]") {
    PhysicsParams p;
    p.collision = CollisionModel::ideal;
    World world = straight_setup(p, 0.2);
    world.strike({2, 0, 0, 0});
    const Event e = step_until(world, EventKind::ball_ball);
    REQUIRE(e.ball == 0);
    REQUIRE(e.other == 1);
    // The cue ball still slides when it arrives (it needs 0.29 s to roll), so its speed then
    // follows from the closed form.
    const double arriving = 2 - p.sliding_friction * p.gravity * e.time;
    const auto balls = world.balls();
    CHECK(length(find_ball(balls, 0).velocity) < 1e-9);
    CHECK(find_ball(balls, 1).velocity.x == Approx(arriving).epsilon(1e-12));
    CHECK(std::abs(find_ball(balls, 1).velocity.y) < 1e-12);
}

TEST_CASE("ball-ball contacts conserve momentum and follow the 1D formulas",
          "[physics][collision]") {
    for (const auto model : {CollisionModel::ideal, CollisionModel::physical}) {
        for (const double m1 : {0.136, 0.170, 0.255}) {
            PhysicsParams p;
            p.collision = model;
            const double m0 = 0.170;
            Ball a = ball_at(0, 1.0, 0.6, m0), b = ball_at(1, 1.0 + 2 * R, 0.6, m1);
            a.velocity = {1.5, 0};
            a.state = MotionState::sliding;
            core::resolve_ball_ball(a, b, p, core::cloth_model(p.friction));
            const double e = model == CollisionModel::ideal ? 1.0 : p.ball_restitution;
            const double v = 1.5;
            CHECK(a.velocity.x == Approx((m0 - e * m1) * v / (m0 + m1)).epsilon(1e-12));
            CHECK(b.velocity.x == Approx((1 + e) * m0 * v / (m0 + m1)).epsilon(1e-12));
            // Separation speed is e times approach speed.
            CHECK(b.velocity.x - a.velocity.x == Approx(e * v).epsilon(1e-12));
            CHECK(m0 * a.velocity.x + m1 * b.velocity.x == Approx(m0 * v).epsilon(1e-12));
        }
    }
}

TEST_CASE("a head-on physical hit separates at e_b times the approach speed in a shot",
          "[physics][collision]") {
    PhysicsParams p;
    World world = straight_setup(p, 0.001);
    world.strike({3, 0, 0, 0});
    const Ball cue_before = world.balls()[0];
    step_until(world, EventKind::ball_ball);
    // 1 mm of sliding at 3 m/s barely slows the cue ball: compute it exactly from the closed form.
    const double t = world.time();
    const double approach = 3 - p.sliding_friction * p.gravity * t;
    const auto balls = world.balls();
    CHECK(find_ball(balls, 1).velocity.x - find_ball(balls, 0).velocity.x ==
          Approx(p.ball_restitution * approach).epsilon(1e-9));
    CHECK(cue_before.velocity.x == 3);
}

TEST_CASE("half-ball hit with a rolling cue ball: 33.7 degrees (the 30-degree rule)",
          "[physics][collision]") {
    PhysicsParams p;
    p.collision = CollisionModel::ideal;
    for (const double speed : {0.5, 1.0, 2.0}) {
        for (const double side : {1.0, -1.0}) {
            World world = straight_setup(p, 0.3, side * R);
            world.strike({speed, 0, 0, 0.4}); // natural roll from the start
            REQUIRE(world.balls()[0].state == MotionState::rolling);
            step_until(world, EventKind::ball_ball);
            // The cue ball slides off the tangent line and bends until it rolls again.
            Event e;
            while ((e = step_until(world, EventKind::rolling)).ball != 0) {
            }
            const Ball cue = find_ball(world.balls(), 0);
            CHECK(std::abs(angle_deg(cue.velocity)) == Approx(33.7).margin(0.3));
            CHECK(angle_deg(cue.velocity) * side < 0); // deflected away from the object ball
        }
    }
}

TEST_CASE("ideal stun shot sends the balls off at 90 degrees", "[physics][collision]") {
    PhysicsParams p;
    p.collision = CollisionModel::ideal;
    for (const double offset : {0.3, 0.5, 1.0, 1.7}) {
        // Close enough that the cue ball still slides with no spin when it arrives.
        World world = straight_setup(p, 1e-4, offset * R);
        world.strike({2, 0, 0, 0});
        step_until(world, EventKind::ball_ball);
        const auto balls = world.balls();
        const Vec2 v0 = find_ball(balls, 0).velocity, v1 = find_ball(balls, 1).velocity;
        const double angle = std::acos(dot(v0, v1) / (length(v0) * length(v1))) * degrees;
        CHECK(angle == Approx(90).margin(0.05));
    }
}

TEST_CASE("ideal cushion: angle in equals angle out", "[physics][cushion]") {
    PhysicsParams p;
    p.cushion = CushionModel::ideal;
    for (const double incoming : {-30.0, -45.0, -60.0, -89.0}) {
        Ball b = ball_at(0, 1.0, R);
        b.velocity = unit_from_angle(incoming / degrees) * 1.5;
        b.state = MotionState::sliding;
        core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
        CHECK(angle_deg(b.velocity) == Approx(-incoming).margin(1e-9));
        CHECK(length(b.velocity) == Approx(1.5).epsilon(1e-12));
    }
    // And in a shot: the ball meets the bottom rail and comes back up.
    World world(table, p, {ball_at(0, 0.6, 0.3)});
    world.strike({1.5, -45, 0, 0});
    const Event e = step_until(world, EventKind::cushion);
    CHECK(e.other == 0);
    CHECK(world.balls()[0].position.y == Approx(R).margin(1e-12));
    CHECK(world.balls()[0].velocity.y > 0);
}

TEST_CASE("physical cushion never adds energy", "[physics][cushion][property]") {
    const PhysicsParams p;
    Random rng(42);
    int rebounds = 0;
    for (int i = 0; i < 100000; ++i) {
        Ball b = test::random_cushion_approach(rng, R);
        const double before = kinetic_energy(b, R);
        core::resolve_cushion(b, {1, 0}, p, core::cloth_model(p.friction));
        CHECK(kinetic_energy(b, R) <= before + 1e-12);
        CHECK(b.velocity.x < 0);
        rebounds += b.velocity.x < 0;
    }
    CHECK(rebounds == 100000);
}

TEST_CASE("physical cushion: a rolling ball comes off slower and at a steeper angle than ideal",
          "[physics][cushion]") {
    const PhysicsParams p;
    Ball b = ball_at(0, 1, 1);
    b.velocity = unit_from_angle(-45 / degrees) * 1.0;
    b.angular_velocity = {-b.velocity.y / R, b.velocity.x / R, 0}; // rolling
    b.state = MotionState::rolling;
    core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
    CHECK(b.velocity.y > 0);
    CHECK(b.velocity.y < 0.707 * p.cushion_restitution + 0.05);
    CHECK(length(b.velocity) < 1.0);
}

TEST_CASE("a slow push leaves both balls rolling at the speed their cloth momentum allows",
          "[physics][collision]") {
    PhysicsParams p;
    // Ball-ball friction would turn the balls too: keep to the cloth.
    p.ball_friction = {.model = BallFrictionModel::constant, .constant = 0};
    // The rear ball has twice the top spin rolling needs and barely catches the one ahead.
    Ball a = ball_at(0, 1.0, 0.6), b = ball_at(1, 1.0 + 2 * R, 0.6);
    a.velocity = {1.0, 0};
    a.angular_velocity = {0, 2.0 / R, 0};
    a.state = MotionState::sliding;
    b.velocity = {0.998, 0};
    b.angular_velocity = {0, 0.998 / R, 0};
    b.state = MotionState::rolling;
    auto cloth_momentum = [](const Ball& x) {
        return x.mass * (x.velocity.x + 0.4 * R * x.angular_velocity.y);
    };
    const double before = cloth_momentum(a) + cloth_momentum(b);
    const double energy = kinetic_energy(a, R) + kinetic_energy(b, R);
    core::resolve_ball_ball(a, b, p, core::cloth_model(p.friction));
    // Rolling at one speed (but for the parting at min_separation_speed), the one their cloth
    // momentum gives.
    CHECK(cloth_momentum(a) + cloth_momentum(b) == Approx(before).epsilon(1e-9));
    CHECK(a.velocity.x == Approx(before / (1.4 * (a.mass + b.mass))).epsilon(1e-5));
    CHECK(length(core::slip_velocity(a, R)) < 1e-5);
    CHECK(length(core::slip_velocity(b, R)) < 1e-5);
    CHECK(kinetic_energy(a, R) + kinetic_energy(b, R) <= energy);
    CHECK(b.velocity.x - a.velocity.x >= core::min_separation_speed * 0.999);
}

TEST_CASE("balls pressed together in a break do not bounce off each other endlessly",
          "[physics][collision]") {
    const PhysicsParams p;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        const ShotResult r =
            simulate_shot(table, p, make_rack(table, p, RackType::eight_ball, seed), {12, 0, 0, 0});
        int contacts = 0;
        for (const Event& e : r.events)
            contacts += e.kind == EventKind::ball_ball;
        INFO("seed " << seed);
        CHECK(contacts < 150);
    }
}
