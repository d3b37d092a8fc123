// Snooker's break-off as the game proposes it (break_off_strike): from the spot in the D the
// front end first offers, a soft shot that hits a red first, fouls nothing and brings the cue
// ball back behind the baulk line; played as the power bar gives it, the same.
#include <catch2/catch.hpp>
#include <termpool/break_off.hpp>
#include <termpool/rules.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>

#include "tui/aim.hpp"
#include "tui/cue_ball_spot.hpp"

using namespace termpool;

namespace {

const PhysicsParams params = physics_for_table(TableSize::snooker);
const Table table = make_table(TableSize::snooker, params.ball_radius);

// A frame of `seed` with the cue ball placed at `spot` in the D (or where the front end first
// proposes, when none is given).
Game placed_frame(std::uint64_t seed, std::optional<Vec2> spot = std::nullopt) {
    Game game(GameType::snooker, table, params, 1, seed);
    REQUIRE(game.ball_in_hand() == BallInHand::d);
    REQUIRE(game.place_cue_ball(spot ? *spot : tui::first_cue_ball_spot(game, {})));
    return game;
}

Vec2 cue_at_rest(const ShotResult& result) {
    for (const Ball& b : result.balls)
        if (b.id == 0 && b.state != MotionState::pocketed)
            return b.position;
    return {-1, -1};
}

// The end red of the back row on the side of `y` (the yellow's side for y below the middle).
int end_red(const Game& game, double y) {
    const double side = y < table.width / 2 ? -1 : 1;
    const Ball* end = nullptr;
    double back = 0;
    for (const Ball& b : game.balls())
        if (is_snooker_red(b.id))
            back = std::max(back, b.position.x);
    for (const Ball& b : game.balls())
        if (is_snooker_red(b.id) && b.position.x > back - params.ball_radius &&
            (!end || side * b.position.y > side * end->position.y))
            end = &b;
    return end ? end->id : -1;
}

} // namespace

TEST_CASE("the break-off from the first spot in the D is soft, legal and comes back to baulk",
          "[break-off][snooker]") {
    for (const std::uint64_t seed : {1, 2, 3, 7, 11}) {
        CAPTURE(seed);
        Game game = placed_frame(seed);
        const Vec2 cue = game.balls().front().position;
        const Strike strike = break_off_strike(table, params, game.balls());
        CAPTURE(strike.speed, strike.angle_deg);
        // Soft: nothing like a pool break (12 m/s), no spin, a level cue.
        CHECK(strike.speed >= 2.0);
        CHECK(strike.speed <= 4.0);
        CHECK(strike.side == 0);
        CHECK(strike.follow == 0);
        CHECK(strike.elevation_deg == 0);
        // Played as the power bar gives it (the speed through the bar's power and back).
        const Strike played{tui::speed_from_power(tui::power_from_speed(strike.speed, true), true),
                            strike.angle_deg, 0, 0};
        ShotResult result;
        const Verdict verdict = game.play(played, {}, &result);
        // The end red of the pack's back row on the cue ball's side, thin: legal, no pot of a
        // colour, no in-off.
        CHECK(verdict.first_contact == end_red(placed_frame(seed), cue.y));
        CHECK(verdict.foul == Foul::none);
        // The cue ball comes back behind the baulk line, and the pack is hardly opened: the
        // next player is left with nothing.
        CHECK(cue_at_rest(result).x < snooker_baulk_x(table));
        CHECK(verdict.pocketed.empty());
    }
}

TEST_CASE("the break-off from elsewhere in the D clips the end red on the cue ball's side",
          "[break-off][snooker]") {
    const double r = snooker_d_radius_on(table);
    for (const double across : {-0.7, -0.5, -0.3, 0.3, 0.5, 0.7}) {
        CAPTURE(across);
        const Vec2 spot = snooker_d_centre(table) + Vec2{-0.4 * r, across * r};
        Game game = placed_frame(3, spot);
        const Strike strike = break_off_strike(table, params, game.balls());
        ShotResult result;
        const Verdict verdict = game.play(strike, {}, &result);
        CHECK(verdict.first_contact == end_red(placed_frame(3, spot), spot.y));
        CHECK(verdict.foul == Foul::none);
        CHECK(cue_at_rest(result).x < snooker_baulk_x(table));
    }
}

TEST_CASE("without a cue ball or a red the break-off is a plain soft strike",
          "[break-off][snooker]") {
    std::vector<Ball> none;
    const Strike strike = break_off_strike(table, params, none);
    CHECK(strike.speed == break_off_speed);
    CHECK(strike.angle_deg == 0);
}
