// The words at the start of a turn, after a choice and at a break speak to the player who
// acts: the one at this terminal is told what to do (the keys), another seat (the computer,
// another terminal) only has its options described. Snooker says break off, the D and frames.
#include <catch2/catch.hpp>
#include <string>
#include <termpool/match.hpp>
#include <termpool/race.hpp>
#include <termpool/snooker_layout.hpp>

#include "match_helpers.hpp"
#include "player/stats_summary.hpp"
#include "tui/table_news.hpp"
#include "tui/turn_words.hpp"

using namespace termpool;
using namespace termpool::tui;
using termpool::test::started;

namespace {

GameRecord header(GameType game, int race_to = 1) {
    GameRecord h;
    h.setup.game = game;
    h.seed = 3;
    h.names[0] = "Ann";
    h.names[1] = "CPU (pro)";
    h.race_to = race_to;
    return h;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("a push-out is offered to the player here, described of another seat", "[tui][words]") {
    TurnFacts ann;
    ann.who = "Ann";
    ann.push_out = true;
    CHECK(turn_words("", ann) == "Ann: aim and shoot, or u declares a push-out");
    CHECK(turn_words("Switch player: Ann to shoot", ann) ==
          "Switch player: Ann to shoot; u declares a push-out");

    TurnFacts cpu = ann;
    cpu.who = "CPU (pro)";
    cpu.here = false;
    CHECK(turn_words("", cpu) == "CPU (pro) may push out");
    const std::string after = turn_words("Switch player: CPU (pro) to shoot", cpu);
    CHECK(after == "Switch player: CPU (pro) to shoot; CPU (pro) may push out");
    CHECK_FALSE(has(after, "u declares"));
}

TEST_CASE("another seat's turn has no keys and no how-to", "[tui][words]") {
    TurnFacts cpu;
    cpu.who = "CPU (hard)";
    cpu.here = false;
    cpu.mouse = true;
    cpu.nomination = true;
    cpu.line = TargetLine::kick;
    CHECK(turn_words("", cpu).empty());
    CHECK(turn_words("Switch player: CPU (hard) to shoot", cpu) ==
          "Switch player: CPU (hard) to shoot");
    // The same turn here: how to aim, to nominate, and the kick.
    TurnFacts ann = cpu;
    ann.who = "Ann";
    ann.here = true;
    const std::string here = turn_words("", ann);
    CHECK(has(here, "Ann: aim (mouse, Left/Right), Space shoots"));
    CHECK(has(here, "2-7 nominates a colour"));
    CHECK(has(here, "a kick off one rail"));
    ann.free_ball = true;
    CHECK(has(turn_words("", ann), "a free ball: 2-7 nominates it"));
}

TEST_CASE("the break: told to the breaker here, said of another seat; snooker breaks off",
          "[tui][words]") {
    const Match pool = started(header(GameType::eight_ball));
    CHECK(breaks_words(pool, 1, true) == "Ann breaks: place the cue ball in the kitchen");
    CHECK(breaks_words(pool, 2, false) == "CPU (pro) breaks from the kitchen");
    const Match snooker = started(header(GameType::snooker, race_for_best_of(3)));
    CHECK(breaks_words(snooker, 1, true) == "Ann breaks off: place the cue ball in the D");
    CHECK(breaks_words(snooker, 2, false) == "CPU (pro) breaks off from the D");
    CHECK(rack_words(snooker, 2, false) == "Frame 1: CPU (pro) breaks off from the D");
}

TEST_CASE("after an in-off the choice and who plays next name the D", "[tui][words][snooker]") {
    Match m = started(header(GameType::snooker));
    // Ann places the cue ball in the D and sends it straight into the baulk pocket at her
    // side: an in-off, the choice is the other player's.
    const Vec2 spot = snooker_d_centre(m.table()) + Vec2{-0.05, -0.1};
    REQUIRE(m.place(1, spot) == MatchError::none);
    const Vec2 pocket = m.table().pockets[0].position;
    const Vec2 to = pocket - spot;
    const double deg = std::atan2(to.y, to.x) * 180 / 3.14159265358979323846;
    REQUIRE(std::holds_alternative<PlayedShot>(m.shoot(1, {2.0, deg, 0, 0}, {})));
    REQUIRE(m.pending().kind == Pending::choose);
    REQUIRE(m.game().ball_in_hand() == BallInHand::d);
    RecordedAction back_in;
    back_in.kind = RecordedAction::Kind::choose;
    back_in.choice = Choice::offender_plays;
    MatchError error = MatchError::none;
    const auto news = take_action(m, back_in, error);
    REQUIRE(news);
    CHECK(news->words == "CPU (pro) chooses: put the offender back in, the cue ball in the D; Ann "
                         "has ball in hand in the D");
    CHECK(next_words(m) == "Ann has ball in hand in the D");
}

TEST_CASE("the end-of-frame figures speak of frames, points and breaks; pool's of racks",
          "[tui][words][snooker]") {
    Match snooker = started(header(GameType::snooker));
    REQUIRE(snooker.concede(1) == MatchError::none);
    const std::string frame = stats_summary(snooker.record().names, snooker.tally());
    CAPTURE(frame);
    for (const char* row : {"Frames won", "Frame score", "Highest break", "Centuries",
                            "Balls potted", "Pot success", "Fouls"})
        CHECK(has(frame, row));
    for (const char* row : {"Racks won", "Break-and-runs", "Longest run"})
        CHECK_FALSE(has(frame, row));
    const Match pool = started(header(GameType::nine_ball));
    const std::string rack = stats_summary(pool.record().names, pool.tally());
    CHECK(has(rack, "Racks won"));
    CHECK(has(rack, "Break-and-runs"));
    CHECK_FALSE(has(rack, "Frame"));
}
