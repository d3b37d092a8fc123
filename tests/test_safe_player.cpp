// The scripted safe snooker player of `termpool selfplay --p2 safe`: an easy pot when there is
// one, else a legal safety; its nominations, its placing in the D and its choices are legal.
#include <algorithm>
#include <catch2/catch.hpp>
#include <termpool/safe_player.hpp>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>

#include "snooker_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

constexpr double R = snooker_ball_radius;

Game frame(std::vector<Ball> balls, BallOn on, BallInHand in_hand = BallInHand::none) {
    SnookerState state;
    state.ball_on = on;
    return snooker_frame(std::move(balls), state, in_hand);
}

} // namespace

TEST_CASE("safe player: it pots an easy red", "[safe][snooker]") {
    // A red 0.3 m out of the top right corner on its axis, the cue ball 0.3 m behind it.
    const Pocket& corner = snooker_table().pockets[2];
    const Vec2 in = -corner.capture_normal;
    const Vec2 red = corner.position - in * 0.3;
    const Game game =
        frame(colours_on_spots(red - in * 0.3, {{1, red}, {2, {1.1, 1.6}}}), BallOn::red);
    SafePlayer player(4);
    const ComputerShot shot = player.shot(game);
    CHECK_FALSE(shot.call.call.safety);
    CHECK(shot.call.call.ball == 1);
    Game check = game;
    const Verdict v = check.play(shot.planned, shot.call);
    CHECK(v.foul == Foul::none);
    CHECK(v.points == 1);
}

TEST_CASE("safe player: with no easy pot it plays a legal safety", "[safe][snooker]") {
    // The only red frozen to the top cushion, the cue ball in baulk: nothing to pot.
    const Table& t = snooker_table();
    const Game game = frame(
        colours_on_spots({1.0, t.width / 2}, {{1, {t.length - R - 0.001, 1.4}}}), BallOn::red);
    for (const std::uint64_t seed : {1, 2, 3}) {
        SafePlayer player(seed);
        const ComputerShot shot = player.shot(game);
        INFO("seed " << seed);
        CHECK(shot.call.call.safety);
        Game check = game;
        const Verdict v = check.play(shot.planned, shot.call);
        CHECK(v.foul == Foul::none);
        CHECK(v.first_contact == 1);
        CHECK(v.next_shooter == 2);
        // It leaves the opponent little, by the computer's own measure.
        CHECK(pot_ease(check) < 0.25);
    }
}

TEST_CASE("safe player: on a colour it nominates the colour it plays at", "[safe][snooker]") {
    // After a red, the cue ball on the baulk cushion: no colour is easy from there.
    const Game game = frame(colours_on_spots({R + 0.001, 1.1}, {{1, {2.9, 1.5}}}), BallOn::colour);
    REQUIRE(game.nomination_owed());
    SafePlayer player(7);
    const ComputerShot shot = player.shot(game);
    CHECK(is_snooker_colour(shot.call.call.ball));
    CHECK_FALSE(shot.call.call.safety);
    Game check = game;
    const Verdict v = check.play(shot.planned, shot.call);
    CHECK(v.foul == Foul::none);
    CHECK(v.nominated == shot.call.call.ball);
    CHECK(v.first_contact == shot.call.call.ball);
}

TEST_CASE("safe player: it places the cue ball in the D and breaks off legally",
          "[safe][snooker]") {
    const Table& t = snooker_table();
    // Ball in hand after an in-off: a legal spot in the D.
    std::vector<Ball> balls = colours_on_spots({0.5, 0.5}, {{1, {2.9, 1.5}}, {2, {2.2, 0.4}}});
    balls.erase(balls.begin());
    const Game in_hand = frame(balls, BallOn::red, BallInHand::d);
    SafePlayer player(5);
    const Vec2 spot = player.place_cue_ball(in_hand);
    CHECK(in_hand.legal_placement(spot));
    CHECK(in_snooker_d(t, spot));
    // The break-off: placed in the D, thin off the pack, a legal shot.
    GameSetup setup;
    setup.game = GameType::snooker;
    Game frame_start = make_game(setup, 1, 9);
    REQUIRE(frame_start.is_break());
    const Vec2 from = player.place_cue_ball(frame_start);
    REQUIRE(frame_start.place_cue_ball(from));
    const ComputerShot off = player.shot(frame_start);
    const Verdict v = frame_start.play(off.planned, off.call);
    CHECK(v.foul == Foul::none);
    CHECK(is_snooker_red(v.first_contact));
}

TEST_CASE("safe player: it concedes only a frame it cannot win", "[safe][snooker]") {
    const SafePlayer player(1);
    const Table& t = snooker_table();
    SnookerState state;
    state.ball_on = BallOn::in_order;
    state.scores[1] = 40;
    const Game behind =
        Game::from_snooker_position(t, physics_for_table(TableSize::snooker),
                                    colours_on_spots({0.5, t.width / 2}, {}), 1, state);
    CHECK(player.concedes(behind));
    state.scores[1] = 20;
    const Game close =
        Game::from_snooker_position(t, physics_for_table(TableSize::snooker),
                                    colours_on_spots({0.5, t.width / 2}, {}), 1, state);
    CHECK_FALSE(player.concedes(close));
}
