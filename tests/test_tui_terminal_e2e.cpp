// The terminal side of the real binary in tmux: a terminal that goes away, and a terminal
// (vt100) whose mouse reports curses cannot decode, and one (dumb) that cannot move the cursor.
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <string>
#include <sys/stat.h>
#include <thread>

#include "tmux_session.hpp"

using namespace tmux_session;

namespace {

// True when the process is gone (or a zombie, which no longer runs).
bool process_gone(const std::string& pid) {
    const std::string stat = file_text("/proc/" + pid + "/stat");
    const std::size_t paren = stat.rfind(')');
    return stat.empty() || (paren + 2 < stat.size() && stat[paren + 2] == 'Z');
}

} // namespace

TEST_CASE("a terminal that goes away ends the game within a second, saved", "[tui][e2e]") {
    const ScratchDir dir("termpool-hangup");
    Tmux t;
    // Another session keeps the server alive once the game's session is killed. The shell
    // ignores SIGHUP and the game is not the session leader, so no SIGHUP reaches it: only
    // the hangup of its terminal tells it to leave (as under a parent that does not pass it on).
    t.start("sleep 60", 100, 32, "keep");
    t.start("trap '' HUP; " +
            game_command(dir, "--player1 Ann --player2 Bob", "xterm-256color", false));
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.keys("Space");
    // The terminal goes away while the break rolls.
    REQUIRE(t.wait_for_text("Ann shoots"));
    std::string game_pid = run("pgrep -P " + t.flag("pane_pid"));
    while (!game_pid.empty() && game_pid.back() == '\n')
        game_pid.pop_back();
    REQUIRE(!game_pid.empty());

    t.kill_session();
    const auto killed = std::chrono::steady_clock::now();
    wait_until([&] { return process_gone(game_pid); }, 3);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
    const bool gone = process_gone(game_pid);
    if (!gone)
        ::kill(std::stoi(game_pid), SIGKILL); // the defect: it would spin forever
    CHECK(gone);
    CHECK(seconds < 1.0);
    CHECK(exit_status(dir.status_file()) == "129");
    const std::string text = file_text(dir.save());
    CHECK(text.find("\nplace ") != std::string::npos);
    CHECK(text.find("\nshot ") != std::string::npos); // the break, saved on the way out
    CHECK(text.find("\nend\n") != std::string::npos);
}

TEST_CASE("vt100: no mouse tracking, a stray click report does not shoot, the screen is cleared",
          "[tui][e2e]") {
    const ScratchDir dir("termpool-vt100");
    Tmux t;
    t.start(game_command(dir, "--player1 Ann --player2 Bob", "vt100"));
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    // vt100's terminfo has no kmous: curses cannot decode reports, so none are asked for.
    CHECK(t.flag("mouse_any_flag") == "0");
    CHECK(t.flag("mouse_button_flag") == "0");
    CHECK(t.flag("mouse_standard_flag") == "0");

    // What a terminal would send anyway: an X10 press and release (button byte 0x20, a Space)
    // and an SGR press and release. None of it may act as a key.
    const std::string before = t.screen();
    t.keys("-H 1b 5b 4d 20 41 31");
    t.keys("-H 1b 5b 4d 23 41 31");
    t.keys("-H 1b 5b 3c 30 3b 33 33 3b 31 37 4d");
    t.keys("-H 1b 5b 3c 30 3b 33 33 3b 31 37 6d");
    // Keys are read in order: once the help that ? opens is up, and closed again, the reports
    // before it have been read, and the screen is what it was.
    t.keys("?");
    REQUIRE(t.wait_for_text("Esc closes"));
    t.keys("Escape");
    REQUIRE(t.wait_gone("Esc closes"));
    CHECK(t.wait_for([&](const std::string& s) { return s == before; }, 2));
    CHECK(t.screen() == before);
    CHECK(file_text(dir.save()).find("\nshot ") == std::string::npos);

    // Arrows still work (the pane sends ESC O D in keypad mode).
    t.keys("Left");
    CHECK(t.wait_for([&](const std::string& s) { return s != before; }, 5));

    // No alternate screen to return from: the table must not stay behind.
    t.keys("q");
    REQUIRE(t.wait_for_text("Quit"));
    t.keys("y");
    CHECK(exit_status(dir.status_file()) == "0");
    const std::string after = t.screen();
    CHECK(after.find("[ shoot ]") == std::string::npos);
    CHECK(after.find("open table") == std::string::npos);
}

TEST_CASE("a terminal that cannot move the cursor (TERM=dumb) is refused with a message",
          "[tui][e2e]") {
    const ScratchDir dir("termpool-dumb");
    Tmux t;
    t.start(game_command(dir, "--player1 Ann --player2 Bob", "dumb"));
    REQUIRE(t.wait_for_text("cannot move the cursor"));
    CHECK(exit_status(dir.status_file()) == "1");
    const std::string screen = t.screen();
    CHECK(screen.find("termpool: this terminal (TERM=dumb) cannot move the cursor, which the game "
                      "needs") != std::string::npos);
    // Refused before a game began: nothing was saved, and the table was never written out.
    CHECK(file_text(dir.save()).empty());
    CHECK(screen.find("on table") == std::string::npos);
}
