// Unit tests of the scenario parser behind `termpool simulate` and of its number helpers.

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <termpool/rack.hpp>

#include "cli/numbers.hpp"
#include "cli/scenario.hpp"

using termpool::cli::parse_scenario;
using termpool::cli::Scenario;
using termpool::cli::ScenarioError;

namespace {

// A 9ft table is 2.54 x 1.27 m; R = 0.028575 m.

Scenario parsed(const std::string& text) {
    auto result = parse_scenario(text);
    if (const auto* error = std::get_if<ScenarioError>(&result))
        FAIL("unexpected error on line " << error->line << ": " << error->message);
    return std::get<Scenario>(std::move(result));
}

ScenarioError refused(const std::string& text) {
    auto result = parse_scenario(text);
    REQUIRE(std::holds_alternative<ScenarioError>(result));
    return std::get<ScenarioError>(result);
}

struct BadCase {
    std::string text;
    int line;
    const char* says;
};

void check_refusals(std::initializer_list<BadCase> cases) {
    for (const BadCase& c : cases) {
        INFO("input:\n" << c.text);
        const ScenarioError e = refused(c.text);
        INFO("message: " << e.message);
        CHECK(e.line == c.line);
        CHECK(e.message.find(c.says) != std::string::npos);
    }
}

} // namespace

TEST_CASE("an empty scenario is a 9ft table with default physics and no balls", "[scenario]") {
    const Scenario s = parsed("");
    CHECK(s.table.size == termpool::TableSize::nine_foot);
    CHECK(s.balls.empty());
    CHECK_FALSE(s.strike);
    CHECK(s.setup.physics.ball_radius == termpool::PhysicsParams{}.ball_radius);
}

TEST_CASE("comments, blank lines, tabs and CRLF are ignored", "[scenario]") {
    const Scenario s = parsed("# a comment line\n"
                              "\n"
                              "   \t  \n"
                              "table\t7ft   # trailing comment\r\n"
                              "\tball 0  0.5\t0.5\r\n"
                              "#ball 1 0.5 0.5   (commented out, would overlap)\n");
    CHECK(s.table.size == termpool::TableSize::seven_foot);
    REQUIRE(s.balls.size() == 1);
    CHECK(s.balls[0].position.x == 0.5);
}

TEST_CASE("table sizes", "[scenario]") {
    CHECK(parsed("table 9ft").table.length == Approx(2.54));
    CHECK(parsed("table 8ft").table.length == Approx(2.34));
    CHECK(parsed("table 7ft").table.width == Approx(0.99));
}

TEST_CASE("collision, cushion and friction models", "[scenario]") {
    using namespace termpool;
    const Scenario s = parsed("collision ideal\ncushion ideal\nfriction decay 0.5\n");
    CHECK(s.setup.physics.collision == CollisionModel::ideal);
    CHECK(s.setup.physics.cushion == CushionModel::ideal);
    CHECK(s.setup.physics.friction.kind == FrictionKind::decay);
    CHECK(s.setup.physics.friction.decay_rate == 0.5);

    const Scenario physical = parsed("collision physical\ncushion physical\nfriction physical");
    CHECK(physical.setup.physics.collision == CollisionModel::physical);
    CHECK(physical.setup.physics.cushion == CushionModel::physical);
    CHECK(physical.setup.physics.friction.kind == FrictionKind::physical);

    const Scenario constant = parsed("friction constant 0.3");
    CHECK(constant.setup.physics.friction.kind == FrictionKind::constant);
    CHECK(constant.setup.physics.friction.deceleration == 0.3);

    const Scenario combined = parsed("friction combined 0.4 0.2");
    CHECK(combined.setup.physics.friction.kind == FrictionKind::combined);
    CHECK(combined.setup.physics.friction.decay_rate == 0.4);
    CHECK(combined.setup.physics.friction.deceleration == 0.2);
}

TEST_CASE("every param sets its field", "[scenario]") {
    const Scenario s = parsed("param u_s 0.21\nparam u_r 0.011\nparam u_sp 0.013\n"
                              "param e_b 0.9\nparam u_b 0.06\nparam e_c 0.8\nparam f_c 0.25\n"
                              "param g 9.8\nparam R 0.03\nparam m 0.16\n");
    const termpool::PhysicsParams& p = s.setup.physics;
    CHECK(p.sliding_friction == 0.21);
    CHECK(p.rolling_friction == 0.011);
    CHECK(p.spin_friction == 0.013);
    CHECK(p.ball_restitution == 0.9);
    CHECK(p.ball_friction.model == termpool::BallFrictionModel::constant);
    CHECK(p.ball_friction.constant == 0.06);
    CHECK(p.cushion_restitution == 0.8);
    CHECK(p.cushion_friction == 0.25);
    CHECK(p.gravity == 9.8);
    CHECK(p.ball_radius == 0.03);
    CHECK(p.ball_mass == 0.16);
    // Edges of the allowed ranges are fine.
    CHECK(parsed("param u_s 0\nparam e_b 1\nparam e_c 0").setup.physics.ball_restitution == 1);
}

TEST_CASE("balls come out in id order with their masses", "[scenario]") {
    const Scenario s = parsed("ball 3 1.0 0.5\nball 0 0.5 0.5 mass=0.2\nball 15 2 1\n");
    REQUIRE(s.balls.size() == 3);
    CHECK(s.balls[0].id == 0);
    CHECK(s.balls[0].mass == 0.2);
    CHECK(s.balls[1].id == 3);
    CHECK(s.balls[1].mass == termpool::PhysicsParams{}.ball_mass);
    CHECK(s.balls[1].position.x == 1.0);
    CHECK(s.balls[1].position.y == 0.5);
    CHECK(s.balls[2].id == 15);
    for (const termpool::Ball& b : s.balls)
        CHECK(b.state == termpool::MotionState::stationary);
}

TEST_CASE("params apply before the balls are built, whatever the order", "[scenario]") {
    // 0.05 from the cushion is on the table for R = 0.028575 but not for R = 0.06.
    const ScenarioError e = refused("ball 1 0.05 0.5\nparam R 0.06\n");
    CHECK(e.line == 1);
    CHECK(e.message.find("off the table") != std::string::npos);

    // 0.05 apart overlaps for R = 0.028575 but not for R = 0.02.
    const Scenario s = parsed("ball 1 1 0.5\nball 2 1.05 0.5\nparam R 0.02\nparam m 0.1\n");
    CHECK(s.setup.physics.ball_radius == 0.02);
    CHECK(s.balls[0].mass == 0.1); // the default mass is the final one
    CHECK(s.balls[1].mass == 0.1);

    // The table follows the final R too.
    CHECK(parsed("param R 0.03\ntable 8ft").table.length == Approx(2.34));
}

TEST_CASE("the rack places 15 balls and a cue ball on the head spot", "[scenario]") {
    const Scenario s = parsed("rack 8ball");
    REQUIRE(s.balls.size() == 16);
    for (std::size_t i = 0; i < s.balls.size(); ++i)
        CHECK(s.balls[i].id == int(i));
    CHECK(s.balls[0].position == s.table.head_spot());

    const termpool::Ball& apex = s.balls[1]; // ball 1 is at the apex of the unseeded 8-ball rack
    CHECK(apex.position == s.table.foot_spot());

    const Scenario nine = parsed("rack 9ball");
    CHECK(nine.balls.size() == 10);

    const Scenario seeded = parsed("rack 8ball 7");
    const Scenario again = parsed("rack 8ball 7");
    CHECK(seeded.balls == again.balls);
    CHECK(seeded.balls != s.balls);
    CHECK(parsed("rack 8ball 18446744073709551615").balls.size() == 16);
}

TEST_CASE("a ball 0 line moves the rack's cue ball; other ids add to a 9-ball rack", "[scenario]") {
    const Scenario s = parsed("rack 9ball\nball 0 0.4 0.3\nball 12 0.4 1.0\n");
    REQUIRE(s.balls.size() == 11);
    CHECK(s.balls[0].position.x == 0.4);
    CHECK(s.balls[0].position.y == 0.3);
    CHECK(s.balls.back().id == 12);
    // A ball line before the rack line works the same.
    CHECK(parsed("ball 0 0.4 0.3\nrack 8ball").balls[0].position.x == 0.4);
}

TEST_CASE("strike with and without tip offsets", "[scenario]") {
    const Scenario s = parsed("ball 0 0.5 0.5\nstrike 3.5 -45\n");
    REQUIRE(s.strike);
    CHECK(s.strike->speed == 3.5);
    CHECK(s.strike->angle_deg == -45);
    CHECK(s.strike->side == 0);
    CHECK(s.strike->follow == 0);

    const Scenario t = parsed("strike 20 90 -0.5 +0.5\nball 0 0.5 0.5\n");
    CHECK(t.strike->speed == 20);
    CHECK(t.strike->side == -0.5);
    CHECK(t.strike->follow == 0.5);
    CHECK(parsed("ball 0 0.5 0.5\nstrike 0 0").strike->speed == 0);
}

TEST_CASE("strike takes the cue's elevation as a fifth field; cue sets the end mass",
          "[scenario][cue]") {
    const Scenario level = parsed("ball 0 0.5 0.5\nstrike 1 0 0.2 0\n");
    CHECK(level.strike->elevation_deg == 0);
    CHECK(level.setup.physics.cue_end_mass == termpool::standard_shaft_end_mass);
    const Scenario raised = parsed("ball 0 0.5 0.5\nstrike 1 0 0.2 0 35.5\ncue low-deflection\n");
    CHECK(raised.strike->elevation_deg == 35.5);
    CHECK(raised.setup.physics.cue_end_mass == termpool::low_deflection_end_mass);
    CHECK(parsed("cue none\n").setup.physics.cue_end_mass == 0);
    CHECK(parsed("cue standard\n").setup.physics.cue_end_mass == termpool::standard_shaft_end_mass);
    CHECK(parsed("cue 0.006\n").setup.physics.cue_end_mass == 0.006);
    CHECK(parsed("cue 0\n").setup.physics.cue_end_mass == 0);
}

TEST_CASE("a strike out of the cue's range or needing a jump shot is refused at its line",
          "[scenario][cue]") {
    check_refusals({
        {"ball 0 1 1\nstrike 1 0 0 0 80.5\n", 2, "elevation 80.5 is outside 0..80 degrees"},
        {"ball 0 1 1\nstrike 1 0 0 0 -1\n", 2, "elevation -1 is outside"},
        {"ball 0 1 1\nstrike 1 0 0 0 x\n", 2, "elevation 'x' is not a number"},
        {"ball 0 1 1\nstrike 1 0 0 0 nan\n", 2, "not finite"},
        {"cue -0.001\n", 1, "cue end mass must be >= 0"},
        {"cue inf\n", 1, "not finite"},
        {"cue none\ncue none\n", 2, "more than one 'cue' line"},
        // 1.73 m/s at 60 degrees is the most before the ball would jump off the slate.
        {"ball 0 1 1\n\nstrike 3 0 0 0 60\n", 3, "at most 1.73 m/s"},
        // Gravity comes after the strike, and still counts: a weaker pull lets the ball fly.
        {"ball 0 1 1\nstrike 1.5 0 0 0 60\nparam g 5\n", 2, "jump"},
    });
    CHECK(parsed("ball 0 1 1\nstrike 1.7 0 0 0 60\n").strike->elevation_deg == 60);
}

TEST_CASE("balls that touch exactly are allowed", "[scenario]") {
    CHECK(parsed("param R 0.025\nball 1 1 0.5\nball 2 1.05 0.5\n").balls.size() == 2);
    // On the cushion line is still on the table.
    CHECK(parsed("param R 0.025\nball 1 0.025 0.025\nball 2 2.515 1.245").balls.size() == 2);
}

TEST_CASE("unknown directives and wrong field counts name the line", "[scenario]") {
    check_refusals({
        {"table 9ft\nbounce 1 2\n", 2, "unknown directive 'bounce'"},
        {"\n\n# x\nTable 9ft\n", 4, "unknown directive"},
        {"table\n", 1, "missing field"},
        {"table 9ft 8ft\n", 1, "extra field '8ft'"},
        {"table 10ft\n", 1, "unknown table size"},
        {"collision\n", 1, "missing field"},
        {"collision soft\n", 1, "unknown collision model"},
        {"cushion ideal ideal\n", 1, "extra field"},
        {"cushion bouncy\n", 1, "unknown cushion model"},
        {"friction\n", 1, "missing field"},
        {"friction sticky\n", 1, "unknown friction model"},
        {"friction physical 1\n", 1, "extra field"},
        {"friction decay\n", 1, "missing field"},
        {"friction decay 1 2\n", 1, "extra field"},
        {"friction constant\n", 1, "missing field"},
        {"friction combined 1\n", 1, "missing field"},
        {"friction combined 1 2 3\n", 1, "extra field"},
        {"param u_s\n", 1, "missing field"},
        {"param u_s 1 2\n", 1, "extra field"},
        {"param mu 0.2\n", 1, "unknown parameter 'mu'"},
        {"ball 1 0.5\n", 1, "missing field"},
        {"ball 1 0.5 0.5 mass=0.1 x\n", 1, "extra field"},
        {"ball 1 0.5 0.5 weight=0.1\n", 1, "unknown field 'weight=0.1'"},
        {"rack\n", 1, "missing field"},
        {"rack 8ball 1 2\n", 1, "extra field"},
        {"rack 11ball\n", 1, "unknown rack"},
        {"strike\n", 1, "missing field"},
        {"ball 0 1 1\nstrike 1\n", 2, "missing field"},
        {"ball 0 1 1\nstrike 1 0 0.1\n", 2, "missing field"},
        {"ball 0 1 1\nstrike 1 0 0.1 0.1 0 0\n", 2, "extra field"},
        {"cue\n", 1, "missing field"},
        {"cue standard 1\n", 1, "extra field"},
        {"cue carbon\n", 1, "unknown cue 'carbon'"},
    });
}

TEST_CASE("non-numeric, NaN and infinite fields are refused", "[scenario]") {
    check_refusals({
        {"ball 1 abc 0.5\n", 1, "x 'abc' is not a number"},
        {"ball 1 0.5 0.5e\n", 1, "y '0.5e' is not a number"},
        {"ball 1 1,5 0.5\n", 1, "not a number"},
        {"ball 1 nan 0.5\n", 1, "x 'nan' is not finite"},
        {"ball 1 0.5 inf\n", 1, "not finite"},
        {"ball 1 0.5 -infinity\n", 1, "not finite"},
        {"ball 1 1e999 0.5\n", 1, "not finite"},
        {"ball 1 0.5 0.5 mass=nan\n", 1, "not finite"},
        {"ball 1 0.5 0.5 mass=\n", 1, "mass '' is not a number"},
        {"ball one 0.5 0.5\n", 1, "ball id 'one' is not an integer"},
        {"ball 1.0 0.5 0.5\n", 1, "not an integer"},
        {"param u_s NaN\n", 1, "not finite"},
        {"param g x\n", 1, "not a number"},
        {"ball 0 1 1\nstrike nan 0\n", 2, "speed 'nan' is not finite"},
        {"ball 0 1 1\nstrike 1 inf\n", 2, "angle 'inf' is not finite"},
        {"ball 0 1 1\nstrike 1 0 nan 0\n", 2, "not finite"},
        {"ball 0 1 1\nstrike 1 0 0 x\n", 2, "not a number"},
        {"friction decay inf\n", 1, "not finite"},
        {"friction combined 1 nan\n", 1, "not finite"},
        {"rack 8ball -1\n", 1, "not an unsigned 64-bit integer"},
        {"rack 8ball 18446744073709551616\n", 1, "not an unsigned 64-bit integer"},
        {"rack 8ball 1.5\n", 1, "not an unsigned 64-bit integer"},
    });
}

TEST_CASE("values out of range are refused", "[scenario]") {
    check_refusals({
        {"ball 0 1 1\nstrike 20.001 0\n", 2, "speed 20.001 is outside 0..20 m/s"},
        {"ball 0 1 1\nstrike -1 0\n", 2, "outside 0..20"},
        {"ball 0 1 1\nstrike 1 0 0.51 0\n", 2, "side offset 0.51 is outside -0.5..0.5"},
        {"ball 0 1 1\nstrike 1 0 0 -0.6\n", 2, "follow offset -0.6 is outside"},
        {"ball 16 1 1\n", 1, "ball id 16 is outside 0..15"},
        {"ball -1 1 1\n", 1, "outside 0..15"},
        {"ball 1 1 1 mass=0\n", 1, "mass must be > 0"},
        {"ball 1 1 1 mass=-0.1\n", 1, "mass must be > 0"},
        {"param u_s -0.1\n", 1, "u_s must be >= 0"},
        {"param u_r -1\n", 1, "u_r must be >= 0"},
        {"param u_sp -1\n", 1, "u_sp must be >= 0"},
        {"param u_b -1\n", 1, "u_b must be >= 0"},
        {"param f_c -1\n", 1, "f_c must be >= 0"},
        {"param e_b 1.01\n", 1, "e_b must be between 0 and 1"},
        {"param e_c -0.1\n", 1, "e_c must be between 0 and 1"},
        {"param R 0\n", 1, "R must be > 0"},
        {"param m -0.17\n", 1, "m must be > 0"},
        {"param g 0\n", 1, "g must be > 0"},
        {"friction decay 0\n", 1, "decay rate K must be > 0"},
        {"friction constant -2\n", 1, "deceleration A must be > 0"},
        {"friction combined 0 1\n", 1, "decay rate K must be > 0"},
        {"friction combined 1 0\n", 1, "deceleration A must be > 0"},
    });
}

TEST_CASE("repeated directives are refused at the repeat", "[scenario]") {
    check_refusals({
        {"table 9ft\n\ntable 9ft\n", 3, "more than one 'table' line (the first is line 1)"},
        {"rack 8ball\nrack 9ball\n", 2, "more than one 'rack' line"},
        {"ball 0 1 1\nstrike 1 0\nstrike 2 0\n", 3, "more than one 'strike' line"},
        {"collision ideal\ncollision ideal\n", 2, "more than one 'collision' line"},
        {"friction decay 1\nfriction physical\n", 2, "more than one 'friction' line"},
        {"param R 0.03\nparam u_s 0.2\nparam R 0.03\n", 3, "more than one 'param R' line"},
    });
}

TEST_CASE("duplicate ids, off-table and overlapping balls name the later line", "[scenario]") {
    check_refusals({
        {"ball 1 1 1\nball 2 0.5 0.5\nball 1 2 1\n", 3,
         "duplicate ball 1 (already placed on line 1)"},
        {"rack 8ball\nball 5 0.3 0.3\n", 2, "duplicate ball 5 (already in the rack on line 1)"},
        {"ball 5 0.3 0.3\nrack 8ball\n", 2, "duplicate ball 5"},
        {"rack 9ball\nball 9 0.3 0.3\n", 2, "duplicate ball 9"},
        {"ball 1 0.02 0.5\n", 1, "ball 1 at (0.02, 0.5) is off the table"},
        {"ball 1 2.53 0.5\n", 1, "off the table"},
        {"ball 1 1 -0.5\n", 1, "off the table"},
        {"table 7ft\nball 1 2 0.5\n", 2, "off the table"},
        {"ball 1 1 0.5\nball 2 1.05 0.5\n", 2, "ball 2 at (1.05, 0.5) overlaps ball 1 (line 1)"},
        {"ball 2 1.05 0.5\n\nball 1 1 0.5\n", 3, "overlaps ball 2"},
        {"ball 10 1.9 0.635\nrack 9ball\n", 2,
         "rack ball 1 at (1.905, 0.635) overlaps ball 10 (line 1)"},
        {"rack 8ball\nball 0 1.9 0.64\n", 2, "overlaps rack ball"},
        {"param R 0.3\nrack 8ball\n", 2, "off the table"},
    });
}

TEST_CASE("a strike needs a cue ball; a scenario without a strike is fine", "[scenario]") {
    check_refusals({
        {"ball 1 1 1\nstrike 1 0\n", 2, "strike without a cue ball"},
        {"strike 1 0\nball 1 1 1\n", 1, "strike without a cue ball"},
        {"strike 1 0\n", 1, "strike without a cue ball"},
    });
    CHECK_FALSE(parsed("ball 1 1 1\n").strike);
    CHECK(parsed("rack 8ball\nstrike 12 0\n").strike);
}

TEST_CASE("line-local errors come before errors between lines", "[scenario]") {
    // Line 2 overlaps line 1, but line 3 cannot even be read.
    const ScenarioError e = refused("ball 1 1 0.5\nball 2 1.01 0.5\nball 3 x 0.5\n");
    CHECK(e.line == 3);
}

TEST_CASE("numbers print with %.9g and read without the locale", "[scenario]") {
    using namespace termpool;
    using namespace termpool::cli;
    CHECK(format_number(0.1) == "0.1");
    CHECK(format_number(1.0 / 3) == "0.333333333");
    CHECK(format_number(12345678901.0) == "1.23456789e+10");
    CHECK(format_number(-0.0) == "0");
    CHECK(parse_double("+0.3") == 0.3);
    CHECK(parse_double("-2.5e-1") == -0.25);
    CHECK(parse_double("1E2") == 100);
    CHECK(std::isinf(*parse_double("1e999")));
    CHECK(*parse_double("-1e999") < 0);
    CHECK(*parse_double("1e-999") == 0);
    CHECK(*parse_double("0.000000000000000000000000000000000000000000000000000000000000000000"
                        "0000000000000000000000000000000000000000000000000000000000000000000"
                        "0000000000000000000000000000000000000000000000000000000000000000000"
                        "0000000000000000000000000000000000000000000000000000000000000000000"
                        "0000000000000000000000000000000000000000000000000000000000000000001") ==
          0);
    CHECK(std::isnan(*parse_double("nan")));
    CHECK_FALSE(parse_double(""));
    CHECK_FALSE(parse_double("+"));
    CHECK_FALSE(parse_double("++1"));
    CHECK_FALSE(parse_double("+-1"));
    CHECK_FALSE(parse_double("0x10"));
    CHECK_FALSE(parse_double("1.5.2"));
    CHECK(parse_integer("15") == 15);
    CHECK_FALSE(parse_integer("15a"));
    CHECK(parse_uint64("18446744073709551615") == 18446744073709551615ULL);
    CHECK_FALSE(parse_uint64("-1"));
}

// ---------------------------------------------------------------------------------------------
// The game context: game, shooter, groups, break, call and push-out.

namespace {

/// A cue ball, balls 1, 8 and 9 well apart, and a strike: enough for any context to be valid.
const std::string table_with_shot = "ball 0 0.5 0.635\nball 1 1.5 0.3\nball 8 1.9 0.635\n"
                                    "ball 9 1.5 1.0\nstrike 1 0\n";

} // namespace

TEST_CASE("a scenario without game directives has no game context", "[scenario]") {
    CHECK_FALSE(parsed(table_with_shot).game);
    CHECK_FALSE(parsed("rack 8ball\nstrike 12 0\n").game);
}

TEST_CASE("each game directive parses", "[scenario]") {
    using namespace termpool;
    const Scenario plain = parsed("game 8ball\n" + table_with_shot);
    REQUIRE(plain.game);
    CHECK(plain.setup.game == GameType::eight_ball);
    CHECK(plain.game->shooter == 1);
    CHECK(plain.game->player1_group == Group::open);
    CHECK_FALSE(plain.game->is_break);
    CHECK(plain.game->call.ball == 0);
    CHECK_FALSE(plain.game->call.safety);

    CHECK(parsed("game 8ball-bar\n" + table_with_shot).setup.game == GameType::eight_ball_bar);
    CHECK(parsed("game 9ball\n" + table_with_shot).setup.game == GameType::nine_ball);

    CHECK(parsed("shooter 1\n" + table_with_shot).game->shooter == 1);
    CHECK(parsed("shooter 2\n" + table_with_shot).game->shooter == 2);

    CHECK(parsed("groups open\n" + table_with_shot).game->player1_group == Group::open);
    CHECK(parsed("groups 1=solids\n" + table_with_shot).game->player1_group == Group::solids);
    CHECK(parsed("groups 1=stripes\n" + table_with_shot).game->player1_group == Group::stripes);

    CHECK(parsed("break\n" + table_with_shot).game->is_break);

    const Scenario called = parsed(table_with_shot + "call 9 6  # into the far corner\n");
    CHECK(called.game->call.ball == 9);
    CHECK(called.game->call.pocket == 6);
    CHECK_FALSE(called.game->call.safety);
    const Scenario eight = parsed(table_with_shot + "call 8 3\n"); // the 8 may be called
    CHECK(eight.game->call.ball == 8);
    CHECK(eight.game->call.pocket == 3);
    const Scenario safety = parsed(table_with_shot + "call safety\n");
    CHECK(safety.game->call.safety);
    CHECK(safety.game->call.ball == 0);
}

TEST_CASE("any game directive makes a context, 8-ball unless `game` says otherwise", "[scenario]") {
    using namespace termpool;
    for (const char* directive : {"shooter 2", "groups 1=stripes", "break", "call 1 2"}) {
        INFO(directive);
        const Scenario s = parsed(std::string(directive) + "\n" + table_with_shot);
        REQUIRE(s.game);
        CHECK(s.setup.game == GameType::eight_ball);
    }
    // All of them together, in any order, with the balls and the rack.
    const Scenario all = parsed("call 3 4\nshooter 2\nrack 8ball\ngroups 1=stripes\n"
                                "game 8ball-bar\nstrike 3 10\n");
    REQUIRE(all.game);
    CHECK(all.setup.game == GameType::eight_ball_bar);
    CHECK(all.game->shooter == 2);
    CHECK(all.game->player1_group == Group::stripes);
    CHECK(all.game->call.ball == 3);
    CHECK(all.game->call.pocket == 4);
    // A break may be any layout: the referee judges what happened.
    CHECK(parsed("game 9ball\nbreak\nball 0 0.5 0.5\nball 5 2 0.5\nstrike 5 0\n").game->is_break);
    // `groups open` is fine in 9-ball: it says nothing.
    CHECK(parsed("game 9ball\ngroups open\n" + table_with_shot).game);
    // A rack puts its balls on the table for a call (the 9-ball rack has 1..9).
    CHECK(parsed("call 5 1\nrack 9ball\nstrike 10 0\n").game->call.ball == 5);
}

TEST_CASE("bad game directives on their own line", "[scenario]") {
    check_refusals({
        {"game\n", 1, "missing field (usage: game 8ball|8ball-bar|9ball|10ball)"},
        {"game 8ball 9ball\n", 1, "extra field '9ball'"},
        {"game snooker\n", 1,
         "unknown game 'snooker' (expected 8ball, 8ball-bar, 9ball or 10ball)"},
        {"game 8-ball\n", 1, "unknown game"},
        {"shooter\n", 1, "missing field"},
        {"shooter 3\n", 1, "shooter '3' is not 1 or 2"},
        {"shooter 0\n", 1, "shooter '0' is not 1 or 2"},
        {"shooter one\n", 1, "is not 1 or 2"},
        {"shooter 1 2\n", 1, "extra field"},
        {"groups\n", 1, "missing field"},
        {"groups solids\n", 1, "unknown groups 'solids' (expected open, 1=solids or 1=stripes)"},
        {"groups 2=solids\n", 1, "unknown groups"},
        {"groups 1=solids 2=stripes\n", 1, "extra field"},
        {"break 1\n", 1, "extra field '1' (usage: break)"},
        {"call\n", 1, "missing field (usage: call BALL POCKET | call safety)"},
        {"call 1\n", 1, "missing field"},
        {"call 1 3 4\n", 1, "extra field '4'"},
        {"call safety 3\n", 1, "extra field '3'"},
        {"call x 3\n", 1, "called ball 'x' is not an integer"},
        {"call 0 3\n", 1, "the cue ball (0) cannot be called"},
        {"call 16 3\n", 1, "called ball 16 is outside 1..15"},
        {"call -1 3\n", 1, "called ball -1 is outside 1..15"},
        {"call 1 corner\n", 1, "called pocket 'corner' is not an integer"},
        {"call 1 0\n", 1, "called pocket 0 is outside 1..6"},
        {"call 1 7\n", 1, "called pocket 7 is outside 1..6"},
        {"push-out 1\n", 1, "extra field '1'"},
        {"game 9ball\npush-out\npush-out\n", 3, "more than one 'push-out' line"},
    });
}

TEST_CASE("repeated game directives are refused at the repeat", "[scenario]") {
    check_refusals({
        {"game 8ball\ngame 8ball\n", 2, "more than one 'game' line (the first is line 1)"},
        {"shooter 1\n\nshooter 2\n", 3, "more than one 'shooter' line (the first is line 1)"},
        {"groups open\ngroups open\n", 2, "more than one 'groups' line"},
        {"break\nbreak\n", 2, "more than one 'break' line"},
        {"call 1 3\ncall safety\n", 2, "more than one 'call' line"},
    });
}

TEST_CASE("game contexts that cannot happen name the later line involved", "[scenario]") {
    const std::string& shot = table_with_shot; // lines 1..5
    check_refusals({
        // Groups on a break: the table is open at the break, whichever comes first.
        {"groups open\nbreak\n" + shot, 2,
         "'groups open' (line 1) cannot go with 'break': the table is open at the break"},
        {"break\n\ngroups 1=solids\n" + shot, 3,
         "'groups 1=solids' cannot go with 'break' (line 1)"},
        // 9-ball has neither groups nor called shots.
        {"game 9ball\ngroups 1=stripes\n" + shot, 2,
         "'groups 1=stripes' cannot go with 'game 9ball' (line 1): 9-ball has no groups"},
        {"groups 1=solids\ngame 9ball\n" + shot, 2, "9-ball has no groups"},
        {"game 9ball\n" + shot + "call 1 3\n", 7,
         "'call' cannot go with 'game 9ball' (line 1): 9-ball shots are not called"},
        {"call safety\ngame 9ball\n" + shot, 2, "9-ball shots are not called"},
        {"game 10ball\ngroups 1=stripes\n" + shot, 2,
         "'groups 1=stripes' cannot go with 'game 10ball' (line 1): 10-ball has no groups"},
        // The called ball must be on the table.
        {shot + "call 2 3\n", 6, "called ball 2 is not on the table"},
        {"call 10 1\nrack 9ball\nstrike 10 0\n", 1, "called ball 10 is not on the table"},
        // Nothing to judge without a strike: reported at the first game directive.
        {"ball 0 0.5 0.5\n\nshooter 2\ngame 8ball\n", 3, "'shooter' without a strike: nothing"},
        {"game 9ball\nrack 9ball\n", 1, "'game' without a strike: nothing to judge"},
        {"ball 0 0.5 0.5\nbreak\n", 2, "'break' without a strike"},
        {"ball 0 0.5 0.5\nball 1 1 1\ncall 1 1\n", 3, "'call' without a strike"},
        {"groups open\n", 1, "'groups' without a strike"},
    });
}

TEST_CASE("a game context does not hide the other errors", "[scenario]") {
    // Line-local errors come first, then the balls, then the game context.
    CHECK(refused("game 9ball\ncall 1 3\nball 0 x 1\n").line == 3);
    CHECK(refused("game 9ball\ncall 1 3\nball 0 1 1\nball 1 1.01 1\nstrike 1 0\n").line == 4);
    CHECK(refused("game 8ball\nstrike 1 0\n").message.find("strike without a cue ball") !=
          std::string::npos);
}

TEST_CASE("throw chooses the ball-ball friction law; param u_b sets the constant", "[scenario]") {
    using termpool::BallFrictionModel;
    CHECK(parsed("").setup.physics.ball_friction == termpool::BallFriction{});
    const termpool::BallFriction fit = parsed("throw fit").setup.physics.ball_friction;
    CHECK(fit == termpool::BallFriction{});
    const termpool::BallFriction own = parsed("throw fit 0.02 0.1 1.5").setup.physics.ball_friction;
    CHECK(own.model == BallFrictionModel::fit);
    CHECK(own.a == 0.02);
    CHECK(own.b == 0.1);
    CHECK(own.c == 1.5);
    const termpool::BallFriction constant =
        parsed("throw constant 0.06").setup.physics.ball_friction;
    CHECK(constant.model == BallFrictionModel::constant);
    CHECK(constant.constant == 0.06);
    CHECK(parsed("throw constant 0").setup.physics.ball_friction.constant == 0);
    CHECK(parsed("throw fit 0 0 0").setup.physics.ball_friction.a == 0);
}

TEST_CASE("bad throw lines are refused with their line", "[scenario]") {
    check_refusals({
        {"throw\n", 1, "missing field (usage: throw fit [A B C] | throw constant U)"},
        {"throw cubic\n", 1, "unknown throw model 'cubic' (expected fit or constant)"},
        {"throw constant\n", 1, "missing field"},
        {"throw constant 0.05 1\n", 1, "extra field '1'"},
        {"throw fit 0.01\n", 1, "missing field"},
        {"throw fit 0.01 0.1\n", 1, "missing field"},
        {"throw fit 0.01 0.1 1 2\n", 1, "extra field '2'"},
        {"throw constant -0.01\n", 1, "u_b must be >= 0 (got -0.01)"},
        {"throw constant x\n", 1, "u_b 'x' is not a number"},
        {"throw constant nan\n", 1, "not finite"},
        {"throw fit -1 0.1 1\n", 1, "fit constant A must be >= 0"},
        {"throw fit 0.01 -0.1 1\n", 1, "fit constant B must be >= 0"},
        {"throw fit 0.01 0.1 -1\n", 1, "fit constant C must be >= 0"},
        {"throw fit 0.01 0.1 inf\n", 1, "not finite"},
        {"\nthrow fit\nthrow fit\n", 3, "more than one 'throw' line (the first is line 2)"},
        {"throw fit\nparam u_b 0.05\n", 2, "'param u_b' cannot go with 'throw' (line 1)"},
        {"param u_b 0.05\n\nthrow constant 0.05\n", 3,
         "'throw' cannot go with 'param u_b' (line 1)"},
    });
}
