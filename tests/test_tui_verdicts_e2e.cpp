// Every event told and kept, through the real binary in tmux: the player's foul stays on the
// verdict line while the computer places and plays, the computer's shot leaves the player's
// power as it was, `l` opens the rack's log, and a replay shows each shot's verdict.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>

#include "match_helpers.hpp"
#include "tmux_session.hpp"

using namespace termpool;
using namespace tmux_session;

namespace {

// 9-ball, seed 1, Ann against `opponent` (the computer, or a second player at this terminal):
// Ann turns the cue 60 degrees off the aim guided opens the break with and breaks, hitting a
// wrong ball first; the animation is skipped.
void foul_on_the_break(const Tmux& t, const ScratchDir& dir,
                       const std::string& opponent = "--vs-computer") {
    t.start(game_command(dir, "--game 9ball --player1 Ann " + opponent +
                                  " --seed 1 --race 1 --assist guided"));
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.repeat("Left", 60);
    t.keys("Space");
    REQUIRE(t.wait_for_text("Ann shoots"));
    t.keys("x");
    REQUIRE(t.wait_for_text("Foul: wrong ball first"));
}

} // namespace

TEST_CASE("the player's foul stays on screen while the computer places and plays", "[tui][e2e]") {
    const ScratchDir dir("termpool-verdicts");
    Tmux t;
    foul_on_the_break(t, dir);
    // The computer puts the cue ball down, turns its cue for about three seconds and shoots:
    // the foul is still told. (Behind the foul, the verdict line breaks "CPU (medium) shoots"
    // after "CPU".)
    REQUIRE(t.wait_for_text("(medium) shoots"));
    CHECK(t.screen().find("Foul: wrong ball first") != std::string::npos);
}

TEST_CASE("after the other player's foul, the player with ball in hand is told to place it",
          "[tui][e2e]") {
    const ScratchDir dir("termpool-verdicts");
    Tmux t;
    // Two players at this terminal: Ann fouls on the break as above, and Bob, whose turn it is
    // here, reads why he has ball in hand and what to do with it.
    foul_on_the_break(t, dir, "--player2 Bob");
    // ("... Bob has ball in hand; Bob: place the" and "cue ball anywhere" on the next row.)
    CHECK(t.wait_for_text("Bob has ball in hand; Bob: place the"));
}

TEST_CASE("l opens the rack's log with each shot's verdict", "[tui][e2e]") {
    const ScratchDir dir("termpool-verdicts");
    Tmux t;
    foul_on_the_break(t, dir);
    t.keys("l");
    REQUIRE(t.wait_for_text("Rack 1: the shots"));
    CHECK(t.wait_for_text("1. Ann, break: pocketed 7"));
    CHECK(t.screen().find("wrong ball first") != std::string::npos);
    t.keys("Escape");
    CHECK(t.wait_gone("Rack 1: the shots"));
}

TEST_CASE("a long rack's log pages whole at 100x32", "[tui][e2e]") {
    // A snooker frame of 24 actions, made by the easy computer in both seats and saved for two
    // players: its log's lines are wider than the box and wrap, two rows a shot.
    const ScratchDir dir("termpool-verdicts");
    GameRecord header;
    header.setup.game = GameType::snooker;
    header.setup.table = TableSize::snooker;
    header.seed = 3;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    header.computers[0] = Level::easy;
    header.computers[1] = Level::easy;
    Match match = termpool::test::started(header, 3);
    for (int i = 0; i < 24 && match.pending().kind != Pending::over; ++i)
        REQUIRE(termpool::test::play_computer_move(match) == MatchError::none);
    REQUIRE(match.pending().kind != Pending::over);
    GameRecord record = match.record();
    record.computers[0].reset();
    record.computers[1].reset();
    REQUIRE(std::system(("mkdir -p " + dir.path + "/termpool").c_str()) == 0);
    std::ofstream(dir.save()) << format_record(record);
    Tmux t;
    t.start(game_command(dir, "--resume"));
    REQUIRE(t.wait_for_text("Ann"));
    t.keys("l");
    REQUIRE(t.wait_for_text("Frame 1: the shots"));
    // The box is whole: its footer and bottom corners are on the screen, on every page.
    for (int page = 1;; ++page) {
        INFO("page " << page);
        REQUIRE(t.wait_for_text("page " + std::to_string(page) + "/"));
        const std::string screen = t.screen();
        CHECK(screen.find("Esc closes") != std::string::npos);
        CHECK(screen.find("\u2570") != std::string::npos); // bottom-left corner
        CHECK(screen.find("\u256F") != std::string::npos); // bottom-right corner
        if (screen.find("k back") != std::string::npos)
            break;
        REQUIRE(page < 10);
        t.keys("Space");
    }
    t.keys("Escape");
    CHECK(t.wait_gone("Frame 1: the shots"));
}

TEST_CASE("the computer's shot leaves the player's power as it was", "[tui][e2e]") {
    const ScratchDir dir("termpool-verdicts");
    Tmux t;
    // The break at the aim guided opens it with leaves the table to the computer.
    t.start(
        game_command(dir, "--player1 Ann --vs-computer easy --seed 1 --race 1 --assist guided"));
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("] 12.0 m/s"));
    t.keys("Space");
    REQUIRE(t.wait_for_text("Ann shoots"));
    t.keys("x");
    // The computer plays its shot at 1.6 m/s; Ann's bar is hers again: the 2.3 m/s of her
    // shots before the break.
    REQUIRE(t.wait_for_text("CPU (easy) to shoot"));
    REQUIRE(t.wait_for_text("CPU (easy) shoots"));
    t.keys("x");
    REQUIRE(t.wait_for([](const std::string& s) {
        return s.find("\u25B6 Ann") != std::string::npos &&
               s.find("[ shoot ]") != std::string::npos;
    }));
    CHECK(t.wait_for_text("] 2.3 m/s", 2));
}

TEST_CASE("a replay shows each shot's verdict", "[tui][e2e]") {
    const ScratchDir dir("termpool-replay");
    {
        std::ofstream out(dir.path + "/game.save");
        out << "termpool-record 1\ngame 8ball\ntable 9ft\nseed 3\nbreaker 1\nplayer1 Ann\n"
               "player2 Bob\nshot 12 0 0 0\nshot 2 90 0 0\nend\n";
    }
    Tmux t;
    t.start(game_command(dir, "replay " + dir.path + "/game.save"));
    REQUIRE(t.wait_for_text("Replay, shot 1 of 2"));
    t.keys("x");
    // The break's verdict while the second shot rolls, then the second's once it stops.
    REQUIRE(t.wait_for_text("Replay, shot 2 of 2"));
    CHECK(t.screen().find("Ann shoots again") != std::string::npos);
    t.keys("x");
    REQUIRE(t.wait_for_text("Replay ended"));
    CHECK(t.wait_for_text("Switch player: Bob to shoot", 1));
}
