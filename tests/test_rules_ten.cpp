// The 10-ball referee (WPA rules) and its rack.
#include <algorithm>
#include <catch2/catch.hpp>
#include <termpool/rack.hpp>

#include "rules_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

Call called(int ball, int pocket) {
    return {ball, pocket, false};
}

ShotCall shot_call(int ball, int pocket) {
    return {called(ball, pocket), false};
}

// Spots of the triangle of ten as the rack lays them out, in rack order.
std::vector<Vec2> ten_spots() {
    const std::vector<Ball> rack = make_rack(nine_foot(), PhysicsParams{}, RackType::ten_ball);
    std::vector<Vec2> spots;
    for (const Ball& b : rack)
        if (b.id != 0)
            spots.push_back(b.position);
    return spots;
}

} // namespace

TEST_CASE("10-ball: the names", "[rules][ten]") {
    CHECK(std::string(game_type_name(GameType::ten_ball)) == "10ball");
    for (const char* name : {"10ball", "ten-ball", "10-ball"})
        CHECK(parse_game_type(name) == GameType::ten_ball);
    CHECK(parse_game_type("ten") == std::nullopt);
    CHECK(std::string(win_reason_name(WinReason::ten_pocketed)) == "ten-pocketed");
    CHECK(game_rack(GameType::ten_ball) == RackType::ten_ball);
    CHECK(game_rack(GameType::nine_ball) == RackType::nine_ball);
    CHECK(game_rack(GameType::eight_ball_bar) == RackType::eight_ball);
}

TEST_CASE("10-ball rack: a triangle of ten, the 1 at the apex, the 10 in the middle of the "
          "third row, the 2 and 3 on the back corners",
          "[rules][ten][rack]") {
    const Table& table = nine_foot();
    const PhysicsParams params;
    const double R = params.ball_radius;
    const std::vector<Ball> fixed = make_rack(table, params, RackType::ten_ball);
    REQUIRE(fixed.size() == 11);
    CHECK(find_ball(fixed, 0).position == table.head_spot());
    CHECK(find_ball(fixed, 1).position == table.foot_spot());
    const std::vector<Vec2> spots = ten_spots();
    // Rows of 1, 2, 3, 4 behind the foot spot.
    const double row = (2 * R + rack_gap) * std::numbers::sqrt3 / 2;
    CHECK(spots[4].x == Approx(table.foot_spot().x + 2 * row));
    CHECK(spots[4].y == Approx(table.foot_spot().y));
    CHECK(spots[6].x == Approx(table.foot_spot().x + 3 * row));
    CHECK(spots[9].x == Approx(table.foot_spot().x + 3 * row));
    CHECK(std::abs(spots[6].y - spots[9].y) == Approx(3 * (2 * R + rack_gap)));

    std::vector<std::vector<int>> orders;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const std::vector<Ball> rack = make_rack(table, params, RackType::ten_ball, seed);
        REQUIRE(rack.size() == 11);
        for (int id = 0; id <= 10; ++id)
            CHECK(std::ranges::count_if(rack, [id](const Ball& b) { return b.id == id; }) == 1);
        // Each racked ball is its spot's, give or take the jitter.
        std::vector<int> order;
        for (const Vec2 spot : spots) {
            const auto at = std::ranges::find_if(rack, [&](const Ball& b) {
                return b.id != 0 && length(b.position - spot) < 3 * rack_jitter;
            });
            REQUIRE(at != rack.end());
            order.push_back(at->id);
        }
        CHECK(order[0] == 1);
        CHECK(order[4] == 10);
        CHECK(((order[6] == 2 && order[9] == 3) || (order[6] == 3 && order[9] == 2)));
        orders.push_back(order);
        // No two balls overlap.
        for (std::size_t i = 0; i < rack.size(); ++i)
            for (std::size_t j = i + 1; j < rack.size(); ++j)
                CHECK(length(rack[i].position - rack[j].position) >= 2 * R);
    }
    std::ranges::sort(orders);
    CHECK(std::unique(orders.begin(), orders.end()) - orders.begin() > 6);
}

TEST_CASE("10-ball: a new game racks ten and the 1 is the ball on", "[rules][ten]") {
    const Game game(GameType::ten_ball, nine_foot(), PhysicsParams{}, 2, 5);
    CHECK(game.balls().size() == 11);
    CHECK(game.is_break());
    CHECK(game.shooter() == 2);
    CHECK(game.ball_in_hand() == BallInHand::kitchen);
    CHECK(game.legal_targets() == std::vector<int>{1});
}

TEST_CASE("10-ball: the lowest ball must be hit first", "[rules][ten]") {
    Game game = position(GameType::ten_ball, with_extra(straight_in(3, 4), {1, 10}));
    const Verdict v = game.play(straight_strike(4), shot_call(3, 4));
    CHECK(v.first_contact == 3);
    CHECK(v.foul == Foul::wrong_ball_first);
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::anywhere);
    CHECK(v.chooser == 0);
    CHECK(game.consecutive_fouls(1) == 1);
    // The 3 stays down.
    CHECK(find_ball(game.balls(), 3).state == MotionState::pocketed);
}

TEST_CASE("10-ball: the called ball in the called pocket keeps the table", "[rules][ten]") {
    SECTION("called") {
        Game game = position(GameType::ten_ball, with_extra(straight_in(1, 4), {2, 10}));
        const Verdict v = game.play(straight_strike(4), shot_call(1, 4));
        REQUIRE(std::ranges::count(v.pocketed, 1) == 1);
        CHECK(v.foul == Foul::none);
        CHECK(v.next_shooter == 1);
        CHECK(v.chooser == 0);
        CHECK(game.legal_targets() == std::vector<int>{2});
    }
    SECTION("not called: the referee takes the obvious call") {
        Game game = position(GameType::ten_ball, with_extra(straight_in(1, 4), {2, 10}));
        const Verdict v = game.play(straight_strike(4), {});
        REQUIRE(std::ranges::count(v.pocketed, 1) == 1);
        CHECK(v.next_shooter == 1);
        CHECK(v.chooser == 0);
    }
    SECTION("another ball down with the called one stays down") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 3, 10}));
        const Verdict v = game.apply(
            shot_call(1, 4), hand_made(game, {hit(0, 1), hit(1, 3), drop(1, 4), drop(3, 6)}));
        CHECK(v.next_shooter == 1);
        CHECK(v.chooser == 0);
        CHECK(v.respotted.empty());
        CHECK(find_ball(game.balls(), 3).state == MotionState::pocketed);
    }
}

TEST_CASE("10-ball: a ball down that was not called gives the incoming player the choice",
          "[rules][ten][choice]") {
    SECTION("the called ball in another pocket") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
        const Verdict v = game.apply(shot_call(1, 4), hand_made(game, {hit(0, 1), drop(1, 3)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.chooser == 2);
        CHECK(v.next_shooter == 2);
        CHECK(v.choices == std::vector<Choice>{Choice::shoot, Choice::pass_back});
        CHECK(v.ball_in_hand == BallInHand::none);
        CHECK(find_ball(game.balls(), 1).state == MotionState::pocketed);
        CHECK_FALSE(game.ready_to_shoot());
        SECTION("shoot") {
            REQUIRE(game.choose(Choice::shoot));
            CHECK(game.shooter() == 2);
            CHECK(game.ready_to_shoot());
        }
        SECTION("hand it back") {
            REQUIRE(game.choose(Choice::pass_back));
            CHECK(game.shooter() == 1);
            CHECK(game.ready_to_shoot());
        }
        CHECK(game.chooser() == 0);
        CHECK(game.ball_in_hand() == BallInHand::none);
        CHECK_FALSE(game.push_out_allowed());
    }
    SECTION("another ball than the one called") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
        const Verdict v =
            game.apply(shot_call(1, 4), hand_made(game, {hit(0, 1), hit(1, 2), drop(2, 5)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.chooser == 2);
        CHECK(find_ball(game.balls(), 2).state == MotionState::pocketed);
    }
    SECTION("a call on a ball that the shot could not hit first still has the 1 hit first") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
        const Verdict v =
            game.apply(shot_call(2, 5), hand_made(game, {hit(0, 1), hit(1, 2), drop(2, 5)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.next_shooter == 1); // a combination, called
    }
}

TEST_CASE("10-ball: a miss with nothing down passes the table, no choice", "[rules][ten]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    const Verdict v = game.apply(shot_call(1, 4), hand_made(game, {hit(0, 1), rail(1)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.next_shooter == 2);
    CHECK(v.chooser == 0);
    CHECK(v.ball_in_hand == BallInHand::none);
}

TEST_CASE("10-ball: a called safety passes the table and what dropped stays down", "[rules][ten]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    ShotCall safety;
    safety.call.safety = true;
    const Verdict v = game.apply(safety, hand_made(game, {hit(0, 1), drop(1, 4)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.next_shooter == 2);
    CHECK(v.chooser == 0);
    CHECK(find_ball(game.balls(), 1).state == MotionState::pocketed);
}

TEST_CASE("10-ball: the 10 wins only called, in the called pocket", "[rules][ten][win]") {
    SECTION("the last ball, called, on a real shot") {
        Game game = position(GameType::ten_ball, straight_in(10, 4));
        const Verdict v = game.play(straight_strike(4), shot_call(10, 4));
        REQUIRE(std::ranges::count(v.pocketed, 10) == 1);
        CHECK(v.winner == 1);
        CHECK(v.reason == WinReason::ten_pocketed);
    }
    SECTION("the last ball without a call: the obvious call is the 10 where it dropped") {
        Game game = position(GameType::ten_ball, straight_in(10, 4));
        const Verdict v = game.play(straight_strike(4), {});
        REQUIRE(std::ranges::count(v.pocketed, 10) == 1);
        CHECK(v.winner == 1);
    }
    SECTION("the 10 in another pocket than called is spotted and the choice is the opponent's") {
        Game game = position(GameType::ten_ball, spread({0, 10}));
        const Verdict v = game.apply(shot_call(10, 4), hand_made(game, {hit(0, 10), drop(10, 3)}));
        CHECK(v.winner == 0);
        CHECK(v.respotted == std::vector<int>{10});
        CHECK(find_ball(game.balls(), 10).state == MotionState::stationary);
        CHECK(v.chooser == 2);
    }
}

TEST_CASE("10-ball: the 10 by a combination", "[rules][ten][win]") {
    // The 1 is lined up with the 10 and corner pocket 3: hitting the 1 drives the 10 in.
    const Vec2 out = out_of_pocket(3);
    const Vec2 ten = pocket_at(3) + out * 0.3;
    const Vec2 one = ten + out * (2 * ball_radius + 0.002);
    const Vec2 cue = one + out * 0.3;
    auto layout = [&] {
        return position(GameType::ten_ball, {ball_at(0, cue.x, cue.y), ball_at(1, one.x, one.y),
                                             ball_at(10, ten.x, ten.y), ball_at(5, 0.5, 1.0)});
    };
    SECTION("called: it wins") {
        Game game = layout();
        const Verdict v = game.play(straight_strike(3, 3.0), shot_call(10, 3));
        REQUIRE(std::ranges::count(v.pocketed, 10) == 1);
        CHECK(v.first_contact == 1);
        CHECK(v.winner == 1);
        CHECK(v.reason == WinReason::ten_pocketed);
    }
    SECTION("not called: it is spotted, no win") {
        Game game = layout();
        const Verdict v = game.play(straight_strike(3, 3.0), {});
        REQUIRE(std::ranges::count(v.pocketed, 10) == 1);
        CHECK(v.winner == 0);
        CHECK(v.respotted == std::vector<int>{10});
        const Ball spotted = find_ball(game.balls(), 10);
        CHECK(spotted.state == MotionState::stationary);
        CHECK(spotted.position.y == Approx(nine_foot().foot_spot().y));
    }
}

TEST_CASE("10-ball: the 10 down with the called ball is spotted and the shooter plays on",
          "[rules][ten]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    const Verdict v = game.apply(shot_call(1, 4),
                                 hand_made(game, {hit(0, 1), hit(1, 10), drop(1, 4), drop(10, 3)}));
    CHECK(v.winner == 0);
    CHECK(v.respotted == std::vector<int>{10});
    CHECK(v.next_shooter == 1);
    CHECK(v.chooser == 0);
    CHECK(find_ball(game.balls(), 10).position == nine_foot().foot_spot());
}

TEST_CASE("10-ball: the 10 down on a foul is spotted, ball in hand anywhere", "[rules][ten]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    const Verdict v =
        game.apply(shot_call(10, 3), hand_made(game, {hit(0, 2), hit(2, 10), drop(10, 3)}));
    CHECK(v.foul == Foul::wrong_ball_first);
    CHECK(v.winner == 0);
    CHECK(v.respotted == std::vector<int>{10});
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::anywhere);
    CHECK(find_ball(game.balls(), 10).position == nine_foot().foot_spot());
}

TEST_CASE("10-ball: a scratch is a foul, ball in hand anywhere", "[rules][ten]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    const Verdict v =
        game.apply(shot_call(1, 4), hand_made(game, {hit(0, 1), drop(1, 4), drop(0, 2)}));
    CHECK(v.foul == Foul::scratch);
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::anywhere);
    CHECK(find_ball(game.balls(), 1).state == MotionState::pocketed);
}

TEST_CASE("10-ball break", "[rules][ten][break]") {
    SECTION("the 10 on the break is spotted, not a win; the other balls stay down") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 3, 10}), 1, Group::open, true);
        const Verdict v =
            game.apply({}, hand_made(game, {hit(0, 1), hit(1, 10), drop(10, 3), drop(3, 1)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.winner == 0);
        CHECK(v.respotted == std::vector<int>{10});
        CHECK(find_ball(game.balls(), 10).position == nine_foot().foot_spot());
        CHECK(find_ball(game.balls(), 3).state == MotionState::pocketed);
        CHECK(v.next_shooter == 1);
        CHECK(game.push_out_allowed());
    }
    SECTION("nothing is called on the break: any ball down keeps the table") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 3, 10}), 1, Group::open, true);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 1), hit(1, 2), drop(2, 6)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.next_shooter == 1);
        CHECK(v.chooser == 0);
    }
    SECTION("four balls to a cushion and nothing down: a legal break, the table passes") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 3, 4, 10}), 1, Group::open, true);
        const Verdict v =
            game.apply({}, hand_made(game, {hit(0, 1), rail(1), rail(2), rail(3), rail(4)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.legal_break);
        CHECK(v.next_shooter == 2);
        CHECK(game.push_out_allowed());
    }
    SECTION("the 1 must be hit first on the break") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 3, 10}), 1, Group::open, true);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 2), drop(2, 6)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
    SECTION("a soft break from the rack is a bad break, ball in hand anywhere") {
        Game game(GameType::ten_ball, nine_foot(), PhysicsParams{}, 1, 3);
        const Verdict v = game.play({1.2, 0, 0, 0}, {});
        CHECK(std::ranges::count(v.fouls, Foul::bad_break) == 1);
        CHECK_FALSE(v.legal_break);
        CHECK(v.next_shooter == 2);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
    SECTION("a full break from the rack: the 10 never stays down") {
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            Game game(GameType::ten_ball, nine_foot(), PhysicsParams{}, 1, seed);
            const Verdict v = game.play({12.0, 0, 0, 0}, {});
            CHECK(v.winner == 0);
            CHECK(find_ball(game.balls(), 10).state != MotionState::pocketed);
            CHECK(v.legal_break);
        }
    }
}

TEST_CASE("10-ball push-out", "[rules][ten][push]") {
    SECTION("right after the break: anything goes, the opponent chooses; the 10 is spotted") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}), 1, Group::open, true);
        game.apply({}, hand_made(game, {hit(0, 1), drop(2, 3), rail(1)}));
        REQUIRE(game.shooter() == 1);
        REQUIRE(game.push_out_allowed());
        const Verdict v = game.apply({{}, true}, hand_made(game, {hit(0, 10), drop(10, 4)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.respotted == std::vector<int>{10});
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
            position(GameType::ten_ball, spread({0, 1, 2, 10}), 1, Group::open, false, true);
        const Verdict v = game.apply({{}, true}, hand_made(game, {drop(0, 2)}));
        CHECK(v.foul == Foul::scratch);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
    SECTION("later in the rack a push-out is not allowed: the shot is judged as usual") {
        Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
        REQUIRE_FALSE(game.push_out_allowed());
        const Verdict v = game.apply({{}, true}, hand_made(game, {}));
        CHECK(v.foul == Foul::no_contact);
    }
}

TEST_CASE("10-ball: three fouls in a row lose the rack", "[rules][ten][fouls]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    Verdict v;
    for (int round = 0; round < 3; ++round) {
        v = game.apply({}, hand_made(game, {hit(0, 2), rail(2)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        if (v.winner)
            break;
        CHECK(game.consecutive_fouls(1) == round + 1);
        REQUIRE(game.shooter() == 2);
        v = game.apply(shot_call(1, 4), hand_made(game, {hit(0, 1), rail(1)}));
        CHECK(v.foul == Foul::none);
    }
    CHECK(v.winner == 2);
    CHECK(v.reason == WinReason::three_fouls);
}

TEST_CASE("10-ball: a legal shot between fouls resets the count", "[rules][ten][fouls]") {
    Game game = position(GameType::ten_ball, spread({0, 1, 2, 10}));
    game.apply({}, hand_made(game, {hit(0, 2), rail(2)})); // 1 fouls
    game.apply({}, hand_made(game, {hit(0, 1), rail(1)})); // 2 legal
    game.apply({}, hand_made(game, {hit(0, 2), rail(2)})); // 1 fouls again
    game.apply({}, hand_made(game, {hit(0, 1), rail(1)})); // 2 legal
    game.apply({}, hand_made(game, {hit(0, 1), rail(1)})); // 1 legal
    CHECK(game.consecutive_fouls(1) == 0);
}
