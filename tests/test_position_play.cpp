// Pro's position play (issue 27): a pot's chance falls with distance and cut and is nothing past
// 80 degrees; a search's trials play to the bit what a game plays, and judge each call as it
// does; a line of play is blocked where the plain rule says; a world reused for many shots gives
// the bits of a fresh one; pro breaks and decides within its budget.
#include "support/random.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <termpool/computer.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/rack.hpp>

#include "core/event_schedule.hpp"
#include "core/position_play.hpp"
#include "core/shot_lines.hpp"
#include "core/shot_trial.hpp"
#include "rules_helpers.hpp"
#include "snooker_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double R = 0.028575;
constexpr double pro_sigma_deg = 0.0625;

Ball object_at(Vec2 p) {
    Ball b;
    b.id = 3;
    b.position = p;
    return b;
}

// The cue ball `back` m behind the object ball on a line `cut_deg` off its line to pocket 3.
Vec2 cue_for(const Ball& object, double back, double cut_deg) {
    const Vec2 along = normalized(table.pockets[2].position - object.position);
    const Vec2 ghost = object.position - along * (2 * R);
    const double c = std::cos(cut_deg * 3.141592653589793 / 180);
    const double s = std::sin(cut_deg * 3.141592653589793 / 180);
    return ghost - Vec2{along.x * c - along.y * s, along.x * s + along.y * c} * back;
}

} // namespace

TEST_CASE("a pot's chance falls with distance and cut, and is nothing past 80 degrees",
          "[computer][position]") {
    const Ball near_pocket = object_at({2.2, 0.3});
    const Ball far_away = object_at({1.2, 0.9});
    const double short_straight =
        pot_chance(table, R, cue_for(near_pocket, 0.3, 0), near_pocket, 3, pro_sigma_deg);
    const double long_straight =
        pot_chance(table, R, cue_for(near_pocket, 1.2, 0), near_pocket, 3, pro_sigma_deg);
    const double short_cut =
        pot_chance(table, R, cue_for(near_pocket, 0.3, 50), near_pocket, 3, pro_sigma_deg);
    const double far_straight =
        pot_chance(table, R, cue_for(far_away, 0.3, 0), far_away, 3, pro_sigma_deg);
    CHECK(short_straight > 0.99);
    CHECK(long_straight < short_straight);
    CHECK(short_cut < short_straight);
    CHECK(far_straight < short_straight);
    CHECK(pot_chance(table, R, cue_for(near_pocket, 0.3, 85), near_pocket, 3, pro_sigma_deg) == 0);
    // A wider spread, a smaller chance.
    CHECK(pot_chance(table, R, cue_for(far_away, 0.5, 20), far_away, 3, 4 * pro_sigma_deg) <
          pot_chance(table, R, cue_for(far_away, 0.5, 20), far_away, 3, pro_sigma_deg));
}

TEST_CASE("a search's trials play what the game plays, to the bit", "[computer][position]") {
    Game game =
        position(GameType::eight_ball, spread({0, 1, 2, 3, 8, 9, 10, 11}), 1, Group::solids);
    ShotTrial trials(game);
    Random rng(5);
    for (int k = 0; k < 40; ++k) {
        const Strike strike{rng.uniform(0.5, 6), rng.uniform(0, 360), rng.uniform(-0.3, 0.3),
                            rng.uniform(-0.3, 0.3)};
        Game fresh = game;
        ShotResult result;
        const Verdict want = fresh.play(strike, {}, &result);
        const Verdict got = trials.play(strike, {});
        INFO("shot " << k);
        CHECK(got.next_shooter == want.next_shooter);
        CHECK(got.pocketed == want.pocketed);
        CHECK(trials.after().balls() == fresh.balls());
    }
    CHECK(trials.work() > 40);
}

TEST_CASE("a search's trials judge each call as the game does, whatever call came before",
          "[computer][position]") {
    // Calls in a random order: the trials work out a call's plan once and keep it while the
    // same call is played again.
    ShotCall safety, ball_one, ball_two, push_out;
    safety.call.safety = true;
    ball_one.call = {1, 3, false};
    ball_two.call = {2, 6, false};
    push_out.push_out = true;
    // Snooker on a colour: the nomination decides the ball to hit first (the only referee
    // whose targets depend on the call).
    ShotCall yellow, black;
    yellow.call.ball = snooker_yellow;
    black.call.ball = snooker_black;
    SnookerState on_colour;
    on_colour.ball_on = BallOn::colour;
    struct Case {
        Game game;
        std::vector<ShotCall> calls;
    };
    const Case cases[] = {
        {snooker_frame(colours_on_spots({1.6, 0.9}, {{1, {2.9, 0.5}}}), on_colour),
         {{}, yellow, black}},
        {position(GameType::eight_ball, spread({0, 1, 2, 3, 8, 9, 10, 11}), 1, Group::solids),
         {{}, safety, ball_one, ball_two}},
        {position(GameType::ten_ball, spread({0, 1, 2, 3, 4, 10}), 1, Group::open, false, true),
         {{}, ball_one, push_out}},
    };
    Random rng(8);
    for (const Case& c : cases) {
        ShotTrial trials(c.game);
        for (int k = 0; k < 60; ++k) {
            const ShotCall& call = c.calls[rng.below(c.calls.size())];
            const Strike strike{rng.uniform(0.5, 6), rng.uniform(0, 360), 0, 0};
            Game fresh = c.game;
            const Verdict want = fresh.play(strike, call);
            const Verdict got = trials.play(strike, call);
            INFO(game_type_name(c.game.type()) << " shot " << k);
            CHECK(got.fouls == want.fouls);
            CHECK(got.first_contact == want.first_contact);
            CHECK(got.pocketed == want.pocketed);
            CHECK(got.next_shooter == want.next_shooter);
            CHECK(got.ball_in_hand == want.ball_in_hand);
            CHECK(got.winner == want.winner);
            CHECK(trials.after().balls() == fresh.balls());
        }
    }
    // Two colours hit at once: the nomination picks the ball hit first, so that a plan kept
    // from another call would show.
    const double r = snooker_ball_radius;
    const Game two = snooker_frame({snooker_ball(0, {1.0, 0.9}), snooker_ball(1, {3.0, 1.5}),
                                    snooker_ball(snooker_yellow, {2.0, 0.9 + r}),
                                    snooker_ball(snooker_green, {2.0, 0.9 - r})},
                                   on_colour);
    ShotTrial two_trials(two);
    for (const int nominated : {snooker_yellow, snooker_green, snooker_yellow, snooker_green}) {
        ShotCall call;
        call.call.ball = nominated;
        Game fresh = two;
        const Verdict want = fresh.play({1, 0, 0, 0}, call);
        const Verdict got = two_trials.play({1, 0, 0, 0}, call);
        INFO("nominated " << nominated);
        CHECK(want.first_contact == nominated);
        CHECK(got.first_contact == want.first_contact);
        CHECK(got.fouls == want.fouls);
    }
}

TEST_CASE("a line of play is blocked exactly where a ball comes within 2R of it",
          "[computer][position]") {
    // The plain rule, every ball's nearest point on the segment, against path_blocked (which
    // skips the balls outside the segment's box first), on lines and balls placed at random
    // and, half of them, just either side of 2R from the line; on a table, and far out where a
    // unit in the last place is metres; with the ball's radius, none, or a negative one.
    Random rng(12);
    for (int k = 0; k < 6000; ++k) {
        const double far = k % 3 == 2 ? 0x1p53 : 0;
        const double radius = k % 5 == 3 ? 0.0 : k % 5 == 4 ? -0.5 : R;
        const Vec2 a{far + rng.uniform(0, 2.5), rng.uniform(0, 1.3)};
        const Vec2 b = k % 10 == 0 ? a : Vec2{far + rng.uniform(0, 2.5), rng.uniform(0, 1.3)};
        std::vector<Ball> balls;
        for (int id = 0; id < 6; ++id) {
            Ball ball;
            ball.id = id;
            const double u = rng.uniform(-0.2, 1.2);
            const Vec2 on_line = a + (b - a) * u;
            const Vec2 across = perpendicular(normalized(b - a));
            ball.position = k % 2 ? Vec2{far + rng.uniform(0, 2.5), rng.uniform(0, 1.3)}
                                  : on_line + across * (2 * radius + rng.uniform(-1e-6, 1e-6));
            ball.state = id == 5 ? MotionState::pocketed : MotionState::stationary;
            balls.push_back(ball);
        }
        bool want = false;
        const Vec2 ab = b - a;
        for (const Ball& ball : balls) {
            if (ball.state == MotionState::pocketed || ball.id == 0 || ball.id == 1)
                continue;
            const double len2 = length_squared(ab);
            const double u = len2 > 0 ? std::clamp(dot(ball.position - a, ab) / len2, 0.0, 1.0) : 0;
            want = want || length_squared(a + ab * u - ball.position) < 4 * radius * radius;
        }
        INFO("line " << k);
        CHECK(path_blocked(balls, a, b, {0, 1}, radius) == want);
    }
    // Where the nearest point's rounding lands on the ball: 2 m past the segment's end by the
    // box, on it by the plain rule.
    Ball beyond;
    beyond.id = 2;
    beyond.position = {0x1p53 + 4, 0};
    CHECK(path_blocked({beyond}, {-1, 0}, {0x1p53 + 2, 0}, {0, 1}, R));
}

TEST_CASE("a world reused for many shots gives the bits of a fresh one", "[physics][position]") {
    const PhysicsParams params;
    Random rng(9);
    World reused(table, params, make_rack(table, params, RackType::eight_ball, 1));
    ShotResult result;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        // Racks of 16 and, every third, of 10 balls: reset takes another count too.
        std::vector<Ball> balls =
            make_rack(table, params, seed % 3 ? RackType::eight_ball : RackType::nine_ball, seed);
        // A break, or a soft shot away from the rack: then nothing wakes the racked balls, and
        // whatever the world still held for them would show.
        const Strike strike = seed % 2 ? Strike{rng.uniform(4, 12), rng.uniform(-1, 1), 0, 0}
                                       : Strike{rng.uniform(0.5, 1.5), rng.uniform(170, 190), 0, 0};
        const ShotResult fresh = simulate_shot(table, params, balls, strike);
        // Left in the middle of a shot, with contacts pending: reset forgets all of it.
        reused.strike({12, 0, 0, 0});
        for (int k = 0; k < 60; ++k)
            reused.step();
        reused.reset(balls);
        World copy = reused; // a copy into new memory, then into kept memory
        copy = reused;
        simulate_shot(copy, strike, result);
        INFO("rack " << seed);
        CHECK(result.events.size() == fresh.events.size());
        CHECK(result.balls == fresh.balls);
        CHECK(result.rest_time == fresh.rest_time);
    }
}

TEST_CASE("pro's break is chosen by simulation and pots a ball more often than not",
          "[computer][position]") {
    int potted = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        Game game(game_row(GameType::eight_ball), table, PhysicsParams{}, 1, seed);
        ComputerPlayer pro(Level::pro, seed);
        REQUIRE(game.is_break());
        const Vec2 spot = pro.place_cue_ball(game);
        REQUIRE(game.place_cue_ball(spot));
        const ComputerShot shot = pro.shot(game);
        CHECK(shot.planned.speed >= 9.0);
        CHECK(shot.planned.speed <= 13.5);
        const Verdict v = game.play(shot.strike, shot.call);
        potted += v.pocketed.empty() ? 0 : 1;
    }
    CHECK(potted >= 4);
}

TEST_CASE("a world reset to another number of balls records them all", "[physics][position]") {
    const PhysicsParams params;
    World world(table, params, make_rack(table, params, RackType::nine_ball, 1));
    const std::vector<Ball> sixteen = make_rack(table, params, RackType::eight_ball, 2);
    world.reset(sixteen);
    world.record(true);
    world.strike({6, 0, 0, 0});
    while (world.step()) {
    }
    const Trajectory& path = world.trajectory();
    for (std::size_t i = 0; i < sixteen.size(); ++i)
        CHECK_FALSE(path.pieces(i).empty());
    // Too many balls are refused and leave the world as it was.
    const std::vector<Ball> too_many(core::ScheduledEvent::max_balls + 1, sixteen.front());
    CHECK_THROWS_AS(world.reset(too_many), std::length_error);
    world.reset(sixteen);
    CHECK(world.balls() == sixteen);
}
