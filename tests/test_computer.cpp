// The computer player: its search finds pots, its placements are legal, a seed replays it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <termpool/computer.hpp>

#include "physics_helpers.hpp"
#include "rules_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

TEST_CASE("the computer's planned shot pots a straight-in ball", "[computer]") {
    for (int n = 1; n <= 6; ++n) {
        Game game = position(GameType::eight_ball, with_extra(straight_in(3, n), {9, 10}), 1,
                             Group::solids);
        ComputerPlayer computer(Level::pro, 7);
        const ComputerShot shot = computer.shot(game);
        Game check = game;
        const Verdict v = check.play(shot.planned, shot.call);
        INFO("pocket " << n);
        CHECK(std::ranges::count(v.pocketed, 3) == 1);
        CHECK(v.foul == Foul::none);
        CHECK(v.next_shooter == 1);
    }
}

TEST_CASE("the computer places the cue ball only where the rules allow", "[computer]") {
    for (const GameType type : {GameType::eight_ball, GameType::eight_ball_bar}) {
        Game game = position(type, spread({0, 1, 2, 8, 9, 10}), 1, Group::solids);
        game.apply({}, hand_made(game, {hit(0, 9), rail(9)})); // a foul: player 2 has it in hand
        REQUIRE(game.ball_in_hand() != BallInHand::none);
        ComputerPlayer computer(Level::medium, 3);
        const Vec2 spot = computer.place_cue_ball(game);
        CHECK(game.legal_placement(spot));
        CHECK(game.place_cue_ball(spot));
    }
}

TEST_CASE("the shot from the spot the computer chose is the one its placing found", "[computer]") {
    Game game = position(GameType::eight_ball, spread({0, 1, 2, 8, 9, 10}), 1, Group::solids);
    game.apply({}, hand_made(game, {hit(0, 9), rail(9)})); // player 2 has ball in hand
    REQUIRE(game.ball_in_hand() != BallInHand::none);
    for (const Level level : {Level::easy, Level::medium, Level::hard, Level::pro}) {
        INFO(level_name(level));
        // As Match asks: the spot, the same game with the cue ball put there, its shot.
        Game placed = game;
        ComputerPlayer computer(level, 3);
        const Vec2 spot = computer.place_cue_ball(placed);
        REQUIRE(placed.place_cue_ball(spot));
        const std::uint64_t simulated = computer.simulations();
        const ComputerShot shot = computer.shot(placed);
        // Pro searches a spot at pool more quickly than a shot: it searches the shot again.
        CHECK((computer.simulations() == simulated) == (level != Level::pro));
        Game check = placed;
        CHECK(check
                  .apply(shot.call,
                         simulate_shot(check.table(), check.params(), check.balls(), shot.planned))
                  .foul == Foul::none);
        // Kept for that shot only: the next decision from the same position searches.
        computer.shot(placed);
        CHECK(computer.simulations() > simulated);
    }
    // The same game with the cue ball put elsewhere (another of the spots, or a nanometre
    // away), or a copy of it on the chosen spot: each is searched.
    const auto searched = [&](const auto& put_elsewhere) {
        Game placed = game;
        ComputerPlayer computer(Level::medium, 3);
        put_elsewhere(placed, computer.place_cue_ball(placed));
        const std::uint64_t simulated = computer.simulations();
        computer.shot(placed);
        return computer.simulations() > simulated;
    };
    CHECK(searched([&](Game& placed, Vec2 spot) {
        bool elsewhere = false;
        for (const Vec2 other : game.legal_placements(6))
            if (!elsewhere && !(other == spot))
                elsewhere = placed.place_cue_ball(other);
        REQUIRE(elsewhere);
    }));
    CHECK(searched([&](Game& placed, Vec2 spot) {
        REQUIRE(placed.place_cue_ball({spot.x + 1e-9, spot.y}));
    }));
    Game original = game;
    ComputerPlayer computer(Level::medium, 3);
    const Vec2 spot = computer.place_cue_ball(original);
    REQUIRE(original.place_cue_ball(spot));
    const Game copy = original;
    const std::uint64_t simulated = computer.simulations();
    computer.shot(copy);
    CHECK(computer.simulations() > simulated);
}

TEST_CASE("a seeded computer decides the same way twice", "[computer]") {
    const Game game(GameType::eight_ball, nine_foot(), PhysicsParams{}, 1, 5);
    Game after_break = game;
    after_break.play({12, 0, 0, 0}, {});
    ComputerPlayer a(Level::hard, 11), b(Level::hard, 11);
    if (after_break.chooser() != 0 || after_break.ball_in_hand() != BallInHand::none)
        return;
    const ComputerShot x = a.shot(after_break), y = b.shot(after_break);
    CHECK(x.strike.angle_deg == y.strike.angle_deg);
    CHECK(x.strike.speed == y.strike.speed);
    CHECK(x.call.call.ball == y.call.call.ball);
}

TEST_CASE("execution noise grows from pro to easy", "[computer]") {
    Game game =
        position(GameType::eight_ball, with_extra(straight_in(3, 3), {9, 10}), 1, Group::solids);
    auto spread_of = [&](Level level) {
        ComputerPlayer computer(level, 1);
        double sum = 0;
        for (int i = 0; i < 40; ++i) {
            const ComputerShot s = computer.shot(game);
            sum += std::abs(s.strike.angle_deg - s.planned.angle_deg);
        }
        return sum / 40;
    };
    const double pro = spread_of(Level::pro), easy = spread_of(Level::easy);
    CHECK(pro > 0);
    CHECK(easy > 4 * pro);
}

TEST_CASE("a ball with another in the way is not chosen", "[computer]") {
    // The 3 sits straight in front of corner pocket 3 behind the cue ball's line to the 1; the
    // 1 is blocked from the cue ball by the 9. The computer must not pick the 1.
    const Vec2 out = out_of_pocket(3);
    const Vec2 three = pocket_at(3) + out * 0.3, cue = three + out * 0.4;
    const Vec2 one{0.5, 0.3};
    const Vec2 nine = cue + (one - cue) * 0.5;
    Game game =
        position(GameType::eight_ball,
                 {ball_at(0, cue.x, cue.y), ball_at(3, three.x, three.y), ball_at(1, one.x, one.y),
                  ball_at(9, nine.x, nine.y), ball_at(10, 0.4, 1.1)},
                 1, Group::solids);
    for (const Level level : {Level::medium, Level::hard, Level::pro}) {
        ComputerPlayer computer(level, 5);
        const ComputerShot shot = computer.shot(game);
        CHECK(shot.call.call.ball != 1);
    }
}

TEST_CASE("with nothing to pot the computer plays safe rather than foul", "[computer]") {
    // The 1 in the middle of the table with a stripe on its line to every pocket; the cue ball
    // can reach it from between the lines to pockets 4 and 5.
    const Vec2 one{1.27, 0.635};
    std::vector<Ball> balls = {ball_at(0, one.x + 0.175, one.y + 0.303), ball_at(1, one.x, one.y),
                               ball_at(8, 0.3, 1.1)};
    for (int n = 1; n <= 6; ++n) {
        const Vec2 blocker = one + normalized(pocket_at(n) - one) * 0.3;
        balls.push_back(ball_at(8 + n, blocker.x, blocker.y));
    }
    Game game = position(GameType::eight_ball, balls, 1, Group::solids);
    ComputerPlayer computer(Level::medium, 2);
    const ComputerShot shot = computer.shot(game);
    CHECK(shot.call.call.safety);
    Game check = game;
    const Verdict v = check.play(shot.planned, shot.call);
    CHECK(v.first_contact == 1);
    CHECK(v.foul == Foul::none);
}

TEST_CASE("the computer's choices are among those offered", "[computer]") {
    Game game(GameType::eight_ball, nine_foot(), PhysicsParams{}, 1, 5);
    game.play({1.2, 0, 0, 0}, {}); // an illegal break: player 2 chooses
    REQUIRE(game.chooser() == 2);
    ComputerPlayer computer(Level::hard, 1);
    const Choice choice = computer.choose(game);
    CHECK(std::ranges::count(game.choices(), choice) == 1);
    CHECK(game.choose(choice));
}

TEST_CASE("hard and pro see a combination that wins the rack", "[computer]") {
    // 9-ball: the 1 lined up with the 9 and corner pocket 3; the cue ball well behind them.
    const Vec2 out = out_of_pocket(3);
    const Vec2 nine = pocket_at(3) + out * 0.3;
    const Vec2 one = nine + out * (2 * ball_radius + 0.05);
    const Vec2 cue = one + out * 0.4;
    Game game = position(GameType::nine_ball, {ball_at(0, cue.x, cue.y), ball_at(1, one.x, one.y),
                                               ball_at(9, nine.x, nine.y), ball_at(5, 0.4, 1.0)});
    for (const Level level : {Level::hard, Level::pro}) {
        ComputerPlayer computer(level, 3);
        const ComputerShot shot = computer.shot(game);
        CHECK(shot.call.call.ball == 9);
        Game check = game;
        CHECK(check.play(shot.planned, shot.call).winner == 1);
    }
}

TEST_CASE("pro aims off the ghost ball to take out throw", "[computer]") {
    // A long 35-degree cut into corner pocket 3: at the ghost-ball aim the object ball is thrown
    // off the line of centres, towards the cue ball's way, by a degree or two.
    const Vec2 out = out_of_pocket(3);
    const Vec2 object = pocket_at(3) + out * 1.1;
    const double cut = 35 * std::numbers::pi / 180;
    const Vec2 along{-out.x * std::cos(cut) + out.y * std::sin(cut),
                     -out.x * std::sin(cut) - out.y * std::cos(cut)};
    const Vec2 cue = object - along * 0.6 - normalized(-out) * (2 * ball_radius);
    const std::vector<Ball> balls =
        with_extra({ball_at(0, cue.x, cue.y), ball_at(3, object.x, object.y)}, {9, 10});
    Game game = position(GameType::eight_ball, balls, 1, Group::solids);
    const double ghost = ghost_aim_deg(cue, object, pocket_at(3));
    // How far off the pocket's line the object ball leaves the cue ball, degrees.
    const auto miss_deg = [&](const Strike& strike) {
        World world(game.table(), game.params(), balls);
        world.strike(strike);
        REQUIRE(step_until(world, EventKind::ball_ball).other == 3);
        const Vec2 v = find_ball(world.balls(), 3).velocity;
        const Vec2 want = -out;
        return std::abs(std::atan2(cross(v, want), dot(v, want))) * 180 / std::numbers::pi;
    };
    ComputerPlayer computer(Level::pro, 11);
    const ComputerShot shot = computer.shot(game);
    INFO("aim " << shot.planned.angle_deg << ", ghost " << ghost);
    REQUIRE(shot.call.call.ball == 3);
    Strike plain = shot.planned;
    plain.angle_deg = ghost;
    const double thrown = miss_deg(plain);
    INFO("thrown " << thrown << " degrees at the ghost-ball aim");
    CHECK(thrown > 0.5);
    CHECK(miss_deg(shot.planned) < thrown / 10);
    Game check = game;
    CHECK(std::ranges::count(check.play(shot.planned, shot.call).pocketed, 3) == 1);
}
