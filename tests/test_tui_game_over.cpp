// The end of a game in the real binary: the players' figures on the game-over screen, in the
// words of the game played, added to the statistics file under that game, and shown by
// `termpool stats`.
#include <catch2/catch.hpp>
#include <string>

#include "tmux_session.hpp"

using tmux_session::file_text;
using tmux_session::ScratchDir;
using tmux_session::Tmux;

TEST_CASE("game over shows the figures and keeps them for termpool stats", "[tui][e2e][stats]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    // Bar rules, rack seed 121: the full-power break at the aim guided proposes drops the 8,
    // which wins.
    t.start("env XDG_STATE_HOME=" + dir.path + " TERM=xterm-256color LANG=C.UTF-8 " +
            tmux_session::termpool_binary() +
            " --game 8ball-bar --seed 121 --assist guided --player1 Ann --player2 Bob; sleep 60");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.repeat("Up", 40);
    REQUIRE(t.wait_for_text("12.0 m/s"));
    t.keys("Space");
    t.keys("x");
    REQUIRE(t.wait_for_text("rematch", 20));
    const std::string screen = t.screen();
    CHECK(screen.find("Ann pocketed the 8 on the break") != std::string::npos);
    CHECK(screen.find("Racks won") != std::string::npos);
    CHECK(screen.find("Break-and-runs") != std::string::npos);

    CHECK(screen.find("Frame") == std::string::npos);

    // The totals file has the game, as bar rules 8-ball: Ann won the one rack played, from her
    // break.
    const std::string totals = file_text(dir.path + "/termpool/stats");
    CHECK(totals.find("termpool-stats 2\n") == 0);
    CHECK(totals.find(" Ann\n") != std::string::npos);
    CHECK(totals.find("player 8ball-bar 1 1 ") != std::string::npos);
    CHECK(totals.find("player 8ball-bar 0 1 0 ") != std::string::npos); // Bob never shot

    // Quitting a game that is over offers to watch it again, not to continue it.
    t.keys("q");
    // The line is wrapped; the binary is not on the PATH, so it is named as it was started.
    CHECK(t.wait_for_text("watch it again with: " + tmux_session::termpool_binary() + " replay", 10,
                          "e2e", true));
    CHECK(t.screen("e2e", true).find("continue it with") == std::string::npos);

    // termpool stats lists both.
    const std::string listing = tmux_session::run("env XDG_STATE_HOME=" + dir.path + " " +
                                                  tmux_session::termpool_binary() + " stats");
    CHECK(listing.find("8-ball, bar rules\n") == 0);
    CHECK(listing.find("Ann") != std::string::npos);
    CHECK(listing.find("Bob") != std::string::npos);
}

TEST_CASE("a snooker frame's end shows frames and breaks, kept apart from pool's racks",
          "[tui][e2e][stats][snooker]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    t.start("env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path +
                " TERM=xterm-256color LANG=C.UTF-8 " + tmux_session::termpool_binary() +
                " --game snooker --seed 3 --player1 Ann --player2 Bob; sleep 60",
            100, 32);
    REQUIRE(t.wait_for_text("Ann breaks off: place the cue ball in the D"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("Left/Right"));
    t.keys("C");
    REQUIRE(t.wait_for_text("Ann: concede the frame?  y / n"));
    t.keys("y");
    REQUIRE(t.wait_for_text("next frame (the loser breaks off)"));
    const std::string screen = t.screen();
    for (const char* word : {"Frames won", "Frame score", "Highest break", "Centuries"})
        CHECK(screen.find(word) != std::string::npos);
    for (const char* word : {"Racks won", "Break-and-runs", "Longest run"})
        CHECK(screen.find(word) == std::string::npos);

    const std::string totals = file_text(dir.path + "/termpool/stats");
    CHECK(totals.find("\nplayer snooker 0 1 0 ") != std::string::npos); // Ann conceded
    CHECK(totals.find("\nplayer snooker 1 1 0 ") != std::string::npos);
    const std::string listing = tmux_session::run("env XDG_STATE_HOME=" + dir.path + " " +
                                                  tmux_session::termpool_binary() + " stats");
    CHECK(listing.find("Snooker\nPlayer  Frames  Points") == 0);
    CHECK(listing.find("Racks") == std::string::npos);
}
