// The snooker table, its balls and its rack: dimensions and pocket mouths, the physics a table
// gives, the rack's layout, scenarios on the snooker table, and the simulator kept exact with
// 22 balls on a break and on random shots.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <termpool/match.hpp>
#include <termpool/rack.hpp>
#include <termpool/record.hpp>
#include <termpool/setup.hpp>
#include <termpool/simulator.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>

#include "cli/scenario.hpp"
#include "stress_shots.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

const PhysicsParams snooker_params = physics_for_table(TableSize::snooker);

Table snooker_table() {
    return make_table(TableSize::snooker, snooker_params.ball_radius);
}

// The width of a pocket's mouth: between the points where the rails turn into its jaws.
double mouth_width(const Table& table, int pocket) {
    std::vector<Vec2> points;
    for (std::size_t i = 0; i < table.jaw_points.size(); ++i)
        if (table.jaw_point_pocket[i] == pocket)
            points.push_back(table.jaw_points[i]);
    REQUIRE(points.size() == 2);
    return length(points[0] - points[1]);
}

const Ball* find(const std::vector<Ball>& balls, int id) {
    const auto it =
        std::find_if(balls.begin(), balls.end(), [&](const Ball& b) { return b.id == id; });
    return it == balls.end() ? nullptr : &*it;
}

// Every ball accounted for once, none overlapping, every one on the table or pocketed.
void check_apart_and_on_table(const Table& table, const std::vector<Ball>& balls, double R) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Ball& a = balls[i];
        if (a.state == MotionState::pocketed)
            continue;
        INFO("ball " << a.id << " at " << a.position.x << " " << a.position.y);
        CHECK(on_playing_surface(table, a.position, R));
        for (std::size_t j = i + 1; j < balls.size(); ++j) {
            if (balls[j].state == MotionState::pocketed)
                continue;
            INFO("and ball " << balls[j].id);
            CHECK(length(a.position - balls[j].position) >= 2 * R - 1e-9);
        }
    }
}

// The thin break of `termpool bench`: from the D, the cue ball's line 1.6 R outside the red at
// the back corner on its side.
Strike thin_break(const std::vector<Ball>& rack, double speed) {
    const Ball& cue = rack.front();
    const Ball* corner = nullptr;
    for (const Ball& b : rack)
        if (is_snooker_red(b.id) &&
            (!corner || b.position.x - 2 * std::abs(b.position.y - cue.position.y) >
                            corner->position.x - 2 * std::abs(corner->position.y - cue.position.y)))
            corner = &b;
    const Vec2 target = corner->position + Vec2{0, -1.6 * snooker_params.ball_radius};
    const Vec2 aim = target - cue.position;
    return Strike{speed, std::atan2(aim.y, aim.x) * 180 / std::numbers::pi, 0, 0};
}

cli::Scenario parsed(const std::string& text) {
    const cli::ScenarioResult r = cli::parse_scenario(text);
    if (const auto* e = std::get_if<cli::ScenarioError>(&r))
        FAIL("line " << e->line << ": " << e->message);
    return std::get<cli::Scenario>(r);
}

std::string refusal(const std::string& text, int& line) {
    const cli::ScenarioResult r = cli::parse_scenario(text);
    const auto* e = std::get_if<cli::ScenarioError>(&r);
    REQUIRE(e);
    line = e->line;
    return e->message;
}

} // namespace

TEST_CASE("the snooker table: 12 ft, 3.569 x 1.778 m, corner mouths 86 mm, middle 105 mm",
          "[snooker][table]") {
    const Table t = snooker_table();
    CHECK(t.size == TableSize::snooker);
    CHECK(t.length == 3.569);
    CHECK(t.width == 1.778);
    for (const int corner : {1, 3, 4, 6})
        CHECK(mouth_width(t, corner) == Approx(0.086));
    for (const int middle : {2, 5})
        CHECK(mouth_width(t, middle) == Approx(0.105));
    // The name on the command line, in a scenario, a record and the hall.
    CHECK(std::string(table_size_name(TableSize::snooker)) == "snooker");
    CHECK(parse_table_size("snooker") == TableSize::snooker);
    CHECK_FALSE(parse_table_size("12ft").has_value());
    // Pool tables keep the WPA's pockets.
    const Table nine = make_table(TableSize::nine_foot);
    CHECK(mouth_width(nine, 1) == Approx(0.114));
    CHECK(mouth_width(nine, 2) == Approx(0.127));
    CHECK(pocket_spec(TableSize::nine_foot).corner_mouth == PocketSpec{}.corner_mouth);
}

TEST_CASE("a snooker ball fits the snooker pockets and drops in them", "[snooker][table]") {
    const Table t = snooker_table();
    const double R = snooker_params.ball_radius;
    // Down the middle of a corner pocket's mouth and of a middle pocket's: on the table there,
    // and a ball sent along the pocket's axis is pocketed.
    CHECK(on_playing_surface(t, {0.3, 0.3}, R));
    struct Case {
        Vec2 from;
        double angle_deg;
        int pocket;
    };
    for (const Case& c : {Case{{0.4, 0.4}, -135, 1}, Case{{t.length / 2, 0.4}, -90, 2},
                          Case{{t.length - 0.4, t.width - 0.4}, 45, 4}}) {
        INFO("pocket " << c.pocket);
        const std::vector<Ball> balls{ball_at(0, c.from.x, c.from.y, snooker_params.ball_mass)};
        const ShotResult r =
            simulate_shot(t, snooker_params, balls, Strike{1.5, c.angle_deg, 0, 0});
        REQUIRE(r.balls.size() == 1);
        CHECK(r.balls[0].state == MotionState::pocketed);
        CHECK(r.balls[0].pocket == c.pocket);
    }
    // A ball frozen to the cushion on the other side of a corner's point is on the table.
    CHECK(on_playing_surface(t, {0.2, R}, R));
}

TEST_CASE("physics_for_table: snooker balls on the snooker table, pool's unchanged elsewhere",
          "[snooker][table]") {
    CHECK(snooker_params.ball_radius == 0.02625);
    CHECK(snooker_params.ball_mass == 0.142);
    CHECK(snooker_params.cue_mass() == 0.142);
    PhysicsParams base;
    base.friction.kind = FrictionKind::decay;
    base.friction.decay_rate = 0.4;
    base.cue_ball_mass = 0.2;
    const PhysicsParams snooker = physics_for_table(TableSize::snooker, base);
    CHECK(snooker.ball_radius == snooker_ball_radius);
    CHECK(snooker.friction.kind == FrictionKind::decay); // every model works on snooker balls
    CHECK(snooker.cue_ball_mass == 0.2);
    for (const TableSize pool :
         {TableSize::seven_foot, TableSize::eight_foot, TableSize::nine_foot}) {
        const PhysicsParams p = physics_for_table(pool, base);
        CHECK(p.ball_radius == PhysicsParams{}.ball_radius);
        CHECK(p.ball_mass == PhysicsParams{}.ball_mass);
        CHECK(p.friction.decay_rate == 0.4);
    }
    // A game on the snooker table plays with snooker balls, its table built for them.
    GameSetup setup;
    setup.table = TableSize::snooker;
    CHECK(game_physics(setup).ball_radius == snooker_ball_radius);
    const Game game = make_game(setup, 1, 7);
    CHECK(game.table().size == TableSize::snooker);
    CHECK(game.params().ball_radius == snooker_ball_radius);
    for (const Ball& b : game.balls())
        CHECK(b.mass == snooker_ball_mass);
}

TEST_CASE("a match on the snooker table starts, and its record keeps the table",
          "[snooker][table]") {
    GameRecord header;
    header.setup.table = TableSize::snooker;
    auto started = Match::start(header, 1);
    REQUIRE(std::holds_alternative<Match>(started));
    const Match& match = std::get<Match>(started);
    CHECK(match.game().params().ball_radius == snooker_ball_radius);
    const std::string text = format_record(match.record());
    CHECK(text.find("table snooker\n") != std::string::npos);
    const auto back = parse_record(text);
    REQUIRE(std::holds_alternative<GameRecord>(back));
    CHECK(std::get<GameRecord>(back).setup.table == TableSize::snooker);
}

TEST_CASE("the snooker rack: 15 reds above the pink, the colours on their spots, the cue ball "
          "in the D",
          "[snooker][rack]") {
    const Table t = snooker_table();
    const double R = snooker_params.ball_radius;
    const Vec2 pink = snooker_spot(t, snooker_pink);
    for (const std::optional<std::uint64_t> seed :
         {std::optional<std::uint64_t>{}, std::optional<std::uint64_t>{1},
          std::optional<std::uint64_t>{2}, std::optional<std::uint64_t>{99},
          std::optional<std::uint64_t>{123456789}}) {
        INFO("seed " << (seed ? std::to_string(*seed) : "none"));
        const std::vector<Ball> rack = make_rack(t, snooker_params, RackType::snooker, seed);
        REQUIRE(rack.size() == static_cast<std::size_t>(snooker_ball_count));
        for (int id = 0; id < snooker_ball_count; ++id)
            CHECK(rack[static_cast<std::size_t>(id)].id == id);
        check_apart_and_on_table(t, rack, R);
        for (int c = snooker_yellow; c <= snooker_black; ++c) {
            CHECK(find(rack, c)->position == snooker_spot(t, c));
            CHECK(find(rack, c)->mass == snooker_ball_mass);
        }
        const Ball& cue = *find(rack, 0);
        CHECK(in_snooker_d(t, cue.position));
        CHECK(cue.position.y < snooker_spot(t, snooker_brown).y); // on the yellow's side
        CHECK(cue.position.y > snooker_spot(t, snooker_yellow).y);
        double nearest = 1e9;
        for (int id = snooker_first_red; id <= snooker_last_red; ++id) {
            const Ball& red = *find(rack, id);
            CHECK(red.position.x > pink.x); // on the top side of the pink
            CHECK(red.position.x < snooker_spot(t, snooker_black).x - 2 * R);
            CHECK(std::abs(red.position.y - pink.y) < 2.5 * 2 * R);
            nearest = std::min(nearest, length(red.position - pink));
        }
        // The apex red is a rack's gap from the pink (its jitter and the pushing apart of
        // the jittered reds aside).
        CHECK(nearest >= 2 * R);
        CHECK(nearest <= 2 * R + rack_gap + 3 * rack_jitter);
        if (!seed)
            CHECK(nearest == Approx(2 * R + rack_gap).margin(1e-12));
    }
    // Seeds jitter the reds: two seeds give two racks.
    CHECK(make_rack(t, snooker_params, RackType::snooker, 1)[5].position !=
          make_rack(t, snooker_params, RackType::snooker, 2)[5].position);
}

TEST_CASE("pool racks are as they were", "[snooker][rack]") {
    // The 8-ball rack without a seed: the apex on the foot spot, the cue ball on the head spot.
    const Table t = make_table(TableSize::nine_foot);
    const std::vector<Ball> rack = make_rack(t, PhysicsParams{}, RackType::eight_ball);
    REQUIRE(rack.size() == 16);
    CHECK(rack[0].position == t.head_spot());
    CHECK(rack[1].position == t.foot_spot());
    CHECK(rack[1].id == 1);
}

TEST_CASE("scenarios on the snooker table: snooker balls, ids up to 21, rack snooker",
          "[snooker][scenario]") {
    const cli::Scenario s = parsed("table snooker\nball 0 1 0.8\nball 21 3.245 0.889\n"
                                   "ball 16 0.737 0.597\n");
    CHECK(s.setup.table == TableSize::snooker);
    CHECK(s.table.size == TableSize::snooker);
    CHECK(s.setup.physics.ball_radius == snooker_ball_radius);
    CHECK(s.setup.physics.ball_mass == snooker_ball_mass);
    REQUIRE(s.balls.size() == 3);
    CHECK(s.balls[2].id == 21);
    CHECK(s.balls[2].mass == snooker_ball_mass);

    // The table may come after the balls.
    CHECK(parsed("ball 19 1.7845 0.889\ntable snooker\n").balls[0].id == 19);
    // A radius or mass given stays.
    const cli::Scenario given = parsed("param R 0.03\ntable snooker\nparam m 0.2\nball 1 1 1\n");
    CHECK(given.setup.physics.ball_radius == 0.03);
    CHECK(given.setup.physics.ball_mass == 0.2);

    const cli::Scenario rack = parsed("table snooker\nrack snooker 4\nstrike 7 0\n");
    CHECK(rack.balls.size() == 22);
    CHECK(rack.strike.has_value());
    CHECK(parsed("table snooker\nrack snooker\n").balls.size() == 22);

    int line = 0;
    CHECK(refusal("table snooker\nball 22 1 1\n", line) == "ball id 22 is outside 0..21");
    CHECK(line == 2);
    CHECK(refusal("ball 1 1 1\nball 16 1.5 1\n", line).starts_with("ball id 16 is outside 0..15"));
    CHECK(line == 2);
    CHECK(refusal("table 9ft\nball 21 1 1\n", line).starts_with("ball id 21 is outside 0..15"));
    CHECK(refusal("table 12ft\n", line).find("snooker") != std::string::npos);
    CHECK(refusal("rack pyramid\n", line).find("snooker") != std::string::npos);
    // The pool referees have no verdict on a colour.
    CHECK(refusal("table snooker\ngame 8ball\nball 0 1 0.8\nball 17 2 0.8\nstrike 3 0\n", line) ==
          "'ball 17' cannot go with 'game 8ball' (line 2): the 8ball referee judges balls 0..15 "
          "only");
    CHECK(line == 4);
    CHECK(refusal("table snooker\nrack snooker\nshooter 2\nstrike 3 0\n", line)
              .starts_with("rack ball 16 needs a game that has it"));
    CHECK(parsed("table snooker\nrack snooker\nstrike 7 0\n").balls.size() == 22);
    // Pool tables keep pool balls.
    CHECK(parsed("table 7ft\nball 1 1 0.5\n").setup.physics.ball_radius == 0.028575);
}

TEST_CASE("snooker breaks stay exact: apart, on the table or pocketed, deterministic",
          "[snooker][physics]") {
    const Table t = snooker_table();
    const double R = snooker_params.ball_radius;
    int first_red = 0, reds_moved = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        INFO("seed " << seed);
        const std::vector<Ball> rack = make_rack(t, snooker_params, RackType::snooker, seed);
        // The thin break, and a full-power one at the apex red.
        for (const Strike& strike : {thin_break(rack, 7), Strike{max_strike_speed, 0, 0, 0.2}}) {
            StressShot shot;
            shot.seed = seed;
            shot.table = t;
            shot.params = snooker_params;
            shot.balls = rack;
            shot.strike = strike;
            const StressReport report = check_stress_shot(shot);
            INFO(report.detail);
            CHECK(report.failure == StressFailure::none);
            const ShotResult r = simulate_shot(t, snooker_params, rack, strike);
            CHECK_FALSE(r.event_limit_hit);
            REQUIRE(r.balls.size() == 22);
            check_apart_and_on_table(t, r.balls, R);
            if (strike.speed == 7) {
                const auto contact =
                    std::find_if(r.events.begin(), r.events.end(),
                                 [](const Event& e) { return e.kind == EventKind::ball_ball; });
                first_red += contact != r.events.end() && is_snooker_red(contact->other);
                for (const Ball& b : r.balls)
                    reds_moved +=
                        is_snooker_red(b.id) && length(b.position - find(rack, b.id)->position) > R;
            }
        }
    }
    // The thin break takes a red first, and opens the pack.
    CHECK(first_red == 20);
    CHECK(reds_moved > 20);
}

TEST_CASE("random shots on the snooker table: the stress test's checks", "[snooker][physics]") {
    // Racks and random layouts of up to 22 snooker balls, every model, every event checked.
    const StressTally t = run_stress(1, 400, 2, 5, true);
    std::string examples;
    for (const std::string& e : t.examples)
        examples += e;
    INFO(examples);
    CHECK(t.shots == 400);
    CHECK(t.failed() == 0);
    CHECK(t.long_shots == 0);
}

TEST_CASE("the snooker stress checks over SOAK_SHOTS shots", "[.snooker-soak]") {
    // SOAK_SHOTS=N build/termpool_tests '[snooker-soak]': a longer run of the test above.
    const char* text = std::getenv("SOAK_SHOTS");
    const std::uint64_t count = text ? parse_uint64(text).value_or(0) : 100000;
    const StressTally t = run_stress(1001, count, 2, 5, true);
    std::printf("snooker shots %zu (%zu classic), events %zu (most in one shot %zu, seed %llu), "
                "failures %zu\n",
                t.shots, t.classic_shots, t.events, t.most_events,
                static_cast<unsigned long long>(t.most_events_seed), t.failed());
    std::string examples;
    for (const std::string& e : t.examples)
        examples += e;
    INFO(examples);
    CHECK(t.failed() == 0);
    CHECK(t.long_shots == 0);
}
