// What the library gives a researcher besides a shot's events: each event's balls just before
// and just after it, the motion between events sampled without simulating again, the layout
// and parameter checks in the simulator's words.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <termpool/termpool.hpp>

#include "physics_helpers.hpp"

using namespace termpool;
using termpool::test::ball_at;

namespace {

const Table table = make_table(TableSize::nine_foot);

/// A break with every event's state stepped to by a World, to compare the trajectory with.
struct SteppedBreak {
    std::vector<Event> events;
    std::vector<std::vector<Ball>> after; // the balls after each event
    ShotResult result;
    Trajectory trajectory{PhysicsParams{}, 0};
};

SteppedBreak stepped_break(const PhysicsParams& params) {
    const std::vector<Ball> balls = make_rack(table, params, RackType::eight_ball, 3);
    const Strike strike{8, 0.5, 0.1, -0.2, 0};
    SteppedBreak out;
    World world(table, params, balls);
    world.strike(strike);
    while (const auto event = world.step()) {
        out.events.push_back(*event);
        out.after.push_back(world.balls());
    }
    out.trajectory = Trajectory(params, balls.size());
    out.result = simulate_shot(table, params, balls, strike, &out.trajectory);
    return out;
}

} // namespace

TEST_CASE("an event's state after it is the world's right after the event, on every cloth",
          "[physics][event-state]") {
    for (const auto kind : {FrictionKind::physical, FrictionKind::decay, FrictionKind::constant}) {
        PhysicsParams params;
        params.friction.kind = kind;
        params.friction.decay_rate = 0.556;
        params.friction.deceleration = 0.545;
        const SteppedBreak shot = stepped_break(params);
        REQUIRE(shot.events == shot.result.events);
        int collisions = 0;
        for (std::size_t i = 0; i < shot.events.size(); ++i) {
            const Event& e = shot.events[i];
            // Several events at one instant (a ball driven into two at once): the trajectory
            // holds the states before the first and after the last, so only lone events are
            // compared.
            const bool shared = (i + 1 < shot.events.size() && shot.events[i + 1].time == e.time) ||
                                (i > 0 && shot.events[i - 1].time == e.time);
            if (shared)
                continue;
            const auto state = event_state(shot.trajectory, e);
            REQUIRE(state);
            INFO(i << " " << event_kind_name(e.kind) << " " << e.ball << " " << e.other);
            const Ball world_after = test::find_ball(shot.after[i], e.ball);
            CHECK(state->ball_after.position.x == Approx(world_after.position.x).margin(1e-12));
            CHECK(state->ball_after.velocity.x == Approx(world_after.velocity.x).margin(1e-12));
            CHECK(state->ball_after.state == world_after.state);
            if (e.kind == EventKind::ball_ball) {
                ++collisions;
                REQUIRE(state->other_after);
                // The two touch at the instant. (In a rack the contact is resolved with the
                // balls frozen to them, so the pair alone need not keep its momentum; the
                // two-ball case below checks that.)
                const double gap =
                    length(state->ball_before.position - state->other_before->position);
                CHECK(gap == Approx(2 * params.ball_radius).margin(1e-9));
                CHECK(state->other_before->position == state->other_after->position);
            }
        }
        CHECK(collisions > 10);
    }
}

TEST_CASE("a collision's state keeps the pair's momentum and turns it as the model says",
          "[physics][event-state]") {
    for (const auto kind : {FrictionKind::physical, FrictionKind::decay}) {
        PhysicsParams params;
        params.friction.kind = kind;
        params.friction.decay_rate = 0.556;
        Trajectory trajectory(params, 2);
        const ShotResult result =
            simulate_shot(table, params, {ball_at(0, 0.6, 0.6), ball_at(1, 1.2, 0.62)},
                          Strike{2, 0, 0, 0, 0}, &trajectory);
        const auto contact =
            std::find_if(result.events.begin(), result.events.end(),
                         [](const Event& e) { return e.kind == EventKind::ball_ball; });
        REQUIRE(contact != result.events.end());
        const auto state = event_state(trajectory, *contact);
        REQUIRE(state);
        REQUIRE(state->other_before);
        CHECK(length(state->other_before->velocity) == 0);
        CHECK(length(state->other_after->velocity) > 0.5);
        const Vec2 before = state->ball_before.velocity * state->ball_before.mass +
                            state->other_before->velocity * state->other_before->mass;
        const Vec2 after = state->ball_after.velocity * state->ball_after.mass +
                           state->other_after->velocity * state->other_after->mass;
        CHECK(length(after - before) < 1e-12);
        // A cut: the object ball leaves near the line of centres (throw is a few degrees).
        const Vec2 centres = state->other_after->position - state->ball_after.position;
        const Vec2 v = state->other_after->velocity;
        CHECK(std::abs(centres.x * v.y - centres.y * v.x) / (length(centres) * length(v)) < 0.1);
    }
}

TEST_CASE("a trajectory sampled between events is the motion the world steps through",
          "[physics][event-state]") {
    const SteppedBreak shot = stepped_break(PhysicsParams{});
    // Half-way between events the sample equals the state before the next event, which the
    // world reached by stepping from the previous one.
    for (std::size_t i = 0; i + 1 < shot.events.size(); ++i) {
        const double t0 = shot.events[i].time, t1 = shot.events[i + 1].time;
        if (!(t1 > t0))
            continue;
        const std::size_t slot = *shot.trajectory.slot_of(shot.events[i + 1].ball);
        const Ball just_before = shot.trajectory.sample_before(slot, t1);
        const Ball at = shot.trajectory.sample(slot, 0.5 * (t0 + t1));
        // Positions along one piece move monotonically towards the event's.
        CHECK(length(just_before.position - at.position) <=
              length(just_before.position - shot.trajectory.sample(slot, t0).position) + 1e-12);
    }
    // After the last event every ball is where the shot left it.
    const double end = shot.result.rest_time + 1;
    for (const Ball& b : shot.result.balls) {
        const Ball sampled = shot.trajectory.sample(*shot.trajectory.slot_of(b.id), end);
        CHECK(sampled.position == b.position);
        CHECK(sampled.state == b.state);
    }
    CHECK_FALSE(shot.trajectory.slot_of(99));
    const Event foreign{0.1, EventKind::cushion, 99, 0};
    CHECK_FALSE(event_state(shot.trajectory, foreign));
}

TEST_CASE("layout_problem names the first ball off the table or overlapping an earlier one",
          "[physics][event-state]") {
    const double R = PhysicsParams{}.ball_radius;
    CHECK_FALSE(layout_problem(table, {ball_at(0, 1, 0.6), ball_at(1, 1.2, 0.6)}, R));
    const auto off = layout_problem(table, {ball_at(0, 1, 0.6), ball_at(1, 0.01, 0.6)}, R);
    REQUIRE(off);
    CHECK(off->kind == LayoutProblem::Kind::off_table);
    CHECK(off->ball == 1);
    const auto overlap =
        layout_problem(table, {ball_at(0, 1, 0.6), ball_at(4, 2, 0.6), ball_at(1, 1.03, 0.6)}, R);
    REQUIRE(overlap);
    CHECK(overlap->kind == LayoutProblem::Kind::overlap);
    CHECK((overlap->ball == 2 && overlap->other == 0));
    const auto twice = layout_problem(table, {ball_at(3, 1, 0.6), ball_at(3, 2, 0.6)}, R);
    REQUIRE(twice);
    CHECK(twice->kind == LayoutProblem::Kind::same_id);
    // Touching within round-off is allowed: a rack is packed that close.
    CHECK_FALSE(
        layout_problem(table, make_rack(table, PhysicsParams{}, RackType::eight_ball, 1), R));
}

TEST_CASE("physics constants by name are refused in the words of a scenario",
          "[physics][event-state]") {
    PhysicsParams params;
    CHECK_FALSE(set_physics_parameter(params, "u_s", 0.25));
    CHECK(params.sliding_friction == 0.25);
    CHECK(*physics_parameter(params, "u_s") == 0.25);
    CHECK(*set_physics_parameter(params, "e_b", 1.5) == "e_b must be between 0 and 1 (got 1.5)");
    CHECK(params.ball_restitution == PhysicsParams{}.ball_restitution);
    CHECK(*set_physics_parameter(params, "g", 0) == "g must be > 0 (got 0)");
    CHECK(set_physics_parameter(params, "mu", 1)
              ->starts_with("unknown parameter 'mu' (expected "
                            "u_s, u_r, u_sp, e_b, u_b, e_c, "
                            "f_c, w_c, g, R or m)"));
    CHECK_FALSE(set_physics_parameter(params, "u_b", 0.06));
    CHECK(params.ball_friction.model == BallFrictionModel::constant);
    CHECK(*physics_parameter(params, "u_b") == 0.06);
    CHECK_FALSE(physics_parameter(params, "mu"));
}
