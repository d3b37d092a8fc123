// Closed forms of the ball-cloth models: sliding, rolling, spinning, and the classic models (the
// seed report's).
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>

#include "physics_helpers.hpp"

using namespace termpool;
using termpool::test::ball_at;
using termpool::test::find_ball;
using termpool::test::step_until;

namespace {

const Table table = make_table(TableSize::nine_foot);

double relative_error(double got, double want) {
    return std::abs(got - want) / std::abs(want);
}

} // namespace

TEST_CASE("a stun shot turns to rolling after 2 v0 / (7 u_s g) at 5/7 v0", "[physics][motion]") {
    const PhysicsParams p;
    for (const double v0 : {0.5, 1.0, 2.0, 3.0}) {
        World world(table, p, {ball_at(0, 0.3, 0.6)});
        world.strike({v0, 0, 0, 0});
        const Event e = step_until(world, EventKind::rolling);
        const double t = 2 * v0 / (7 * p.sliding_friction * p.gravity);
        CHECK(relative_error(e.time, t) < 1e-9);
        const Ball b = world.balls()[0];
        CHECK(relative_error(b.velocity.x, 5.0 / 7.0 * v0) < 1e-9);
        CHECK(std::abs(b.velocity.y) < 1e-12);
        // Rolling means the contact point is at rest.
        CHECK(std::abs(b.velocity.x - p.ball_radius * b.angular_velocity.y) < 1e-12);
    }
}

TEST_CASE("a rolling ball stops after v / (u_r g) having gone v^2 / (2 u_r g)",
          "[physics][motion]") {
    const PhysicsParams p;
    for (const double v : {0.1, 0.3, 0.5}) {
        World world(table, p, {ball_at(0, 0.3, 0.6)});
        // A tip offset of 2/5 R gives natural roll at once.
        world.strike({v, 0, 0, 0.4});
        REQUIRE(world.balls()[0].state == MotionState::rolling);
        const Event e = step_until(world, EventKind::stopped);
        const double g = p.gravity, ur = p.rolling_friction;
        CHECK(relative_error(e.time, v / (ur * g)) < 1e-9);
        const Ball b = world.balls()[0];
        CHECK(relative_error(b.position.x - 0.3, v * v / (2 * ur * g)) < 1e-9);
        CHECK(b.state == MotionState::stationary);
    }
}

TEST_CASE("a stop shot with english leaves the cue ball spinning in place", "[physics][motion]") {
    PhysicsParams p;
    p.collision = CollisionModel::ideal;
    // Squirt would send the cue ball off the line of centres: a cut, not a stop shot.
    p.cue_end_mass = 0;
    // Close enough that the cue ball arrives with no top or bottom spin.
    World world(table, p, {ball_at(0, 1.0, 0.6), ball_at(1, 1.0 + 2 * p.ball_radius + 1e-4, 0.6)});
    world.strike({1.0, 0, 0.5, 0});
    const Event hit = step_until(world, EventKind::ball_ball);
    const Ball cue = find_ball(world.balls(), 0);
    CHECK(length(cue.velocity) < 1e-3);
    CHECK(cue.angular_velocity.z > 0); // right english: counter-clockwise seen from above
    // The little top spin it picked up on the way creeps it forward; then it spins in place.
    Event spinning;
    while ((spinning = step_until(world, EventKind::spinning)).ball != 0) {
    }
    Event stopped;
    while ((stopped = step_until(world, EventKind::stopped)).ball != 0) {
    }
    CHECK(stopped.time > spinning.time);
    // The vertical spin decays at the same rate whatever the ball does.
    const double rate = 5 * p.gravity * p.spin_friction / (2 * p.ball_radius);
    CHECK(relative_error(stopped.time - hit.time, cue.angular_velocity.z / rate) < 1e-9);
    CHECK(length(find_ball(world.balls(), 0).position - cue.position) < 1e-3);
}

TEST_CASE("the classic friction models follow their closed forms", "[physics][motion][classic]") {
    PhysicsParams p;
    const double v0 = 0.8;
    SECTION("decay: v shrinks by e^(-K t)") {
        p.friction = {FrictionKind::decay, 1.5, 0, 0.005};
        World world(table, p, {ball_at(0, 0.3, 0.6)});
        world.strike({v0, 0, 0, 0});
        const Event e = step_until(world, EventKind::stopped);
        const double t = std::log(v0 / 0.005) / 1.5;
        CHECK(relative_error(e.time, t) < 1e-9);
        const double distance = v0 * (1 - std::exp(-1.5 * t)) / 1.5;
        CHECK(relative_error(world.balls()[0].position.x - 0.3, distance) < 1e-9);
    }
    SECTION("constant: deceleration A") {
        p.friction = {FrictionKind::constant, 0, 0.4, 0.005};
        World world(table, p, {ball_at(0, 0.3, 0.6)});
        world.strike({v0, 0, 0, 0});
        const Event e = step_until(world, EventKind::stopped);
        const double t = (v0 - 0.005) / 0.4;
        CHECK(relative_error(e.time, t) < 1e-9);
        CHECK(relative_error(world.balls()[0].position.x - 0.3, v0 * t - 0.2 * t * t) < 1e-9);
    }
    SECTION("combined: decay while it slows more, then constant") {
        p.friction = {FrictionKind::combined, 1.0, 0.3, 0.005};
        World world(table, p, {ball_at(0, 0.3, 0.6)});
        world.strike({v0, 0, 0, 0});
        const Event e = step_until(world, EventKind::stopped);
        // K v > A until v = A / K = 0.3 m/s.
        const double t = std::log(v0 / 0.3) + (0.3 - 0.005) / 0.3;
        CHECK(relative_error(e.time, t) < 1e-9);
    }
    SECTION("the classic models carry no spin") {
        p.friction = {FrictionKind::decay, 1.0, 0, 0.005};
        World world(table, p, {ball_at(0, 0.3, 0.6)});
        world.strike({v0, 0, 0.5, 0.5});
        const Ball b = world.balls()[0];
        CHECK(b.angular_velocity == Vec3{});
        CHECK(b.state == MotionState::rolling);
    }
}

TEST_CASE("a classic ball that a contact leaves at rest is reported stopped at the contact",
          "[physics][motion][classic]") {
    // Issue 28: the stop came with no event when the contact, not the cloth, took the last of
    // the ball's speed. A stop shot: the cue ball gives all its speed to the object ball.
    for (const FrictionKind kind :
         {FrictionKind::decay, FrictionKind::constant, FrictionKind::combined}) {
        INFO(static_cast<int>(kind));
        PhysicsParams p;
        p.friction = {kind, 1.0, 0.3, 0.005};
        p.collision = CollisionModel::ideal;
        World world(table, p, {ball_at(0, 1.0, 0.6), ball_at(1, 1.3, 0.6)});
        world.strike({1.0, 0, 0, 0});
        const Event hit = step_until(world, EventKind::ball_ball);
        REQUIRE(find_ball(world.balls(), 0).state == MotionState::stationary);
        const std::optional<Event> next = world.step();
        REQUIRE(next);
        CHECK(*next == Event{hit.time, EventKind::stopped, 0, 0});
        const Event later = step_until(world, EventKind::stopped);
        CHECK(later.ball == 1);
        CHECK(later.time > hit.time);
        CHECK_FALSE(world.step());
    }
    // The shot: a ball that a cushion leaves slower than the rest speed.
    PhysicsParams p;
    p.friction = {FrictionKind::constant, 0, 0.001, 0.005};
    World world(table, p, {ball_at(0, 2.5, 0.6)});
    world.strike({0.0072, 0, 0, 0});
    const Event cushion = step_until(world, EventKind::cushion);
    const std::optional<Event> next = world.step();
    REQUIRE(next);
    CHECK(*next == Event{cushion.time, EventKind::stopped, 0, 0});
    CHECK(find_ball(world.balls(), 0).state == MotionState::stationary);
    CHECK_FALSE(world.step());
}

TEST_CASE("a trajectory samples the same states the world stepped through",
          "[physics][trajectory]") {
    const PhysicsParams p;
    World world(table, p, make_rack(table, p, RackType::eight_ball, 3));
    world.record(true);
    world.strike({8, 1.5, 0.1, -0.2});
    std::vector<std::pair<double, std::vector<Ball>>> snapshots;
    while (world.step())
        snapshots.emplace_back(world.time(), world.balls());
    REQUIRE(snapshots.size() > 20);
    for (std::size_t k = 0; k < snapshots.size(); ++k) {
        const auto& [t, balls] = snapshots[k];
        // Events at one instant (two balls that a contact left with slips of one length start
        // rolling together) are stepped one by one, but the state at that time is the one after
        // all of them: compare the last snapshot of each instant.
        if (k + 1 < snapshots.size() && snapshots[k + 1].first == t)
            continue;
        const std::vector<Ball> sampled = world.trajectory().sample(t);
        REQUIRE(sampled.size() == balls.size());
        for (std::size_t i = 0; i < balls.size(); ++i) {
            CHECK(length(sampled[i].position - balls[i].position) < 1e-12);
            CHECK(sampled[i].state == balls[i].state);
        }
    }
    // Between events too: halfway through the shot every ball is somewhere on the table.
    for (const Ball& b : world.trajectory().sample(snapshots.back().first / 2)) {
        if (b.state != MotionState::pocketed)
            CHECK(on_playing_surface(table, b.position, p.ball_radius));
    }
}
