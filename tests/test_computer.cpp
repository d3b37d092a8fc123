// The computer player: its search finds pots, its placements are legal, a seed replays it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <termpool/computer.hpp>

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
