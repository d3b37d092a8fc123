// The 9-ball referee (WPA rules).
#include <algorithm>
#include <catch2/catch.hpp>

#include "rules_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

TEST_CASE("9-ball: the lowest ball must be hit first", "[rules][nine]") {
    Game game = position(GameType::nine_ball, with_extra(straight_in(3, 4), {1, 9}));
    const Verdict v = game.play(straight_strike(4), {});
    CHECK(v.first_contact == 3);
    CHECK(v.foul == Foul::wrong_ball_first);
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::anywhere);
    CHECK(game.consecutive_fouls(1) == 1);
}

TEST_CASE("9-ball: a legal pot keeps the table, a legal miss passes it", "[rules][nine]") {
    SECTION("pot") {
        Game game = position(GameType::nine_ball, with_extra(straight_in(1, 4), {2, 9}));
        const Verdict v = game.play(straight_strike(4), {});
        CHECK(v.foul == Foul::none);
        CHECK(v.next_shooter == 1);
    }
    SECTION("a ball to a cushion after contact, nothing down") {
        Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}));
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 1), rail(1)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.next_shooter == 2);
        CHECK(v.ball_in_hand == BallInHand::none);
    }
    SECTION("nothing down and no cushion is a foul") {
        Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}));
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 1)}));
        CHECK(v.foul == Foul::no_rail);
    }
}

TEST_CASE("9-ball: a legal 9 wins, by combination too", "[rules][nine][win]") {
    // The 1 is lined up with the 9 and corner pocket 3: hitting the 1 drives the 9 in.
    const Vec2 out = out_of_pocket(3);
    const Vec2 nine = pocket_at(3) + out * 0.3;
    const Vec2 one = nine + out * (2 * ball_radius + 0.002);
    const Vec2 cue = one + out * 0.3;
    Game game = position(GameType::nine_ball, {ball_at(0, cue.x, cue.y), ball_at(1, one.x, one.y),
                                               ball_at(9, nine.x, nine.y), ball_at(5, 0.5, 1.0)});
    const Verdict v = game.play(straight_strike(3, 3.0), {});
    REQUIRE(std::ranges::count(v.pocketed, 9) == 1);
    CHECK(v.first_contact == 1);
    CHECK(v.winner == 1);
    CHECK(v.reason == WinReason::nine_pocketed);
}

TEST_CASE("9-ball: the 9 on the break wins", "[rules][nine][break]") {
    Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}), 1, Group::open, true);
    const Verdict v = game.apply({}, hand_made(game, {hit(0, 1), hit(1, 9), drop(9, 3)}));
    CHECK(v.winner == 1);
}

TEST_CASE("9-ball: a 9 pocketed on a foul is spotted", "[rules][nine]") {
    Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}));
    const Verdict v = game.apply({}, hand_made(game, {hit(0, 2), hit(2, 9), drop(9, 3)}));
    CHECK(v.foul == Foul::wrong_ball_first);
    CHECK(v.winner == 0);
    CHECK(v.respotted == std::vector<int>{9});
    const Ball nine = find_ball(game.balls(), 9);
    CHECK(nine.state == MotionState::stationary);
    CHECK(nine.position == nine_foot().foot_spot());
}

TEST_CASE(
    "9-ball: a break that drops nothing and drives fewer than four balls to a cushion is a foul",
    "[rules][nine][break]") {
    Game game(GameType::nine_ball, nine_foot(), PhysicsParams{}, 1, 3);
    const Verdict v = game.play({1.2, 0, 0, 0}, {});
    CHECK(v.foul == Foul::bad_break);
    CHECK_FALSE(v.legal_break);
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::anywhere);
}

TEST_CASE("9-ball: three fouls in a row lose the rack", "[rules][nine][fouls]") {
    Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}));
    Verdict v;
    for (int round = 0; round < 3; ++round) {
        // Player 1 fouls (wrong ball), player 2 plays a legal safety.
        v = game.apply({}, hand_made(game, {hit(0, 2), rail(2)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        if (v.winner)
            break;
        CHECK(game.consecutive_fouls(1) == round + 1);
        REQUIRE(game.shooter() == 2);
        v = game.apply({}, hand_made(game, {hit(0, 1), rail(1)}));
        CHECK(v.foul == Foul::none);
    }
    CHECK(v.winner == 2);
    CHECK(v.reason == WinReason::three_fouls);
}

TEST_CASE("9-ball: a legal shot between fouls resets the count", "[rules][nine][fouls]") {
    Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}));
    game.apply({}, hand_made(game, {hit(0, 2), rail(2)})); // 1 fouls
    game.apply({}, hand_made(game, {hit(0, 1), rail(1)})); // 2 legal
    game.apply({}, hand_made(game, {hit(0, 2), rail(2)})); // 1 fouls again
    game.apply({}, hand_made(game, {hit(0, 1), rail(1)})); // 2 legal
    game.apply({}, hand_made(game, {hit(0, 1), rail(1)})); // 1 legal
    CHECK(game.consecutive_fouls(1) == 0);
}

TEST_CASE("9-ball push-out", "[rules][nine][push]") {
    SECTION("right after the break: anything goes, the opponent chooses") {
        Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}), 1, Group::open, true);
        game.apply({}, hand_made(game, {hit(0, 1), drop(2, 3), rail(1)})); // legal break, 1 on
        REQUIRE(game.shooter() == 1);
        REQUIRE(game.push_out_allowed());
        // A push-out that hits nothing and reaches no cushion is no foul.
        const Verdict v = game.apply({{}, true}, hand_made(game, {}));
        CHECK(v.foul == Foul::none);
        CHECK(v.chooser == 2);
        CHECK(v.choices == std::vector<Choice>{Choice::shoot, Choice::pass_back});
        SECTION("shoot") {
            REQUIRE(game.choose(Choice::shoot));
            CHECK(game.shooter() == 2);
        }
        SECTION("pass back") {
            REQUIRE(game.choose(Choice::pass_back));
            CHECK(game.shooter() == 1);
        }
        CHECK_FALSE(game.push_out_allowed());
    }
    SECTION("a scratch on a push-out is still a foul") {
        Game game =
            position(GameType::nine_ball, spread({0, 1, 2, 9}), 1, Group::open, false, true);
        const Verdict v = game.apply({{}, true}, hand_made(game, {drop(0, 2)}));
        CHECK(v.foul == Foul::scratch);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
    SECTION("later in the rack a push-out is not allowed: the shot is judged as usual") {
        Game game = position(GameType::nine_ball, spread({0, 1, 2, 9}));
        REQUIRE_FALSE(game.push_out_allowed());
        const Verdict v = game.apply({{}, true}, hand_made(game, {}));
        CHECK(v.foul == Foul::no_contact);
    }
}
