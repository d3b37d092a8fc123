// The real binary in tmux, driven as a player would: names, ball in hand, the break, a mouse
// motion, a terminal too small, and quitting.
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "tmux_session.hpp"

using namespace tmux_session;

TEST_CASE("the game in tmux: names, break, mouse aim, resize, quit", "[tui][e2e]") {
    const ScratchDir dir("termpool-e2e");
    Tmux t;
    t.start(game_command(dir, ""));
    REQUIRE(t.wait_for_text("Name of player 1"));

    // Names at the prompt.
    t.keys("-l Ann");
    t.keys("Enter");
    REQUIRE(t.wait_for_text("Name of player 2"));
    t.keys("-l Bob");
    t.keys("Enter");
    // The last question: the race length; Enter keeps a single game.
    REQUIRE(t.wait_for_text("Race to how many racks?"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("place the cue ball"));
    CHECK(t.flag("mouse_any_flag") == "1");

    // Ball in hand in the kitchen: place it where it is, then break softly (minimum power), which
    // cannot be a legal break: the turn goes to Bob with a choice.
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    const std::string before_break = t.screen();
    for (int i = 0; i < 60; ++i)
        t.keys("j");
    t.keys("Space");
    t.keys("x"); // the rest of the shot at once
    REQUIRE(t.wait_for_text("Bob, choose"));
    const std::string after_break = t.screen();
    CHECK(after_break != before_break);
    t.keys("1"); // play on
    REQUIRE(t.wait_for_text("Bob to shoot"));

    // A mouse motion moves the aim.
    const std::string before_mouse = t.screen();
    t.keys(mouse_motion(20, 5));
    CHECK(t.wait_for([&](const std::string& s) { return s != before_mouse; }, 5));

    // Too small: a message, and the game waits; restored, the table is back.
    t.tmux("resize-window -t e2e -x 30 -y 10");
    CHECK(t.wait_for_text("Please enlarge"));
    t.tmux("resize-window -t e2e -x 100 -y 32");
    CHECK(t.wait_for_text("[ shoot ]"));

    // Quit, confirm; the exit status is 0 and mouse reporting is off again.
    t.keys("q");
    REQUIRE(t.wait_for_text("Quit"));
    t.keys("y");
    CHECK(exit_status(dir.status_file()) == "0");
    CHECK(t.flag("mouse_any_flag") == "0");
    CHECK(t.flag("mouse_button_flag") == "0");
}

TEST_CASE("the help at 80x24: pages turn with Space, k and PgDn; Esc and q close it",
          "[tui][e2e]") {
    const ScratchDir dir("termpool-help");
    Tmux t;
    t.start(game_command(dir, "--player1 Ann --player2 Bob"), 80, 24);
    REQUIRE(t.wait_for_text("place the cue ball"));
    CHECK(t.screen().find("? help  q quit") != std::string::npos);
    t.keys("?");
    REQUIRE(t.wait_for_text("page 1/3"));
    t.keys("Space");
    CHECK(t.wait_for_text("page 2/3"));
    t.keys("k");
    CHECK(t.wait_for_text("page 1/3"));
    t.keys("NPage");
    CHECK(t.wait_for_text("page 2/3"));
    t.keys("NPage");
    CHECK(t.wait_for_text("page 3/3"));
    t.keys("Escape");
    CHECK(t.wait_gone("Esc closes"));
    // q closes the help rather than asking to quit; opened again it starts on page 1.
    t.keys("?");
    REQUIRE(t.wait_for_text("page 1/3"));
    t.keys("q");
    CHECK(t.wait_gone("Esc closes"));
    CHECK(t.screen().find("Quit the game?") == std::string::npos);
    t.keys("q");
    REQUIRE(t.wait_for_text("Quit the game?"));
    t.keys("y");
    CHECK(exit_status(dir.status_file()) == "0");
}

TEST_CASE("SIGHUP during a shot leaves a save that resumes", "[tui][e2e]") {
    const ScratchDir dir("termpool-save");
    Tmux t;
    t.start(game_command(dir, "--player1 Ann --player2 Bob"));
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.keys("Space");
    // Hang up while the break is still rolling (the break rolls for seconds).
    REQUIRE(t.wait_for_text("Ann shoots"));
    run("pkill -HUP -P " + t.flag("pane_pid") + " 2>/dev/null");
    CHECK(exit_status(dir.status_file()) == "129");
    const std::string text = file_text(dir.save());
    CHECK(text.find("\nshot 12 ") != std::string::npos); // the break, at full power
    CHECK(text.find("\nend\n") != std::string::npos);

    // Resumed, the game is where the shot left it.
    t.kill_session();
    t.start(game_command(dir, "--resume"));
    const bool resumed = t.wait_for_text("Game resumed");
    INFO(t.screen() << "\nsessions: " << t.tmux("list-sessions")
                    << "status file: " << file_text(dir.status_file()));
    CHECK(resumed);
}

TEST_CASE("a saved game plays back with replay", "[tui][e2e]") {
    const ScratchDir dir("termpool-replay");
    {
        std::ofstream out(dir.path + "/game.save");
        out << "termpool-record 1\ngame 8ball\ntable 9ft\nseed 3\nbreaker 1\nplayer1 Ann\n"
               "player2 Bob\nshot 12 0 0 0\nshot 2 90 0 0\nend\n";
    }
    Tmux t;
    t.start(game_command(dir, "replay " + dir.path + "/game.save"));
    REQUIRE(t.wait_for_text("Replay, shot 1 of 2"));
    t.keys("Space");
    t.keys("Right");
    CHECK(t.wait_for_text("Ann"));
    t.keys("q");
    CHECK(exit_status(dir.status_file()) == "0");
}
