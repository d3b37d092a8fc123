// The cue's elevation through the real binary in tmux, as a player meets it: the help names
// the keys, e raises the cue and the screen says so, a cue raised too steeply for the power is
// not shot and the message says why, and a slightly raised cue breaks.
#include <catch2/catch.hpp>
#include <string>

#include "tmux_session.hpp"

using tmux_session::ScratchDir;
using tmux_session::Tmux;

TEST_CASE("the game in tmux: e raises the cue, a jump is refused, the raised cue shoots",
          "[tui][e2e][cue]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    // Seed 1, the break at the aim guided proposes: the next turn is not Ann's.
    t.start("env XDG_STATE_HOME=" + dir.path + " TERM=xterm-256color LANG=C.UTF-8 " +
            tmux_session::termpool_binary() +
            " --player1 Ann --player2 Bob --seed 1 --assist guided; sleep 60");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    REQUIRE(t.wait_for_text("] 12.0 m/s"));
    CHECK(t.wait_for_text("elev 0\u00B0"));

    // The help names the keys.
    t.keys("?");
    REQUIRE(t.wait_for_text("raise / lower the cue 5 degrees"));
    CHECK(t.wait_for_text("level the cue"));
    t.keys("Escape");
    REQUIRE(t.wait_for([](const std::string& s) { return s.find("level the cue") == s.npos; }));

    t.keys("e");
    REQUIRE(t.wait_for_text("elev 5\u00B0"));

    // 60 degrees at the break's 12 m/s would drive the ball into the slate and jump: not shot.
    t.repeat("e", 11);
    REQUIRE(t.wait_for_text("elev 60\u00B0"));
    t.keys("Space");
    REQUIRE(t.wait_for_text("Not played:"));
    CHECK(t.wait_for_text("jump"));
    CHECK(t.screen().find("Ann shoots") == std::string::npos);
    CHECK(t.wait_for_text("[ shoot ]"));

    // Level again, raised a little, and the break goes.
    t.keys("v");
    REQUIRE(t.wait_for_text("elev 0\u00B0"));
    t.keys("e");
    REQUIRE(t.wait_for_text("elev 5\u00B0"));
    t.keys("Space");
    REQUIRE(t.wait_for_text("Ann shoots"));
    t.keys("x");
    // The next turn starts with a level cue.
    CHECK(t.wait_for(
        [](const std::string& s) {
            return s.find("Ann shoots") == s.npos && s.find("elev 5\u00B0") == s.npos;
        },
        30));
}
