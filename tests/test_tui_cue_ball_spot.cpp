// Where the TUI first puts the cue ball in hand in pool: on the head spot when it is free,
// else on the legal spot nearest it (not the first legal spot of the picker's grid, which may
// be across the table).
#include <algorithm>
#include <catch2/catch.hpp>

#include "rules_helpers.hpp"
#include "tui/cue_ball_spot.hpp"

using namespace termpool;
using namespace termpool::test;

TEST_CASE("pool ball in hand starts on the head spot when it is free", "[tui]") {
    const Vec2 head = nine_foot().head_spot();
    // The break: ball in hand in the kitchen, the head spot free.
    const Game game(GameType::eight_ball, nine_foot(), PhysicsParams{});
    REQUIRE(game.ball_in_hand() == BallInHand::kitchen);
    CHECK(tui::first_cue_ball_spot(game, head) == head);
    // A foul (the cue ball hit nothing): ball in hand anywhere, the head spot still free.
    Game fouled = position(GameType::eight_ball,
                           {ball_at(0, 1.8, 0.6), ball_at(1, 2.0, 1.0), ball_at(8, 1.5, 1.0)});
    fouled.apply({}, hand_made(fouled, {}));
    REQUIRE(fouled.ball_in_hand() == BallInHand::anywhere);
    CHECK(tui::first_cue_ball_spot(fouled, head) == head);
}

TEST_CASE("pool ball in hand starts on the legal spot nearest a taken head spot", "[tui]") {
    const Vec2 head = nine_foot().head_spot();
    // The 1 sits on the head spot; the cue ball hits nothing: ball in hand anywhere.
    Game game = position(GameType::eight_ball,
                         {ball_at(0, 1.8, 0.6), ball_at(1, head.x, head.y), ball_at(8, 1.5, 1.0)});
    game.apply({}, hand_made(game, {}));
    REQUIRE(game.ball_in_hand() == BallInHand::anywhere);
    REQUIRE_FALSE(game.legal_placement(head));
    const Vec2 spot = tui::first_cue_ball_spot(game, head);
    CHECK(game.legal_placement(spot));
    const std::vector<Vec2> spots = game.legal_placements(24);
    REQUIRE_FALSE(spots.empty());
    // The nearest of the picker's spots, a grid step or so from the head spot, not the first.
    for (const Vec2 other : spots)
        CHECK(length(spot - head) <= length(other - head));
    CHECK(length(spot - head) < 0.15);
    CHECK(length(spots.front() - head) > length(spot - head));
}
