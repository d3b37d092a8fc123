// The snooker referee (WPBSA rules as far as the simulator can judge them): hand-made positions
// and shots, real simulated shots on the snooker table, and a whole frame through the Match.
#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <termpool/match.hpp>
#include <termpool/rack.hpp>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>

#include "match_helpers.hpp"
#include "rules_helpers.hpp"
#include "snooker_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

constexpr double R = snooker_ball_radius;

PhysicsParams snooker_params() {
    return physics_for_table(TableSize::snooker);
}

Ball sball(int id, double x, double y) {
    return snooker_ball(id, {x, y});
}

Ball on_spot(int colour) {
    const Vec2 p = snooker_spot(snooker_table(), colour);
    return sball(colour, p.x, p.y);
}

// The cue ball at (x, y), the reds given at the far side of the table out of every line, and
// the colours given on their spots.
std::vector<Ball> layout(Vec2 cue, std::vector<int> reds, std::vector<int> colours) {
    std::vector<Ball> balls{sball(0, cue.x, cue.y)};
    int k = 0;
    for (const int id : reds) {
        balls.push_back(sball(id, 2.9 + 0.08 * (k / 5), 0.25 + 0.09 * (k % 5)));
        ++k;
    }
    for (const int id : colours)
        balls.push_back(on_spot(id));
    return balls;
}

const std::vector<int> all_colours{16, 17, 18, 19, 20, 21};

Game frame(std::vector<Ball> balls, int shooter = 1, SnookerState state = {},
           BallInHand bih = BallInHand::none) {
    return Game::from_snooker_position(snooker_table(), snooker_params(), std::move(balls), shooter,
                                       state, bih);
}

SnookerState on(BallOn ball_on, int score1 = 0, int score2 = 0) {
    SnookerState s;
    s.ball_on = ball_on;
    s.scores[0] = score1;
    s.scores[1] = score2;
    return s;
}

ShotCall nominate(int ball) {
    ShotCall c;
    c.call.ball = ball;
    return c;
}

bool at(const Game& g, int id, Vec2 p) {
    const Ball b = find_ball(g.balls(), id);
    return b.state != MotionState::pocketed && length(b.position - p) < 1e-12;
}

} // namespace

TEST_CASE("snooker: names, the table and a new frame", "[rules][snooker]") {
    CHECK(std::string(game_type_name(GameType::snooker)) == "snooker");
    CHECK(parse_game_type("snooker") == GameType::snooker);
    CHECK(std::string(choice_name(Choice::offender_plays)) == "offender-plays");
    CHECK(std::string(choice_name(Choice::replace_and_replay)) == "replace-and-replay");
    CHECK(std::string(foul_name(Foul::pot_not_on)) == "pot-not-on");
    CHECK(std::string(ball_in_hand_name(BallInHand::d)) == "d");
    CHECK(std::string(win_reason_name(WinReason::frame_won)) == "frame-won");

    GameSetup setup;
    setup.game = GameType::snooker; // the table left at its default: snooker takes its own
    CHECK(table_played(setup) == TableSize::snooker);
    const Game g = make_game(setup, 1, 7);
    CHECK(g.table().size == TableSize::snooker);
    CHECK(g.params().ball_radius == snooker_ball_radius);
    CHECK(g.balls().size() == 22);
    CHECK(g.ball_in_hand() == BallInHand::d);
    CHECK(g.snooker().ball_on == BallOn::red);
    CHECK(g.legal_targets().size() == 15);
    CHECK(g.points_remaining() == 147);
    CHECK_FALSE(g.nomination_owed());
    CHECK(g.ready_to_shoot()); // the rack leaves the cue ball in the D
    // Ball in hand is in the D only.
    const Vec2 d = snooker_d_centre(g.table());
    CHECK(g.legal_placement(d + Vec2{-0.1, 0.12}));
    CHECK_FALSE(g.legal_placement(d + Vec2{0.05, 0.12}));   // beyond the baulk line
    CHECK_FALSE(g.legal_placement(d + Vec2{-0.05, -0.33})); // outside the arc
    for (const Vec2 p : g.legal_placements())
        CHECK(in_snooker_d(g.table(), p));
}

TEST_CASE("snooker: a red, then the nominated colour, a break", "[rules][snooker]") {
    Game g = frame(layout({1.2, 0.6}, {1, 2}, all_colours));
    Verdict v = g.apply({}, hand_made(g, {hit(0, 1), drop(1, 3)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.points == 1);
    CHECK(v.next_shooter == 1);
    CHECK(g.snooker().ball_on == BallOn::colour);
    CHECK(g.legal_targets() == all_colours);
    CHECK(g.nomination_owed());

    v = g.apply(nominate(snooker_black), hand_made(g, {hit(0, 21), drop(21, 3)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.nominated == snooker_black);
    CHECK(v.points == 7);
    CHECK(v.respotted == std::vector<int>{snooker_black});
    CHECK(at(g, snooker_black, snooker_spot(g.table(), snooker_black)));
    CHECK(g.score_of(1) == 8);
    CHECK(g.snooker().current_break == 8);
    CHECK(g.snooker().ball_on == BallOn::red);

    // A miss ends the visit: the break is kept as the highest.
    v = g.apply({}, hand_made(g, {hit(0, 2), rail(2)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.next_shooter == 2);
    CHECK(g.snooker().highest_break[0] == 8);
    CHECK(g.snooker().current_break == 0);
    CHECK(g.snooker().ball_on == BallOn::red);
}

TEST_CASE("snooker: several reds in one shot count one each", "[rules][snooker]") {
    Game g = frame(layout({1.2, 0.6}, {1, 2, 3}, all_colours));
    const Verdict v = g.apply({}, hand_made(g, {hit(0, 1), hit(1, 2), drop(1, 3), drop(2, 6)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.points == 2);
    CHECK(g.score_of(1) == 2);
}

TEST_CASE("snooker: with no nomination the referee takes the colour hit first",
          "[rules][snooker]") {
    Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, on(BallOn::colour));
    const Verdict v = g.apply({}, hand_made(g, {hit(0, 20), drop(20, 3)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.nominated == snooker_pink);
    CHECK(v.points == 6);
    CHECK(at(g, snooker_pink, snooker_spot(g.table(), snooker_pink)));
}

TEST_CASE("snooker: fouls and their values", "[rules][snooker][foul]") {
    SECTION("a colour hit before the red: the colour's value, at least 4") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 19)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.penalty == 5);
        CHECK(g.score_of(2) == 5);
        CHECK(g.score_of(1) == 0);
        CHECK(v.chooser == 2);
        CHECK(v.choices.front() == Choice::play_on);
        CHECK(std::ranges::count(v.choices, Choice::offender_plays) == 1);
    }
    SECTION("a low colour hit before the red: 4") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 16)}));
        CHECK(v.penalty == 4);
    }
    SECTION("the nominated colour not hit: the higher of the two") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, on(BallOn::colour));
        const Verdict v = g.apply(nominate(snooker_green), hand_made(g, {hit(0, 20)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.penalty == 6);
    }
    SECTION("the nominated colour hit but another potted") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, on(BallOn::colour));
        const Verdict v =
            g.apply(nominate(snooker_blue), hand_made(g, {hit(0, 19), hit(19, 21), drop(21, 3)}));
        CHECK(v.foul == Foul::pot_not_on);
        CHECK(v.penalty == 7);
        CHECK(v.respotted == std::vector<int>{snooker_black});
        CHECK(at(g, snooker_black, snooker_spot(g.table(), snooker_black)));
    }
    SECTION("a colour potted with a red: the red stays down unscored, the colour comes back") {
        Game g = frame(layout({1.2, 0.6}, {1, 2}, all_colours));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 1), drop(1, 3), drop(19, 2)}));
        CHECK(v.foul == Foul::pot_not_on);
        CHECK(v.penalty == 5);
        CHECK(v.points == 0);
        CHECK(g.score_of(1) == 0);
        CHECK(find_ball(g.balls(), 1).state == MotionState::pocketed);
        CHECK(at(g, snooker_blue, snooker_spot(g.table(), snooker_blue)));
        CHECK(g.snooker().ball_on == BallOn::red);
    }
    SECTION("in-off: 4, and the next player has the cue ball in the D") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 1), drop(0, 1)}));
        CHECK(v.foul == Foul::scratch);
        CHECK(v.penalty == 4);
        CHECK(v.ball_in_hand == BallInHand::d);
        CHECK_FALSE(v.free_ball);
        REQUIRE(g.choose(Choice::play_on));
        CHECK(g.shooter() == 2);
        CHECK(g.ball_in_hand() == BallInHand::d);
        CHECK_FALSE(g.ready_to_shoot());
        const Vec2 d = snooker_d_centre(g.table()) + Vec2{-0.1, 0.1};
        CHECK(g.place_cue_ball(d));
        CHECK(g.ready_to_shoot());
    }
    SECTION("a ball off the table: its value, and a colour is re-spotted") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 1), hit(1, 20), off(20)}));
        CHECK(v.foul == Foul::off_table);
        CHECK(v.penalty == 6);
        CHECK(at(g, snooker_pink, snooker_spot(g.table(), snooker_pink)));
    }
    SECTION("no ball hit: the value of the ball on, a miss") {
        Game g = frame(layout({1.2, 0.6}, {}, all_colours), 1, on(BallOn::in_order));
        const Verdict v = g.apply({}, hand_made(g, {rail(0)}));
        CHECK(v.foul == Foul::no_contact);
        CHECK(v.penalty == 4); // the yellow is on: the minimum
        CHECK(v.miss);
    }
}

TEST_CASE("snooker: after a foul the next player plays on or puts the offender back in",
          "[rules][snooker][foul]") {
    Game g = frame(layout({1.2, 0.6}, {1}, all_colours));
    g.apply({}, hand_made(g, {hit(0, 19)}));
    REQUIRE(g.chooser() == 2);
    SECTION("play on") {
        REQUIRE(g.choose(Choice::play_on));
        CHECK(g.shooter() == 2);
    }
    SECTION("the offender plays again") {
        REQUIRE(g.choose(Choice::offender_plays));
        CHECK(g.shooter() == 1);
        CHECK(g.ready_to_shoot());
    }
    CHECK(g.score_of(2) == 5);
}

TEST_CASE("snooker: a miss may have the balls replaced", "[rules][snooker][miss]") {
    Game g = frame(layout({1.2, 0.6}, {1, 2}, all_colours));
    const std::vector<Ball> before = g.balls();
    ShotResult r = hand_made(g, {hit(0, 16), hit(16, 2)});
    for (Ball& b : r.balls) // the shot moved the cue ball and the yellow
        if (b.id == 0 || b.id == 16)
            b.position = b.position + Vec2{0.2, 0.1};
    const Verdict v = g.apply({}, r);
    CHECK(v.foul == Foul::wrong_ball_first);
    CHECK(v.miss);
    REQUIRE(std::ranges::count(v.choices, Choice::replace_and_replay) == 1);
    REQUIRE(g.choose(Choice::replace_and_replay));
    CHECK(g.shooter() == 1);
    CHECK(g.balls() == before);
    CHECK(g.score_of(2) == 4); // the foul's points stay given
    CHECK(g.snooker().ball_on == BallOn::red);
    CHECK(g.ready_to_shoot());
}

TEST_CASE("snooker: three misses in a row, the balls replaced, lose the frame",
          "[rules][snooker][miss]") {
    Game g = frame(layout({1.2, 0.6}, {1, 2}, all_colours));
    for (int miss = 1; miss <= 2; ++miss) {
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 16)}));
        REQUIRE(v.miss);
        CHECK(g.snooker().misses[0] == miss);
        REQUIRE(g.choose(Choice::replace_and_replay));
    }
    SECTION("the third") {
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 16)}));
        CHECK(v.winner == 2);
        CHECK(v.reason == WinReason::three_misses);
        CHECK(g.score_of(2) == 12);
    }
    SECTION("a hit in between starts the count again") {
        g.apply({}, hand_made(g, {hit(0, 1), rail(1)}));
        CHECK(g.snooker().misses[0] == 0);
    }
}

TEST_CASE("snooker: snookered, by the edges of the ball on", "[rules][snooker][free]") {
    const Vec2 cue{2.0, 0.9};
    SECTION("a ball straight in the way") {
        const std::vector<Ball> balls{sball(0, cue.x, cue.y), sball(21, 2.3, 0.9),
                                      sball(1, 2.6, 0.9)};
        CHECK(snookered(balls, cue, {1}, R));
    }
    SECTION("a clear line to both edges") {
        const std::vector<Ball> balls{sball(0, cue.x, cue.y), sball(21, 2.3, 1.2),
                                      sball(1, 2.6, 0.9)};
        CHECK_FALSE(snookered(balls, cue, {1}, R));
    }
    SECTION("one edge blocked is snookered too") {
        // The black covers the line to one edge of the red only.
        const std::vector<Ball> balls{sball(0, cue.x, cue.y), sball(21, 2.3, 0.9 + 2.5 * R),
                                      sball(1, 2.6, 0.9)};
        CHECK(snookered(balls, cue, {1}, R));
    }
    SECTION("one clear ball on is enough") {
        const std::vector<Ball> balls{sball(0, cue.x, cue.y), sball(21, 2.3, 0.9),
                                      sball(1, 2.6, 0.9), sball(2, 1.5, 0.5)};
        CHECK(snookered(balls, cue, {1}, R));
        CHECK_FALSE(snookered(balls, cue, {1, 2}, R));
    }
    SECTION("balls on do not snooker") {
        const std::vector<Ball> balls{sball(0, cue.x, cue.y), sball(2, 2.3, 0.9),
                                      sball(1, 2.6, 0.9)};
        CHECK_FALSE(snookered(balls, cue, {1, 2}, R));
    }
}

TEST_CASE("snooker: a free ball after a foul when snookered", "[rules][snooker][free]") {
    // The only red hides behind the black, seen from the cue ball.
    const Vec2 black = snooker_spot(snooker_table(), snooker_black);
    std::vector<Ball> balls{sball(0, black.x - 0.4, black.y), sball(1, black.x + 0.2, black.y)};
    for (const int id : {16, 17, 18, 19, 20, 21})
        balls.push_back(on_spot(id));
    Game g = frame(balls);
    CHECK(g.shooter_snookered());
    // Snookered, the shooter fails to hit the red: a foul, but not a miss.
    Verdict v = g.apply({}, hand_made(g, {hit(0, 21)}));
    CHECK(v.foul == Foul::wrong_ball_first);
    CHECK(v.penalty == 7);
    CHECK_FALSE(v.miss);
    CHECK(std::ranges::count(v.choices, Choice::replace_and_replay) == 0);
    CHECK(v.free_ball); // the next player is snookered the same way
    CHECK(g.free_ball_offered());
    REQUIRE(g.choose(Choice::play_on));
    CHECK(g.snooker().free_ball);
    CHECK(g.legal_targets().size() == 7); // any ball may be nominated

    SECTION("the free ball potted counts as a red and is re-spotted") {
        v = g.apply(nominate(snooker_black), hand_made(g, {hit(0, 21), drop(21, 3)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.nominated == snooker_black);
        CHECK(v.points == 1);
        CHECK(g.score_of(2) == 8); // 7 for the foul, 1 for the free ball
        CHECK(at(g, snooker_black, black));
        CHECK(g.snooker().ball_on == BallOn::colour);
        CHECK_FALSE(g.snooker().free_ball);
    }
    SECTION("without a nomination the ball hit first is the free ball") {
        ShotResult r = hand_made(g, {hit(0, 21), rail(21)});
        for (Ball& b : r.balls) // the black driven off the line to the red
            if (b.id == snooker_black)
                b.position = b.position + Vec2{0, 0.3};
        v = g.apply({}, r);
        CHECK(v.foul == Foul::none);
        CHECK(v.nominated == snooker_black);
        CHECK(v.next_shooter == 1);
    }
    SECTION("a free ball that leaves the opponent snookered behind it is a foul") {
        v = g.apply(nominate(snooker_black), hand_made(g, {hit(0, 21), rail(21)}));
        CHECK(v.foul == Foul::free_ball_snooker);
        CHECK(v.penalty == 4); // the value of the ball on, a red: the minimum
        CHECK(g.score_of(1) == 4);
    }
    SECTION("the free ball nominated but another colour hit") {
        v = g.apply(nominate(snooker_pink), hand_made(g, {hit(0, 21)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.penalty == 7);
    }
    SECTION("the offender put back in gets no free ball") {
        Game h = frame(balls);
        h.apply({}, hand_made(h, {hit(0, 21)}));
        REQUIRE(h.choose(Choice::offender_plays));
        CHECK_FALSE(h.snooker().free_ball);
    }
}

TEST_CASE("snooker: a free ball in the colours is worth the ball on", "[rules][snooker][free]") {
    // Only the green and the black left: the black hides the green.
    const Vec2 black = snooker_spot(snooker_table(), snooker_black);
    std::vector<Ball> balls{sball(0, black.x - 0.4, black.y), sball(21, black.x, black.y),
                            sball(17, black.x + 0.2, black.y)};
    SnookerState s = on(BallOn::in_order);
    s.free_ball = true;
    Game g = frame(balls, 1, s);
    const Verdict v = g.apply(nominate(snooker_black), hand_made(g, {hit(0, 21), drop(21, 3)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.points == 3);
    CHECK(at(g, snooker_black, black));
    CHECK(g.snooker().ball_on == BallOn::in_order);
    CHECK(g.legal_targets() == std::vector<int>{snooker_green});
}

TEST_CASE("snooker: the colours in order once the reds are gone", "[rules][snooker]") {
    SECTION("the colour after the last red comes back") {
        Game g = frame(layout({1.2, 0.6}, {}, all_colours), 1, on(BallOn::colour));
        const Verdict v = g.apply(nominate(snooker_pink), hand_made(g, {hit(0, 20), drop(20, 3)}));
        CHECK(v.points == 6);
        CHECK(at(g, snooker_pink, snooker_spot(g.table(), snooker_pink)));
        CHECK(g.snooker().ball_on == BallOn::in_order);
        CHECK(g.legal_targets() == std::vector<int>{snooker_yellow});
    }
    SECTION("a missed colour after the last red: the next player is on the yellow") {
        Game g = frame(layout({1.2, 0.6}, {}, all_colours), 1, on(BallOn::colour));
        const Verdict v = g.apply(nominate(snooker_pink), hand_made(g, {hit(0, 20), rail(20)}));
        CHECK(v.next_shooter == 2);
        CHECK(g.snooker().ball_on == BallOn::in_order);
    }
    SECTION("potted in order they stay down") {
        Game g = frame(layout({1.2, 0.6}, {}, all_colours), 1, on(BallOn::in_order));
        Verdict v = g.apply({}, hand_made(g, {hit(0, 16), drop(16, 1)}));
        CHECK(v.points == 2);
        CHECK(v.respotted.empty());
        CHECK(find_ball(g.balls(), 16).state == MotionState::pocketed);
        CHECK(g.legal_targets() == std::vector<int>{snooker_green});
        CHECK(g.points_remaining() == 25);
        // Out of order is a foul, and the colour comes back.
        v = g.apply({}, hand_made(g, {hit(0, 17), hit(17, 18), drop(18, 2)}));
        CHECK(v.foul == Foul::pot_not_on);
        CHECK(v.penalty == 4);
        CHECK(at(g, snooker_brown, snooker_spot(g.table(), snooker_brown)));
    }
    SECTION("the last red potted on a foul: the next player is on the yellow") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours));
        g.apply({}, hand_made(g, {hit(0, 16), hit(16, 1), drop(1, 3)}));
        CHECK(g.snooker().ball_on == BallOn::in_order);
    }
}

TEST_CASE("snooker: the end of the frame", "[rules][snooker][end]") {
    const std::vector<Ball> last{sball(0, 2.8, 0.7), on_spot(snooker_black)};
    SECTION("the last black potted wins on points") {
        Game g = frame(last, 1, on(BallOn::in_order, 40, 45));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 21), drop(21, 3)}));
        CHECK(v.points == 7);
        CHECK(v.winner == 1);
        CHECK(v.reason == WinReason::frame_won);
        CHECK(g.score_of(1) == 47);
    }
    SECTION("a foul on the last black ends the frame") {
        Game g = frame(last, 1, on(BallOn::in_order, 40, 30));
        const Verdict v = g.apply({}, hand_made(g, {rail(0)}));
        CHECK(v.penalty == 7);
        CHECK(v.winner == 1); // 40 to 37
        CHECK(v.chooser == 0);
    }
    SECTION("level scores: a re-spotted black, lots drawn, from the D") {
        Game g = frame(last, 1, on(BallOn::in_order, 40, 47));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 21), drop(21, 3)}));
        CHECK(v.winner == 0);
        CHECK(g.snooker().respotted_black);
        CHECK(v.respotted == std::vector<int>{snooker_black});
        CHECK(g.ball_in_hand() == BallInHand::d);
        CHECK(at(g, snooker_black, snooker_spot(g.table(), snooker_black)));
        CHECK((g.shooter() == 1 || g.shooter() == 2));
        // The next score or foul ends it.
        const int first = g.shooter();
        REQUIRE(g.place_cue_ball(snooker_d_centre(g.table()) + Vec2{-0.1, 0}));
        const Verdict w = g.apply({}, hand_made(g, {rail(0)}));
        CHECK(w.penalty == 7);
        CHECK(w.winner == 3 - first);
    }
    SECTION("a concession") {
        Game g = frame(last, 1, on(BallOn::in_order, 10, 60));
        CHECK(g.concede(1));
        CHECK(g.winner() == 2);
        CHECK(g.win_reason() == WinReason::conceded);
        CHECK_FALSE(g.concede(2));
        Game pool = position(GameType::nine_ball, spread({0, 1, 9}));
        CHECK_FALSE(pool.concede(1));
    }
}

TEST_CASE("snooker: re-spotting a colour", "[rules][snooker][spot]") {
    const Table& t = snooker_table();
    const Vec2 pink = snooker_spot(t, snooker_pink);
    SECTION("its own spot when free") {
        CHECK(snooker_respot(t, {sball(0, 1, 1)}, snooker_pink, R) == pink);
    }
    SECTION("its spot taken: the highest free spot") {
        const std::vector<Ball> balls{sball(1, pink.x, pink.y + 0.01)};
        CHECK(snooker_respot(t, balls, snooker_pink, R) == snooker_spot(t, snooker_black));
        const std::vector<Ball> both{sball(1, pink.x, pink.y + 0.01), on_spot(snooker_black)};
        CHECK(snooker_respot(t, both, snooker_pink, R) == snooker_spot(t, snooker_blue));
    }
    SECTION("every spot taken: straight up the table from its own spot") {
        std::vector<Ball> balls;
        for (const int id : all_colours)
            if (id != snooker_pink)
                balls.push_back(on_spot(id));
        balls.push_back(sball(1, pink.x, pink.y));
        const Vec2 p = snooker_respot(t, balls, snooker_pink, R);
        CHECK(p.y == pink.y);
        CHECK(p.x > pink.x);
        CHECK(p.x < pink.x + 2 * R + 0.001);
    }
    SECTION("a foul's colours are spotted highest first") {
        // The black's spot is taken: black and pink potted on a foul; the black takes the
        // pink's spot (the highest free), the pink is pushed up from its own.
        const Vec2 black = snooker_spot(t, snooker_black);
        std::vector<Ball> balls = layout({1.2, 0.6}, {1}, {16, 17, 18, 19, 20, 21});
        balls.push_back(sball(2, black.x, black.y + 0.01));
        Game g = frame(balls);
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 1), drop(21, 3), drop(20, 6)}));
        CHECK(v.respotted == std::vector<int>{21, 20});
        CHECK(at(g, snooker_black, pink));
        const Ball p = find_ball(g.balls(), snooker_pink);
        CHECK(p.position.y == pink.y);
        CHECK(p.position.x > pink.x);
    }
}

TEST_CASE("snooker: a cue ball touching a ball on plays away without a foul",
          "[rules][snooker][touching]") {
    const std::vector<Ball> balls{sball(0, 2.0, 0.9), sball(1, 2.0 + 2 * R + 0.00005, 0.9),
                                  on_spot(snooker_yellow)};
    Game g = frame(balls);
    CHECK(g.touching_ball() == 1);
    const Verdict v = g.apply({}, hand_made(g, {rail(0)}));
    CHECK(v.foul == Foul::none);
    CHECK(v.next_shooter == 2);
}

TEST_CASE("snooker: real shots on the snooker table", "[rules][snooker][simulated]") {
    const Table& t = snooker_table();
    // A red 0.3 m out of corner pocket 3, the cue ball 0.3 m behind it on the same line.
    const Vec2 pocket = t.pockets[2].position;
    const Vec2 out = normalized(Vec2{-1, 1});
    const Vec2 red = pocket + out * 0.3, cue = red + out * 0.3;
    const double aim = aim_deg(cue, red);
    SECTION("a red potted") {
        Game g = frame({sball(0, cue.x, cue.y), sball(1, red.x, red.y), sball(2, 1.5, 0.5),
                        on_spot(snooker_yellow), on_spot(snooker_black)});
        const Verdict v = g.play({2.0, aim, 0, -0.3}, {});
        REQUIRE(std::ranges::count(v.pocketed, 1) == 1);
        CHECK(v.foul == Foul::none);
        CHECK(v.points == 1);
        CHECK(v.next_shooter == 1);
        CHECK(g.snooker().ball_on == BallOn::colour);
    }
    SECTION("an in-off: the cue ball follows the red in") {
        Game g = frame({sball(0, cue.x, cue.y), sball(1, red.x, red.y), sball(2, 1.5, 0.5),
                        on_spot(snooker_black)});
        const Verdict v = g.play({3.0, aim, 0, 0.5}, {});
        REQUIRE(std::ranges::count(v.pocketed, 0) == 1);
        CHECK(v.foul == Foul::scratch);
        CHECK(v.penalty == 4);
        CHECK(g.score_of(2) == 4);
        CHECK(v.ball_in_hand == BallInHand::d);
    }
    SECTION("the break-off from the D") {
        GameSetup setup;
        setup.game = GameType::snooker;
        Game g = make_game(setup, 1, 3);
        const Ball cue_ball = find_ball(g.balls(), 0);
        // At the red nearest the yellow's side of the pack: the line passes clear of the pink.
        Vec2 apex{0, 1e9};
        for (const Ball& b : g.balls())
            if (is_snooker_red(b.id) && (b.position.y < apex.y - 1e-3 ||
                                         (b.position.y < apex.y + 1e-3 && b.position.x > apex.x)))
                apex = b.position;
        const Verdict v = g.play({4.0, aim_deg(cue_ball.position, apex), 0, 0}, {});
        CHECK(v.first_contact >= 1);
        CHECK(v.first_contact <= 15);
        CHECK(std::ranges::count(v.fouls, Foul::wrong_ball_first) == 0);
        CHECK(g.score_of(1) + g.score_of(2) == v.points + v.penalty);
    }
}

namespace {

GameRecord snooker_header(std::uint64_t seed) {
    GameRecord header;
    header.setup.game = GameType::snooker;
    header.seed = seed;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    return header;
}

int points_of(const std::vector<PlayedShot>& shots, int player) {
    int total = 0;
    for (const PlayedShot& s : shots)
        total += s.shooter == player ? s.verdict.points : s.verdict.penalty;
    return total;
}

} // namespace

TEST_CASE("snooker through the Match: nominations, choices, concession and replay",
          "[snooker][match][record]") {
    Match m = started(snooker_header(11));
    CHECK(m.setup().table == TableSize::snooker);
    CHECK(m.pending().kind == Pending::place);
    CHECK(m.pending().ball_in_hand == BallInHand::d);
    CHECK_FALSE(m.calls_pocket(snooker_black));
    // A shot nominating the black with no pocket: the record can say it.
    ShotCall call;
    call.call.ball = snooker_black;
    const Vec2 apex = find_ball(m.game().balls(), 1).position;
    const Vec2 cue = find_ball(m.game().balls(), 0).position;
    auto played = m.shoot(1, {1.0, aim_deg(cue, apex), 0, 0}, call);
    REQUIRE(std::holds_alternative<PlayedShot>(played));
    ShotCall too_high;
    too_high.call.ball = 22;
    CHECK(std::get<MatchError>(m.shoot(m.to_act(), {1, 0, 0, 0}, too_high)) ==
          MatchError::bad_call);
    // Play on until a foul owes a choice or 30 shots, then concede.
    for (int i = 0; i < 30 && m.pending().kind != Pending::choose; ++i) {
        const Vec2 c = find_ball(m.game().balls(), 0).position;
        const auto on = m.game().legal_targets();
        REQUIRE_FALSE(on.empty());
        const Vec2 target = find_ball(m.game().balls(), on.back()).position;
        if (m.pending().kind == Pending::place)
            REQUIRE(m.place(m.to_act(), snooker_d_centre(m.table()) + Vec2{-0.05, 0.1}) ==
                    MatchError::none);
        played = m.shoot(m.to_act(), {1.5, aim_deg(c, target) + 8, 0, 0}, {});
        REQUIRE(std::holds_alternative<PlayedShot>(played));
    }
    if (m.pending().kind == Pending::choose)
        REQUIRE(m.choose(m.to_act(), m.pending().choices.back()) == MatchError::none);
    const int conceder = m.to_act();
    REQUIRE(m.concede(conceder) == MatchError::none);
    CHECK(m.game().winner() == 3 - conceder);
    CHECK(m.pending().kind == Pending::over);
    // The figures count the frame: won by the other player, played by both.
    CHECK(m.tally().of(3 - conceder).racks_won == 1);
    CHECK(m.tally().of(conceder).racks_won == 0);
    CHECK(m.tally().of(1).racks_played == 1);
    CHECK(m.tally().of(2).racks_played == 1);

    const std::string text = format_record(m.record());
    CHECK(text.find("game snooker") != std::string::npos);
    CHECK(text.find("table snooker") != std::string::npos);
    CHECK(text.find("call 21 0") != std::string::npos);
    CHECK(text.find("choose concede") != std::string::npos);
    const auto parsed = parse_record(text);
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    const auto again = Match::replay(std::get<GameRecord>(parsed));
    REQUIRE(std::holds_alternative<Match>(again));
    const Match& r = std::get<Match>(again);
    CHECK(r.state_hash() == m.state_hash());
    CHECK(r.game().score_of(1) == m.game().score_of(1));
    CHECK(r.game().score_of(2) == m.game().score_of(2));
    CHECK(r.game().win_reason() == WinReason::conceded);
    CHECK(r.tally().both() == m.tally().both());
}

TEST_CASE("snooker: a pool record may not call a snooker ball", "[snooker][record]") {
    GameRecord pool;
    pool.setup.game = GameType::nine_ball;
    Match m = started(pool);
    ShotCall colour;
    colour.call.ball = snooker_yellow;
    colour.call.pocket = 1;
    CHECK(std::get<MatchError>(m.shoot(1, {1, 0, 0, 0}, colour)) == MatchError::bad_call);
    ShotCall no_pocket;
    no_pocket.call.ball = 3;
    CHECK(std::get<MatchError>(m.shoot(1, {1, 0, 0, 0}, no_pocket)) == MatchError::bad_call);

    const auto bad = parse_record("termpool-record 1\ngame 9ball\nshot 1 0 0 0 call 17 0\nend\n");
    REQUIRE(std::holds_alternative<RecordError>(bad));
    CHECK(std::get<RecordError>(bad).line == 3);
    const auto good =
        parse_record("termpool-record 1\ngame snooker\nshot 1 0 0 0 call 17 0\nend\n");
    CHECK(std::holds_alternative<GameRecord>(good));
}

TEST_CASE("snooker: a replace-and-replay survives the record", "[snooker][match][miss]") {
    // Find a shot that misses the reds from the D (straight back at the baulk cushion), so a
    // miss is called; the opponent has the balls replaced.
    Match m = started(snooker_header(5));
    auto played = m.shoot(1, {1.0, 180, 0, 0}, {});
    REQUIRE(std::holds_alternative<PlayedShot>(played));
    const Verdict& v = std::get<PlayedShot>(played).verdict;
    REQUIRE(v.miss);
    REQUIRE(m.pending().kind == Pending::choose);
    REQUIRE(m.choose(2, Choice::replace_and_replay) == MatchError::none);
    CHECK(m.to_act() == 1);
    CHECK(m.game().score_of(2) == 4);
    const auto again = Match::replay(m.record());
    REQUIRE(std::holds_alternative<Match>(again));
    CHECK(std::get<Match>(again).state_hash() == m.state_hash());
    CHECK(std::get<Match>(again).game().balls() == m.game().balls());
}

TEST_CASE("snooker: a whole frame between computers through the Match", "[snooker][match][frame]") {
    GameRecord header = snooker_header(3);
    header.computers[0] = Level::easy;
    header.computers[1] = Level::easy;
    Match m = started(header, 9);
    std::vector<PlayedShot> shots;
    int shots_left = 400;
    while (m.pending().kind != Pending::over && shots_left > 0) {
        const int player = m.to_act();
        const std::optional<ComputerMove> move = m.computer_move();
        REQUIRE(move);
        if (move->kind == Pending::place) {
            REQUIRE(m.place(player, move->spot) == MatchError::none);
        } else if (move->kind == Pending::choose) {
            REQUIRE(m.choose(player, move->choice) == MatchError::none);
        } else {
            auto played = m.shoot(player, move->shot.strike, move->shot.call);
            REQUIRE(std::holds_alternative<PlayedShot>(played));
            shots.push_back(std::get<PlayedShot>(played));
            --shots_left;
        }
        // Invariants: every ball accounted for once, no overlap, the scores the sum of the
        // points scored and given.
        const Game& g = m.game();
        REQUIRE(g.balls().size() == 22);
        for (int id = 0; id < 22; ++id)
            REQUIRE(std::ranges::count_if(g.balls(), [&](const Ball& b) { return b.id == id; }) ==
                    1);
        for (std::size_t i = 0; i < g.balls().size(); ++i)
            for (std::size_t j = i + 1; j < g.balls().size(); ++j) {
                const Ball &a = g.balls()[i], &b = g.balls()[j];
                if (a.state != MotionState::pocketed && b.state != MotionState::pocketed &&
                    a.id != 0 && b.id != 0)
                    REQUIRE(length(a.position - b.position) >= 2 * g.params().ball_radius - 1e-9);
            }
        REQUIRE(g.score_of(1) == points_of(shots, 1));
        REQUIRE(g.score_of(2) == points_of(shots, 2));
        // Colours are never lost while reds remain.
        if (std::ranges::any_of(g.balls(), [](const Ball& b) {
                return is_snooker_red(b.id) && b.state != MotionState::pocketed;
            }))
            for (int id = snooker_yellow; id <= snooker_black; ++id)
                REQUIRE(find_ball(g.balls(), id).state != MotionState::pocketed);
    }
    INFO("shots " << shots.size() << ", score " << m.game().score_of(1) << "-"
                  << m.game().score_of(2));
    CHECK(shots.size() > 10);
    if (m.pending().kind == Pending::over) {
        CHECK(m.game().winner() != 0);
    } else {
        // Unfinished within the bound: the player to act concedes, and the record says so.
        REQUIRE(m.concede(m.to_act()) == MatchError::none);
        CHECK(m.pending().kind == Pending::over);
    }
    const auto again = Match::replay(m.record());
    REQUIRE(std::holds_alternative<Match>(again));
    CHECK(std::get<Match>(again).state_hash() == m.state_hash());
}

TEST_CASE("snooker: a best-of-N match is a race to (N+1)/2, frames rerack the snooker way",
          "[snooker][match][race]") {
    CHECK(race_for_best_of(1) == 1);
    CHECK(race_for_best_of(7) == 4);
    CHECK(race_for_best_of(35) == 18);
    GameRecord header = snooker_header(8);
    header.race_to = race_for_best_of(3);
    Match m = started(header);
    REQUIRE(m.concede(1) == MatchError::none); // frame 1 to player 2
    CHECK(m.score().racks_won[1] == 1);
    REQUIRE(m.pending().kind == Pending::next_rack);
    REQUIRE(m.next_rack(m.to_act()) == MatchError::none);
    CHECK(m.rack() == 2);
    CHECK(m.game().balls().size() == 22);
    CHECK(m.game().score_of(1) == 0);
    CHECK(m.game().score_of(2) == 0);
    CHECK(m.game().ball_in_hand() == BallInHand::d);
    REQUIRE(m.concede(m.to_act()) == MatchError::none);
    const auto again = Match::replay(m.record());
    REQUIRE(std::holds_alternative<Match>(again));
    CHECK(std::get<Match>(again).state_hash() == m.state_hash());
    CHECK(std::get<Match>(again).score().racks_won[0] +
              std::get<Match>(again).score().racks_won[1] ==
          2);
}

TEST_CASE("snooker: the computer breaks off from the D onto a red", "[snooker][computer]") {
    GameSetup setup;
    setup.game = GameType::snooker;
    int fouls = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        Game g = make_game(setup, 1, seed);
        ComputerPlayer computer(Level::medium, seed);
        REQUIRE(g.place_cue_ball(computer.place_cue_ball(g)));
        CHECK(in_snooker_d(g.table(), find_ball(g.balls(), 0).position));
        const ComputerShot shot = computer.shot(g);
        const Verdict v = g.play(shot.strike, shot.call);
        CHECK(is_snooker_red(v.first_contact));
        fouls += v.foul != Foul::none;
    }
    CHECK(fouls <= 1);
}

TEST_CASE("snooker: a real shot away from a touching red is no foul", "[snooker][touching]") {
    // The cue ball rests against a red; it is struck straight away from it, into the open.
    const std::vector<Ball> balls{sball(0, 2.0, 0.9), sball(1, 2.0 + 2 * R + 0.00002, 0.9),
                                  on_spot(snooker_yellow), on_spot(snooker_black)};
    Game g = frame(balls);
    REQUIRE(g.touching_ball() == 1);
    const Verdict v = g.play({1.0, 180, 0, 0}, {});
    CHECK(v.foul == Foul::none);
    CHECK(v.penalty == 0);
    CHECK(v.next_shooter == 2);
    CHECK(find_ball(g.balls(), 1).position == balls[1].position); // the red did not move
}

TEST_CASE("snooker: a nominated free ball must be hit first", "[rules][snooker][free]") {
    // Reds on; a free ball after a foul: the pink is named as the free ball.
    SnookerState s = on(BallOn::red);
    s.free_ball = true;
    SECTION("the red hit first instead, and potted: a foul, no points") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, s);
        const Verdict v = g.apply(nominate(snooker_pink), hand_made(g, {hit(0, 1), drop(1, 3)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.points == 0);
        CHECK(v.penalty == 4);
        CHECK(g.score_of(2) == 4);
    }
    SECTION("the named free ball and a red hit at once: the free ball counts as hit first") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, s);
        const Verdict v =
            g.apply(nominate(snooker_pink), hand_made(g, {hit(0, 1), hit(0, 20), drop(20, 3)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.points == 1); // the free ball is worth a red
    }
    SECTION("with no ball named, the red hit first is playing the ball on") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, s);
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 1), drop(1, 3)}));
        CHECK(v.foul == Foul::none);
        CHECK(v.points == 1);
    }
}

TEST_CASE("snooker: a foul after a red before any colour is nominated costs seven",
          "[rules][snooker][foul]") {
    SECTION("nothing hit") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, on(BallOn::colour));
        const Verdict v = g.apply({}, hand_made(g, {}));
        CHECK(v.foul == Foul::no_contact);
        CHECK(v.penalty == 7);
    }
    SECTION("a red hit first") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, on(BallOn::colour));
        const Verdict v = g.apply({}, hand_made(g, {hit(0, 1)}));
        CHECK(v.foul == Foul::wrong_ball_first);
        CHECK(v.penalty == 7);
    }
    SECTION("a colour named and missed: its value, at least 4") {
        Game g = frame(layout({1.2, 0.6}, {1}, all_colours), 1, on(BallOn::colour));
        const Verdict v = g.apply(nominate(snooker_yellow), hand_made(g, {}));
        CHECK(v.penalty == 4);
    }
}
