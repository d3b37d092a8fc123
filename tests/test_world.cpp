// Whole shots: no tunnelling, energy and momentum, determinism, and a large property test.
#include "support/random.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/cloth_model.hpp"
#include "physics_helpers.hpp"

using namespace termpool;
using termpool::test::ball_at;
using termpool::test::find_ball;
using termpool::test::step_until;
using termpool::test::total_energy;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double R = 0.028575;

double smallest_gap(const std::vector<Ball>& balls) {
    double gap = 1e9;
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j) {
            if (balls[i].state == MotionState::pocketed || balls[j].state == MotionState::pocketed)
                continue;
            gap = std::min(gap, length(balls[i].position - balls[j].position) - 2 * R);
        }
    return gap;
}

Vec2 momentum(const Ball& a, const Ball& b) {
    return a.velocity * a.mass + b.velocity * b.mass;
}

} // namespace

TEST_CASE("balls 1 mm apart at 20 m/s collide", "[physics][tunnelling]") {
    for (const auto model : {FrictionKind::physical, FrictionKind::decay, FrictionKind::constant,
                             FrictionKind::combined}) {
        PhysicsParams p;
        p.friction = {model, 0.5, 0.5, 0.005};
        World world(table, p, {ball_at(0, 1.0, 0.6), ball_at(1, 1.0 + 2 * R + 0.001, 0.6)});
        world.strike({20, 0, 0, 0});
        const Event e = step_until(world, EventKind::ball_ball);
        CHECK(e.ball == 0);
        CHECK(e.time == Approx(0.001 / 20).epsilon(1e-3));
        CHECK(smallest_gap(world.balls()) > -1e-9);
    }
}

TEST_CASE("a ball at 20 m/s into a cushion or a jaw bounces or drops, never leaves the table",
          "[physics][tunnelling]") {
    for (const auto model : {FrictionKind::physical, FrictionKind::decay, FrictionKind::constant,
                             FrictionKind::combined}) {
        PhysicsParams p;
        p.friction = {model, 0.5, 0.5, 0.005};
        // Straight at every rail, at each pocket's jaws and points, and a fan of angles.
        std::vector<double> angles;
        for (int k = 0; k < 360; ++k)
            angles.push_back(k + 0.37);
        for (const double angle : angles) {
            for (const Vec2 start : {Vec2{0.3, 0.3}, Vec2{1.27, 0.2}, Vec2{2.0, 1.0}}) {
                Trajectory trajectory(p, 1);
                const ShotResult r = simulate_shot(table, p, {ball_at(0, start.x, start.y)},
                                                   {20, angle, 0.3, -0.3}, &trajectory);
                REQUIRE_FALSE(r.event_limit_hit);
                const Ball b = r.balls[0];
                if (b.state != MotionState::pocketed)
                    CHECK(on_playing_surface(table, b.position, R));
                // Sampled at k/200 of the shot, k < 200: a sum of steps could land ulps before
                // the last event, a capture, where the centre is on the capture line itself.
                for (int k = 0; k < 200; ++k) {
                    const Ball s = trajectory.sample(r.rest_time * k / 200)[0];
                    if (s.state != MotionState::pocketed)
                        CHECK(on_playing_surface(table, s.position, R));
                }
            }
        }
    }
}

TEST_CASE("a ball driven into a jaw point rattles off it", "[physics][jaw]") {
    const PhysicsParams p;
    // The left point of side pocket 2, met by a ball whose centre passes just inside the mouth.
    const Vec2 point = table.jaw_points[2 * 1 + 1];
    World world(table, p, {ball_at(0, point.x + 0.01, 0.5)});
    world.strike({3, -90, 0, 0});
    const Event e = step_until(world, EventKind::jaw);
    CHECK(e.other == 2);
    CHECK(length(world.balls()[0].position - point) == Approx(R).margin(1e-9));
}

TEST_CASE("a ball rolled into the mouth of a pocket drops", "[physics][pocket]") {
    const PhysicsParams p;
    for (int pocket = 1; pocket <= 6; ++pocket) {
        const Vec2 target = table.pockets[pocket - 1].position;
        const Vec2 from{table.length / 2 + (target.x - table.length / 2) * 0.5,
                        table.width / 2 + (target.y - table.width / 2) * 0.5 +
                            (pocket == 2 || pocket == 5 ? 0 : 0)};
        const Vec2 d = target - from;
        const double angle = std::atan2(d.y, d.x) * 180 / std::numbers::pi;
        const ShotResult r =
            simulate_shot(table, p, {ball_at(0, from.x, from.y)}, {3, angle, 0, 0});
        REQUIRE_FALSE(r.events.empty());
        CHECK(r.balls[0].state == MotionState::pocketed);
        CHECK(r.balls[0].pocket == pocket);
    }
}

TEST_CASE("the same shot twice gives identical events and final states", "[physics][determinism]") {
    const PhysicsParams p;
    const auto rack = make_rack(table, p, RackType::eight_ball, 11);
    const ShotResult a = simulate_shot(table, p, rack, {12, 0.2, 0, 0});
    const ShotResult b = simulate_shot(table, p, rack, {12, 0.2, 0, 0});
    CHECK(a.events == b.events);
    CHECK(a.balls == b.balls);
    CHECK(a.rest_time == b.rest_time);
    CHECK(a.events.size() > 30);
}

TEST_CASE("a world copied into another in the middle of a shot steps on as the original does",
          "[physics][determinism]") {
    const PhysicsParams p;
    PhysicsParams other_cloth;
    other_cloth.sliding_friction = 0.25;
    const auto rack = make_rack(table, p, RackType::eight_ball, 11);
    // The rest of the shot, events and final balls, from `world` as it stands.
    auto finish = [](World& world) {
        std::vector<Event> events;
        while (const auto e = world.step())
            events.push_back(*e);
        return std::make_pair(events, world.balls());
    };
    for (const bool recording : {false, true}) {
        World original(table, p, rack);
        original.record(recording);
        original.strike({12, 0.2, 0, 0});
        for (int k = 0; k < 40; ++k)
            original.step();
        // Into worlds of as many balls that hold other contacts (struck otherwise and stepped
        // part way), that recorded or not, and that have other physics.
        for (const bool target_recorded : {false, true}) {
            for (const PhysicsParams& target_params : {p, other_cloth}) {
                World copy(table, target_params,
                           make_rack(table, target_params, RackType::eight_ball, 12));
                copy.record(target_recorded);
                copy.strike({9, -0.4, 0.1, 0});
                for (int k = 0; k < 25; ++k)
                    copy.step();
                copy = original;
                World same = original; // into new memory
                // Its trajectory, empty or not, is for the original's physics: a sliding piece
                // added to a copy of it moves as one added to the original's does.
                Trajectory from_copy = copy.trajectory(), from_same = same.trajectory();
                Ball slider = rack[0];
                slider.state = MotionState::sliding;
                slider.velocity = {1, 0};
                from_copy.add(0, 100, slider);
                from_same.add(0, 100, slider);
                CHECK(from_copy.sample(0, 100.5) == from_same.sample(0, 100.5));
                // Recording from here on: a copy that had not recorded starts a trajectory of
                // the original's physics.
                copy.record(true);
                same.record(true);
                INFO("recording " << recording << ", target recorded " << target_recorded
                                  << ", other physics " << (&target_params == &other_cloth));
                const auto want = finish(same);
                const auto got = finish(copy);
                CHECK(got.first == want.first);
                CHECK(got.second == want.second);
                CHECK(want.first.size() > 20);
                const double end = same.time();
                for (int k = 0; k <= 10; ++k)
                    CHECK(copy.trajectory().sample(end * k / 10) ==
                          same.trajectory().sample(end * k / 10));
            }
        }
    }
}

TEST_CASE("a break spreads the rack and comes to rest", "[physics][break]") {
    const PhysicsParams p;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const auto rack = make_rack(table, p, RackType::eight_ball, seed);
        const ShotResult r = simulate_shot(table, p, rack, {12, 0, 0, 0});
        CHECK_FALSE(r.event_limit_hit);
        CHECK(r.rest_time > 2);
        CHECK(r.rest_time < 40);
        int cushions = 0;
        for (const Event& e : r.events)
            cushions += e.kind == EventKind::cushion;
        CHECK(cushions >= 4);
    }
}

namespace {

// One random shot: a random layout of 1..16 balls, a random strike, a random model. Checks after
// every event, and at sampled times between events, the invariants the simulator promises.
void check_random_shot(std::uint64_t seed, bool sample_between) {
    Random rng(seed);
    PhysicsParams p;
    // Half the shots on a classic cloth, the others on the physical one.
    if (const std::uint64_t kind = rng.below(6); kind < 3)
        p.friction = test::random_classic_friction(rng, kind);
    if (rng.below(4) == 0)
        p.collision = CollisionModel::ideal;
    if (rng.below(4) == 0)
        p.cushion = CushionModel::ideal;
    const bool classic_model = p.friction.kind != FrictionKind::physical;

    std::vector<Ball> balls;
    const int count = 1 + static_cast<int>(rng.below(classic_model ? 6 : 16));
    for (int id = 0; id < count; ++id) {
        for (int attempt = 0; attempt < 100; ++attempt) {
            const Ball b = ball_at(id, rng.uniform(R, table.length - R),
                                   rng.uniform(R, table.width - R), rng.uniform(0.12, 0.25));
            if (smallest_gap([&] {
                    auto all = balls;
                    all.push_back(b);
                    return all;
                }()) >= 0) {
                balls.push_back(b);
                break;
            }
        }
    }
    const Strike strike{rng.uniform(0, 20), rng.uniform(0, 360), rng.uniform(-0.5, 0.5),
                        rng.uniform(-0.5, 0.5)};

    World world(table, p, balls);
    const core::ClothModel cloth = core::cloth_model(p.friction);
    if (sample_between)
        world.record(true);
    world.strike(strike);
    double energy = total_energy(world.balls(), R);
    std::size_t events = 0;
    while (true) {
        const std::vector<Ball> before = world.balls();
        const double before_time = world.time();
        const auto e = world.step();
        if (!e)
            break;
        ++events;
        const std::vector<Ball> after = world.balls();
        INFO("seed " << seed << " event " << events << " " << event_kind_name(e->kind));
        REQUIRE(smallest_gap(after) > -1e-9);
        for (const Ball& b : after)
            if (b.state != MotionState::pocketed)
                REQUIRE(on_playing_surface(table, b.position, R));
        const double now = total_energy(after, R);
        REQUIRE(now <= energy + 1e-12);
        energy = now;
        if (e->kind == EventKind::ball_ball) {
            // Neither ball changed its motion since the last event, so advancing their states
            // from then gives the motion just before the contact.
            const double dt = e->time - before_time;
            const Ball a0 = cloth.advance(find_ball(before, e->ball), dt, p);
            const Ball b0 = cloth.advance(find_ball(before, e->other), dt, p);
            const Vec2 p0 = momentum(a0, b0);
            const Vec2 p1 = momentum(find_ball(after, e->ball), find_ball(after, e->other));
            // The classic models stop a ball left slower than their rest speed.
            double stopped_mass = 0;
            for (const int id : {e->ball, e->other}) {
                const Ball b = find_ball(after, id);
                if (classic_model && b.state == MotionState::stationary)
                    stopped_mass += b.mass;
            }
            // A slow contact where the cloth presses the balls together is a push, resolved
            // with the cloth's help (see resolve_physical_push): momentum is not the pair's alone.
            const Vec2 n = normalized(b0.position - a0.position);
            const bool push =
                !classic_model && dot(a0.velocity - b0.velocity, n) < p.elastic_below_speed;
            if (!push) {
                REQUIRE(length(p1 - p0) <=
                        1e-12 * (1 + length(p0)) + stopped_mass * p.friction.rest_speed);
            }
        }
    }
    INFO("seed " << seed);
    REQUIRE(world.at_rest());
    if (sample_between) {
        const double end = world.time();
        for (int k = 1; k < 50; ++k) {
            const auto sampled = world.trajectory().sample(end * k / 50);
            REQUIRE(smallest_gap(sampled) > -1e-9);
            for (const Ball& b : sampled)
                if (b.state != MotionState::pocketed)
                    REQUIRE(on_playing_surface(table, b.position, R));
        }
    }
}

} // namespace

TEST_CASE("2,000 random shots keep every ball apart, on the table, and reach rest",
          "[physics][property]") {
    for (std::uint64_t seed = 1; seed <= 2000; ++seed)
        check_random_shot(seed, seed % 20 == 0);
}

// `make soak` (the [.soak] tag, hidden from `make test`): the same checks over 100,000 more.
TEST_CASE("make soak: 100,000 more random shots keep every ball apart, on the table, and reach "
          "rest",
          "[physics][property][.soak]") {
    for (std::uint64_t seed = 2001; seed <= 102000; ++seed)
        check_random_shot(seed, seed % 20 == 0);
}
