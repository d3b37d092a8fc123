// The 8-ball referee (WPA and bar rules), mostly on real simulated shots.
#include <algorithm>
#include <catch2/catch.hpp>

#include "rules_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

bool has_foul(const Verdict& v, Foul f) {
    return std::ranges::count(v.fouls, f) > 0;
}

} // namespace

TEST_CASE("a straight-in pot is simulated into its pocket", "[rules][setup]") {
    for (int n = 1; n <= 6; ++n) {
        const ShotResult r =
            simulate_shot(nine_foot(), PhysicsParams{}, straight_in(1, n), straight_strike(n));
        INFO("pocket " << n);
        CHECK(r.balls[1].state == MotionState::pocketed);
        CHECK(r.balls[1].pocket == n);
        CHECK(r.balls[0].state != MotionState::pocketed);
    }
}

TEST_CASE("8-ball break: a legal break keeps the table open and the turn follows the pots",
          "[rules][eight][break]") {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        Game game(GameType::eight_ball, nine_foot(), PhysicsParams{}, 1, seed);
        REQUIRE(game.is_break());
        REQUIRE(game.ball_in_hand() == BallInHand::kitchen);
        ShotResult r;
        const Verdict v = game.play({12, 0, 0, 0}, {}, &r);
        CHECK(v.player1_group == Group::open);
        if (v.foul != Foul::none || v.winner != 0 || v.chooser != 0)
            continue;
        CHECK(v.legal_break);
        const bool potted = std::ranges::any_of(v.pocketed, [](int id) { return id != 0; });
        CHECK(v.next_shooter == (potted ? 1 : 2));
        CHECK_FALSE(game.is_break());
    }
}

TEST_CASE("8-ball break: an illegal break owes the incoming player a choice",
          "[rules][eight][break]") {
    Game game(GameType::eight_ball, nine_foot(), PhysicsParams{}, 1, 5);
    // A soft break barely moves the rack: nothing drops and fewer than four balls reach a rail.
    const Verdict v = game.play({1.2, 0, 0, 0}, {});
    REQUIRE_FALSE(v.legal_break);
    CHECK(v.foul == Foul::none);
    CHECK(v.chooser == 2);
    CHECK(v.choices == std::vector<Choice>{Choice::play_on, Choice::re_rack, Choice::re_break});

    SECTION("play on: player 2 shoots the table as it lies") {
        REQUIRE(game.choose(Choice::play_on));
        CHECK(game.shooter() == 2);
        CHECK_FALSE(game.is_break());
    }
    SECTION("re-rack: player 2 breaks a new rack") {
        REQUIRE(game.choose(Choice::re_rack));
        CHECK(game.shooter() == 2);
        CHECK(game.breaker() == 2);
        CHECK(game.is_break());
        CHECK(game.ball_in_hand() == BallInHand::kitchen);
    }
    SECTION("re-break: player 1 breaks again") {
        REQUIRE(game.choose(Choice::re_break));
        CHECK(game.shooter() == 1);
        CHECK(game.is_break());
    }
    SECTION("a choice that is not offered is refused") {
        CHECK_FALSE(game.choose(Choice::spot_eight));
        CHECK(game.chooser() == 2);
    }
}

TEST_CASE("8-ball break: a scratch gives ball in hand in the kitchen, table open",
          "[rules][eight][break]") {
    Game game = position(GameType::eight_ball, with_extra(straight_in(0, 3), {1, 2, 9}), 1,
                         Group::open, true);
    // The cue ball itself is driven into pocket 3 (no ball in its way).
    std::vector<Ball> balls = game.balls();
    balls.erase(balls.begin() + 1); // the duplicate "ball 0" object of straight_in
    game = position(GameType::eight_ball, balls, 1, Group::open, true);
    const Verdict v = game.play(straight_strike(3), {});
    CHECK(v.foul == Foul::scratch);
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::kitchen);
    CHECK(v.player1_group == Group::open);
    CHECK(game.legal_placement({0.3, 0.6}));
    CHECK_FALSE(game.legal_placement({1.0, 0.6})); // past the head string
}

TEST_CASE("8-ball break: the 8 is not a loss: spot it or break again", "[rules][eight][break]") {
    SECTION("pocketed cleanly: the breaker chooses") {
        Game game = position(GameType::eight_ball, with_extra(straight_in(8, 3), {1, 9}), 1,
                             Group::open, true);
        const Verdict v = game.play(straight_strike(3), {});
        REQUIRE(std::ranges::count(v.pocketed, 8) == 1);
        CHECK(v.winner == 0);
        CHECK(v.chooser == 1);
        CHECK(v.choices == std::vector<Choice>{Choice::spot_eight, Choice::re_break});
        REQUIRE(game.choose(Choice::spot_eight));
        const Ball eight = find_ball(game.balls(), 8);
        CHECK(eight.state == MotionState::stationary);
        CHECK(eight.position == nine_foot().foot_spot());
        CHECK(game.shooter() == 1);
    }
    SECTION("with a scratch: the 8 is spotted, the incoming player has the kitchen") {
        Game game = position(GameType::eight_ball, with_extra(straight_in(8, 3), {1, 9}), 1,
                             Group::open, true);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 8), drop(8, 3), drop(0, 3, 0.4)}));
        CHECK(v.winner == 0);
        CHECK(v.foul == Foul::scratch);
        CHECK(v.respotted == std::vector<int>{8});
        CHECK(v.next_shooter == 2);
        CHECK(v.ball_in_hand == BallInHand::kitchen);
        CHECK(find_ball(game.balls(), 8).state == MotionState::stationary);
    }
    SECTION("the spot is taken: the 8 goes behind it on the long string") {
        std::vector<Ball> balls = with_extra(straight_in(8, 3), {1, 9});
        const Vec2 foot = nine_foot().foot_spot();
        balls.push_back(ball_at(2, foot.x, foot.y));
        Game game = position(GameType::eight_ball, balls, 1, Group::open, true);
        game.play(straight_strike(3), {});
        REQUIRE(game.choose(Choice::spot_eight));
        const Ball eight = find_ball(game.balls(), 8);
        CHECK(eight.position.y == foot.y);
        CHECK(eight.position.x >= foot.x + 2 * ball_radius);
        CHECK(eight.position.x < foot.x + 2 * ball_radius + 0.001);
    }
}

TEST_CASE("8-ball: a called ball on an open table decides the groups", "[rules][eight][groups]") {
    for (const int shooter : {1, 2}) {
        for (const int id : {3, 12}) {
            Game game =
                position(GameType::eight_ball, with_extra(straight_in(id, 6), {1, 8, 9}), shooter);
            const Verdict v = game.play(straight_strike(6), {{id, 6, false}});
            INFO("shooter " << shooter << " ball " << id);
            CHECK(v.foul == Foul::none);
            CHECK(v.groups_assigned);
            CHECK(v.next_shooter == shooter);
            const Group mine = id < 8 ? Group::solids : Group::stripes;
            CHECK(game.group_of(shooter) == mine);
        }
    }
}

TEST_CASE("8-ball: an uncalled shot is called for the shooter when it is obvious",
          "[rules][eight][call]") {
    Game game = position(GameType::eight_ball, with_extra(straight_in(3, 4), {1, 8, 9}));
    const Verdict v = game.play(straight_strike(4), {});
    CHECK(v.groups_assigned);
    CHECK(v.next_shooter == 1);
}

TEST_CASE("8-ball: a ball in a pocket not called stays down and the turn passes",
          "[rules][eight][call]") {
    Game game = position(GameType::eight_ball, with_extra(straight_in(3, 4), {1, 8, 9}));
    const Verdict v = game.play(straight_strike(4), {{3, 5, false}});
    CHECK(v.foul == Foul::none);
    CHECK(std::ranges::count(v.pocketed, 3) == 1);
    CHECK(find_ball(game.balls(), 3).state == MotionState::pocketed);
    CHECK_FALSE(v.groups_assigned);
    CHECK(v.next_shooter == 2);
    CHECK(v.ball_in_hand == BallInHand::none);
}

TEST_CASE("8-ball: a called safety passes the turn even when a ball drops",
          "[rules][eight][call]") {
    Game game =
        position(GameType::eight_ball, with_extra(straight_in(3, 4), {1, 8, 9}), 1, Group::solids);
    const Verdict v = game.play(straight_strike(4), {{0, 0, true}});
    CHECK(v.foul == Foul::none);
    CHECK(std::ranges::count(v.pocketed, 3) == 1);
    CHECK(v.next_shooter == 2);
}

TEST_CASE("8-ball fouls, each on a real shot", "[rules][eight][fouls]") {
    SECTION("wrong ball first: a stripe shooter hits a solid") {
        Game game = position(GameType::eight_ball, with_extra(straight_in(3, 4), {8, 9}), 1,
                             Group::stripes);
        const Verdict v = game.play(straight_strike(4), {});
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.next_shooter == 2);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
    SECTION("open table: the 8 may not be hit first") {
        Game game = position(GameType::eight_ball, with_extra(straight_in(8, 4), {1, 9}));
        game = position(GameType::eight_ball, with_extra(straight_in(8, 4, 0.6), {1, 9}));
        const Verdict v = game.play({0.4, straight_strike(4).angle_deg, 0, 0}, {});
        CHECK(v.first_contact == 8);
        CHECK(has_foul(v, Foul::wrong_ball_first));
    }
    SECTION("no contact: the cue ball meets only a cushion") {
        Game game = position(GameType::eight_ball, with_extra({ball_at(0, 1.2, 0.3)}, {1, 8, 9}), 1,
                             Group::solids);
        const Verdict v = game.play({1.0, -90, 0, 0}, {});
        CHECK(v.first_contact == -1);
        CHECK(v.foul == Foul::no_contact);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
    SECTION("no rail: a soft touch that drops nothing and reaches no cushion") {
        Game game = position(GameType::eight_ball, with_extra(straight_in(3, 4, 0.6), {8, 9}), 1,
                             Group::solids);
        const Verdict v = game.play({0.35, straight_strike(4).angle_deg, 0, 0}, {});
        CHECK(v.first_contact == 3);
        CHECK(v.foul == Foul::no_rail);
    }
    SECTION("scratch: the cue ball follows the object ball in") {
        Game game =
            position(GameType::eight_ball, with_extra(straight_in(3, 4), {8, 9}), 1, Group::solids);
        const Verdict v = game.play({4, straight_strike(4).angle_deg, 0, 0.5}, {});
        REQUIRE(std::ranges::count(v.pocketed, 0) == 1);
        CHECK(v.foul == Foul::scratch);
        CHECK(v.next_shooter == 2);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
        CHECK(game.legal_placement({2.0, 0.6}));
    }
    SECTION("an object ball off the table") {
        Game game = position(GameType::eight_ball, spread({0, 1, 8, 9}), 1, Group::solids);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 1), off(9), rail(1)}));
        CHECK(v.foul == Foul::off_table);
        CHECK(find_ball(game.balls(), 9).state == MotionState::pocketed);
    }
    SECTION("precedence: scratch before wrong ball first before no rail") {
        Game game = position(GameType::eight_ball, spread({0, 1, 8, 9}), 1, Group::solids);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 9), drop(0, 2)}));
        CHECK(v.foul == Foul::scratch);
        CHECK(v.fouls == std::vector<Foul>{Foul::scratch, Foul::wrong_ball_first, Foul::no_rail});
    }
    SECTION("precedence: no contact before no rail") {
        Game game = position(GameType::eight_ball, spread({0, 1, 8, 9}), 1, Group::solids);
        const Verdict v = game.apply({}, hand_made(game, {off(0), off(9)}));
        CHECK(v.fouls == std::vector<Foul>{Foul::cue_off_table, Foul::off_table, Foul::no_contact});
    }
}

TEST_CASE("8-ball: hitting an own ball and another at the same instant is legal",
          "[rules][eight][fouls]") {
    for (const Group group : {Group::solids, Group::stripes}) {
        Game game = position(GameType::eight_ball, spread({0, 1, 8, 9}), 1, group);
        const Verdict v =
            game.apply({}, hand_made(game, {hit(0, 1, 0.1), hit(0, 9, 0.1), rail(9)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.first_contact == (group == Group::solids ? 1 : 9));
    }
}

TEST_CASE("8-ball: pocketing the called 8 after the group wins", "[rules][eight][win]") {
    Game game =
        position(GameType::eight_ball, with_extra(straight_in(8, 1), {9, 10}), 1, Group::solids);
    const Verdict v = game.play(straight_strike(1), {{8, 1, false}});
    CHECK(v.winner == 1);
    CHECK(v.reason == WinReason::eight_pocketed);
    CHECK(game.winner() == 1);
    // Nothing more can be played.
    const Verdict after = game.play({1, 0, 0, 0}, {});
    CHECK(after.pocketed.empty());
    CHECK(game.winner() == 1);
}

TEST_CASE("8-ball: the ways to lose with the 8", "[rules][eight][loss]") {
    SECTION("the 8 before the group is cleared") {
        Game game =
            position(GameType::eight_ball, with_extra(straight_in(8, 1), {2, 9}), 1, Group::solids);
        const Verdict v = game.play(straight_strike(1), {{8, 1, false}});
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_early);
    }
    SECTION("the 8 knocked in by the shooter's own ball") {
        Game game = position(GameType::eight_ball, spread({0, 2, 8, 9}), 1, Group::solids);
        const Verdict v =
            game.apply({{2, 1, false}},
                       hand_made(game, {hit(0, 2), hit(2, 8, 0.2), drop(8, 3, 0.5), rail(2)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_early);
    }
    SECTION("the 8 on the same shot as the group's last ball") {
        Game game = position(GameType::eight_ball, spread({0, 2, 8, 9}), 1, Group::solids);
        const Verdict v =
            game.apply({{8, 3, false}}, hand_made(game, {hit(0, 2), drop(2, 1), drop(8, 3, 0.5)}));
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_early);
    }
    SECTION("the 8 on a foul") {
        Game game =
            position(GameType::eight_ball, with_extra(straight_in(8, 1), {9}), 1, Group::solids);
        const Verdict v = game.play({4, straight_strike(1).angle_deg, 0, 0.5}, {{8, 1, false}});
        REQUIRE(std::ranges::count(v.pocketed, 0) == 1);
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_on_foul);
    }
    SECTION("the 8 in a pocket not called") {
        Game game =
            position(GameType::eight_ball, with_extra(straight_in(8, 1), {9}), 1, Group::solids);
        const Verdict v = game.play(straight_strike(1), {{8, 6, false}});
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_wrong_pocket);
    }
    SECTION("the 8 off the table") {
        Game game = position(GameType::eight_ball, spread({0, 8, 9}), 1, Group::solids);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 8), off(8)}));
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_off_table);
    }
    SECTION("missing the 8 is an ordinary foul") {
        Game game = position(GameType::eight_ball, with_extra({ball_at(0, 1.2, 0.3)}, {8, 9}), 1,
                             Group::solids);
        const Verdict v = game.play({1.0, -90, 0, 0}, {{8, 1, false}});
        CHECK(v.winner == 0);
        CHECK(v.foul == Foul::no_contact);
        CHECK(v.next_shooter == 2);
    }
    SECTION("a scratch while shooting at the 8 without pocketing it is an ordinary foul") {
        Game game = position(GameType::eight_ball, spread({0, 8, 9}), 1, Group::solids);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 8), rail(8), drop(0, 2)}));
        CHECK(v.winner == 0);
        CHECK(v.foul == Foul::scratch);
        CHECK(v.ball_in_hand == BallInHand::anywhere);
    }
}

TEST_CASE("8-ball bar rules", "[rules][eight][bar]") {
    SECTION("the first ball down after the break decides the groups, no call needed") {
        Game game =
            position(GameType::eight_ball_bar, with_extra(straight_in(12, 6), {1, 8, 3}), 2);
        const Verdict v = game.play(straight_strike(6), {});
        CHECK(v.groups_assigned);
        CHECK(game.group_of(2) == Group::stripes);
        CHECK(v.next_shooter == 2);
    }
    SECTION("any ball of the group keeps the turn, wherever it drops") {
        Game game = position(GameType::eight_ball_bar, with_extra(straight_in(3, 4), {1, 8, 9}), 1,
                             Group::solids);
        const Verdict v = game.play(straight_strike(4), {{3, 6, false}});
        CHECK(v.next_shooter == 1);
    }
    SECTION("both groups on the break: the breaker chooses") {
        Game game =
            position(GameType::eight_ball_bar, spread({0, 1, 8, 9, 10}), 1, Group::open, true);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 1), drop(1, 1), drop(9, 3)}));
        CHECK(v.chooser == 1);
        CHECK(v.choices == std::vector<Choice>{Choice::take_solids, Choice::take_stripes});
        REQUIRE(game.choose(Choice::take_stripes));
        CHECK(game.group_of(1) == Group::stripes);
        CHECK(game.group_of(2) == Group::solids);
        CHECK(game.shooter() == 1);
    }
    SECTION("one group on the break goes to the breaker") {
        Game game =
            position(GameType::eight_ball_bar, spread({0, 1, 8, 9, 10}), 2, Group::open, true);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 1), drop(10, 3)}));
        CHECK(v.groups_assigned);
        CHECK(game.group_of(2) == Group::stripes);
    }
    SECTION("the 8 on the break wins") {
        Game game = position(GameType::eight_ball_bar, with_extra(straight_in(8, 3), {1, 9}), 1,
                             Group::open, true);
        const Verdict v = game.play(straight_strike(3), {});
        CHECK(v.winner == 1);
        CHECK(v.reason == WinReason::eight_on_break);
    }
    SECTION("a scratch with the 8 loses, even on the break") {
        Game game = position(GameType::eight_ball_bar, spread({0, 1, 8, 9}), 1, Group::open, true);
        const Verdict v = game.apply({}, hand_made(game, {hit(0, 8), drop(8, 3), drop(0, 2)}));
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::eight_on_foul);
    }
    SECTION("ball in hand only in the kitchen") {
        Game game = position(GameType::eight_ball_bar, with_extra(straight_in(3, 4), {8, 9}), 1,
                             Group::stripes);
        const Verdict v = game.play(straight_strike(4), {});
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.ball_in_hand == BallInHand::kitchen);
        CHECK_FALSE(game.legal_placement({2.0, 0.6}));
        CHECK(game.legal_placement({0.3, 0.6}));
    }
}

TEST_CASE("ball in hand: the cue ball goes only where the rules allow", "[rules][placement]") {
    Game game = position(GameType::eight_ball, spread({0, 1, 8, 9}), 1, Group::solids);
    game.apply({}, hand_made(game, {hit(0, 9), rail(9)})); // wrong ball: 2 has it anywhere
    REQUIRE(game.ball_in_hand() == BallInHand::anywhere);
    const Ball one = find_ball(game.balls(), 1);
    CHECK_FALSE(game.legal_placement(one.position));                                   // on a ball
    CHECK_FALSE(game.legal_placement(one.position + Vec2{2 * ball_radius - 1e-4, 0})); // touching
    CHECK(game.legal_placement(one.position + Vec2{2 * ball_radius + 1e-4, 0}));
    CHECK_FALSE(game.legal_placement({0.01, 0.6})); // in the cushion
    CHECK_FALSE(game.legal_placement({1.0, 1.26})); // in the cushion
    CHECK(game.legal_placement({2.4, 1.1}));
    CHECK_FALSE(game.place_cue_ball({0.01, 0.6}));
    REQUIRE(game.place_cue_ball({2.4, 1.1}));
    CHECK(find_ball(game.balls(), 0).position == Vec2{2.4, 1.1});
    for (const Vec2 p : game.legal_placements())
        CHECK(game.legal_placement(p));
}

TEST_CASE("a stalemate re-racks after three more turns each", "[rules][stalemate]") {
    Game game = position(GameType::eight_ball, spread({0, 1, 8, 9}), 1, Group::open);
    bool reracked = false;
    int shots = 0;
    while (!reracked && shots < 100) {
        const int target = game.shooter() == 1 ? 1 : 9;
        const Verdict v = game.apply({}, hand_made(game, {hit(0, target), rail(target)}));
        reracked = v.stalemate_rerack;
        ++shots;
    }
    CHECK(reracked);
    CHECK(shots == Game::stalemate_warning_turns + 6);
    CHECK(game.is_break());
    CHECK(game.shooter() == game.breaker());
    CHECK(game.balls().size() == 16);
}

TEST_CASE("8-ball groups: in_group agrees with group_balls for every ball", "[rules]") {
    for (const Group group : {Group::open, Group::solids, Group::stripes}) {
        const std::vector<int> balls = group_balls(group);
        for (int id = -1; id <= 16; ++id) {
            INFO("group " << static_cast<int>(group) << ", ball " << id);
            CHECK(in_group(group, id) == (std::ranges::count(balls, id) > 0));
        }
    }
}

TEST_CASE("8-ball legal targets: the shooter's group in order, else the 8", "[rules]") {
    const auto targets = [](std::vector<int> ids, Group group, int shooter = 1) {
        return position(GameType::eight_ball, with_extra(straight_in(3, 4), ids), shooter, group)
            .legal_targets();
    };
    // Open table: every ball on it but the 8, in ascending order whatever the order of balls.
    CHECK(targets({12, 1, 8, 9}, Group::open) == std::vector<int>{1, 3, 9, 12});
    // A group: its own balls only; player 2 has the other group.
    CHECK(targets({12, 1, 8, 9}, Group::solids) == std::vector<int>{1, 3});
    CHECK(targets({12, 1, 8, 9}, Group::solids, 2) == std::vector<int>{9, 12});
    // Ball 3 (the straight-in pot's) is always on. Stripes with one left, then cleared: the 8.
    CHECK(targets({8, 9}, Group::stripes) == std::vector<int>{9});
    CHECK(targets({8}, Group::solids, 2) == std::vector<int>{8});
    CHECK(targets({8, 12}, Group::stripes, 2) == std::vector<int>{3});
    // Only the 8 left on an open table: the 8.
    CHECK(position(GameType::eight_ball, straight_in(8, 4)).legal_targets() == std::vector<int>{8});
    // No object ball on the table: none.
    std::vector<Ball> cue_only = straight_in(3, 4);
    std::erase_if(cue_only, [](const Ball& b) { return b.id != 0; });
    CHECK(position(GameType::eight_ball, cue_only).legal_targets().empty());
}
