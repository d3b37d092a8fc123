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
    if (std::system("command -v tmux >/dev/null 2>&1") != 0) {
        WARN("tmux is missing: the end-to-end test of the game is skipped");
        return;
    }
    const std::string binary = termpool_binary();
    const ScratchDir scratch("termpool-e2e");
    const std::string& dir = scratch.path;
    const std::string status_file = dir + "/status";

    Tmux t;
    t.tmux("new-session -d -s e2e -x 100 -y 32 \"env XDG_STATE_HOME=" + dir +
           " TERM=xterm-256color LANG=C.UTF-8 " + binary + "; echo \\$? > " + status_file +
           "; sleep 60\"");
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
    REQUIRE(t.wait_for_text("Bob, choose", 30));
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
    const std::string status = exit_status(status_file);
    CHECK(status == "0");
    CHECK(t.flag("mouse_any_flag") == "0");
    CHECK(t.flag("mouse_button_flag") == "0");
    std::remove(status_file.c_str());
}

TEST_CASE("the help at 80x24: pages turn with Space, k and PgDn; Esc and q close it",
          "[tui][e2e]") {
    if (std::system("command -v tmux >/dev/null 2>&1") != 0) {
        WARN("tmux is missing: the end-to-end test of the help is skipped");
        return;
    }
    const std::string binary = termpool_binary();
    const ScratchDir scratch("termpool-help");
    const std::string& dir = scratch.path;
    const std::string status_file = dir + "/status";
    Tmux t;
    t.tmux("new-session -d -s e2e -x 80 -y 24 \"env XDG_STATE_HOME=" + dir +
           " TERM=xterm-256color LANG=C.UTF-8 " + binary +
           " --player1 Ann --player2 Bob; echo \\$? > " + status_file + "; sleep 60\"");
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
    CHECK(
        t.wait_for([](const std::string& s) { return s.find("Esc closes") == std::string::npos; }));
    // q closes the help rather than asking to quit; opened again it starts on page 1.
    t.keys("?");
    REQUIRE(t.wait_for_text("page 1/3"));
    t.keys("q");
    CHECK(
        t.wait_for([](const std::string& s) { return s.find("Esc closes") == std::string::npos; }));
    CHECK(t.screen().find("Quit the game?") == std::string::npos);
    t.keys("q");
    REQUIRE(t.wait_for_text("Quit the game?"));
    t.keys("y");
    CHECK(exit_status(status_file) == "0");
    std::remove(status_file.c_str());
}

TEST_CASE("SIGHUP during a shot leaves a save that resumes", "[tui][e2e]") {
    if (std::system("command -v tmux >/dev/null 2>&1") != 0) {
        WARN("tmux is missing: the end-to-end test of saves is skipped");
        return;
    }
    const std::string binary = termpool_binary();
    const ScratchDir scratch("termpool-save");
    const std::string& dir = scratch.path;
    const std::string status_file = dir + "/status";
    const std::string save = dir + "/termpool/game.save";
    const std::string env = "env XDG_STATE_HOME=" + dir + " TERM=xterm-256color LANG=C.UTF-8 ";

    Tmux t;
    t.tmux("new-session -d -s e2e -x 100 -y 32 \"" + env + binary +
           " --player1 Ann --player2 Bob; echo \\$? > " + status_file + "; sleep 60\"");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.keys("Space");
    // Hang up while the break is still rolling.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const std::string pid = run("tmux -L " + t.socket + " display-message -p -t e2e '#{pane_pid}'");
    run("pkill -HUP -P " + pid + " 2>/dev/null");
    const std::string status = exit_status(status_file);
    CHECK(status == "129");
    std::ifstream saved(save);
    std::string text((std::istreambuf_iterator<char>(saved)), std::istreambuf_iterator<char>());
    CHECK(text.find("\nshot 12 ") != std::string::npos); // the break, at full power
    CHECK(text.find("\nend\n") != std::string::npos);

    // Resumed, the game is where the shot left it.
    t.tmux("kill-session -t e2e");
    t.tmux("new-session -d -s e2e -x 100 -y 32 \"" + env + binary + " --resume; sleep 60\"");
    CHECK(t.wait_for_text("Game resumed"));
}

TEST_CASE("a saved game plays back with replay", "[tui][e2e]") {
    if (std::system("command -v tmux >/dev/null 2>&1") != 0) {
        WARN("tmux is missing: the end-to-end test of replays is skipped");
        return;
    }
    const std::string binary = termpool_binary();
    const ScratchDir scratch("termpool-replay");
    const std::string& dir = scratch.path;
    {
        std::ofstream out(dir + "/game.save");
        out << "termpool-record 1\ngame 8ball\ntable 9ft\nseed 3\nbreaker 1\nplayer1 Ann\n"
               "player2 Bob\nshot 12 0 0 0\nshot 2 90 0 0\nend\n";
    }
    const std::string status_file = dir + "/status";
    Tmux t;
    t.tmux("new-session -d -s e2e -x 100 -y 32 \"env TERM=xterm-256color LANG=C.UTF-8 " + binary +
           " replay " + dir + "/game.save; echo \\$? > " + status_file + "; sleep 60\"");
    REQUIRE(t.wait_for_text("Replay, shot 1 of 2"));
    t.keys("Space");
    t.keys("Right");
    CHECK(t.wait_for_text("Ann"));
    t.keys("q");
    const std::string status = exit_status(status_file);
    CHECK(status == "0");
}
