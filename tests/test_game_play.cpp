// Whole games played to the end by a simple shot picker, with the referee's invariants checked
// after every shot.
#include "support/random.hpp"
#include <algorithm>
#include <catch2/catch.hpp>

#include "rules_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

// Picks a legal target and a pocket at random and aims the ghost ball, at a random firm speed.
// Ball in hand goes to a random legal spot; a choice takes a random option.
struct SimplePicker {
    Random rng;

    void place(Game& game) {
        const std::vector<Vec2> spots = game.legal_placements(10);
        REQUIRE_FALSE(spots.empty());
        REQUIRE(game.place_cue_ball(spots[rng.below(spots.size())]));
    }

    std::pair<Strike, ShotCall> shot(const Game& game) {
        const std::vector<int> targets = game.legal_targets();
        const Ball cue = find_ball(game.balls(), 0);
        const int target = targets[rng.below(targets.size())];
        const int pocket = 1 + static_cast<int>(rng.below(6));
        const Ball object = find_ball(game.balls(), target);
        const Strike strike{rng.uniform(1.5, 5),
                            ghost_aim_deg(cue.position, object.position, pocket_at(pocket)),
                            rng.uniform(-0.2, 0.2), rng.uniform(-0.3, 0.3)};
        ShotCall call;
        if (game.type() != GameType::nine_ball)
            call.call = {target, pocket, false};
        return {strike, call};
    }
};

int play_to_the_end(GameType type, std::uint64_t seed) {
    Game game(type, nine_foot(), PhysicsParams{}, 1 + static_cast<int>(seed % 2), seed);
    SimplePicker picker{Random(seed)};
    const std::size_t ball_count = type == GameType::nine_ball  ? 10
                                   : type == GameType::ten_ball ? 11
                                                                : 16;
    int shots = 0;
    while (game.winner() == 0 && shots < 2000) {
        INFO("seed " << seed << " shot " << shots);
        if (game.chooser() != 0) {
            REQUIRE(game.choose(game.choices()[picker.rng.below(game.choices().size())]));
            continue;
        }
        const Ball cue = find_ball(game.balls(), 0);
        if (game.ball_in_hand() != BallInHand::none &&
            (cue.state == MotionState::pocketed || !game.legal_placement(cue.position)))
            picker.place(game);
        const auto [strike, call] = picker.shot(game);
        const int shooter = game.shooter();
        const Verdict v = game.play(strike, call);
        ++shots;
        // Exactly one shooter, every ball accounted for once.
        REQUIRE((v.next_shooter == 1 || v.next_shooter == 2));
        REQUIRE((game.shooter() == 1 || game.shooter() == 2));
        REQUIRE(game.balls().size() == ball_count);
        for (std::size_t id = 0; id < ball_count; ++id) {
            const int want = static_cast<int>(id);
            REQUIRE(std::ranges::count_if(game.balls(),
                                          [&](const Ball& b) { return b.id == want; }) == 1);
        }
        // A foul always hands the table over with ball in hand (unless it ended the game).
        if (v.foul != Foul::none && v.winner == 0 && !v.stalemate_rerack && v.chooser == 0) {
            REQUIRE(v.next_shooter != shooter);
            REQUIRE(v.ball_in_hand != BallInHand::none);
        }
    }
    CHECK(game.winner() != 0);
    CHECK(game.win_reason() != WinReason::none);
    return shots;
}

} // namespace

TEST_CASE("seeded games are played to their end", "[rules][game]") {
    for (const GameType type : {GameType::eight_ball, GameType::eight_ball_bar, GameType::nine_ball,
                                GameType::ten_ball}) {
        int total = 0;
        for (std::uint64_t seed = 1; seed <= 6; ++seed)
            total += play_to_the_end(type, seed);
        INFO(game_type_name(type) << ": " << total << " shots in 6 games");
        CHECK(total > 6);
    }
}

TEST_CASE("the same seed plays the same game", "[rules][game]") {
    CHECK(play_to_the_end(GameType::eight_ball, 42) == play_to_the_end(GameType::eight_ball, 42));
}
