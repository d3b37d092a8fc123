// The hall as its players see it: `termpool hall serve` in a child process and three
// `termpool hall` terminals in tmux at different sizes (100x32, 80x24, 200x60). One creates a
// table, one sits, one watches; the break is played on the first and rolls out on the other
// two, which end with the same balls on the table. Every wait is bounded.
#include <catch2/catch.hpp>
#include <chrono>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "child_process.hpp"
#include "hall/client.hpp"
#include "hall_helpers.hpp"
#include "temp_dir.hpp"
#include "tmux_session.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using tmux_session::file_text;
using tmux_session::termpool_binary;
using tmux_session::Tmux;

namespace {

// `termpool hall serve` on `dir`/hall.sock, once it answers.
std::unique_ptr<ChildProcess> serve(const std::string& dir) {
    const std::string log = dir + "/server.log";
    auto server = std::make_unique<ChildProcess>(
        std::vector<std::string>{termpool_binary(), "hall", "serve", "--socket", dir + "/hall.sock",
                                 "--state", dir + "/state"},
        log,
        std::vector<std::string>{"XDG_RUNTIME_DIR=" + dir + "/runtime",
                                 "XDG_STATE_HOME=" + dir + "/xdg-state", "TMPDIR=" + dir});
    for (const auto end = Clock::now() + kWait;;) {
        HallClient probe;
        if (probe.connect(dir + "/hall.sock").empty())
            return server;
        if (!server->running() || Clock::now() >= end)
            FAIL("the hall did not start:\n" << file_text(log));
        std::this_thread::sleep_for(10ms);
    }
}

// `termpool hall` for `name` in `tmux` at `width` x `height`, its state folder its own.
void open_terminal(const Tmux& tmux, const std::string& dir, const std::string& name, int width,
                   int height) {
    tmux.start("env XDG_STATE_HOME=" + dir + "/state-" + name + " XDG_RUNTIME_DIR=" + dir +
                   "/runtime " + termpool_binary() + " hall --socket " + dir +
                   "/hall.sock --name " + name,
               width, height);
    REQUIRE(tmux.wait_for_text("Welcome, " + name));
}

// The balls the panel's legend lists as on the table, as numbers (10 to 15 may show as A-F).
std::set<int> balls_on_table(const std::string& screen) {
    std::set<int> balls;
    const std::size_t at = screen.find("on table ");
    if (at == std::string::npos)
        return balls;
    std::istringstream words(screen.substr(at + 9, screen.find('\n', at) - at - 9));
    for (std::string w; words >> w;) {
        w = w.substr(0, w.find('='));
        if (w.size() == 1 && w[0] >= 'A' && w[0] <= 'F')
            balls.insert(10 + w[0] - 'A');
        else if (!w.empty() && w.find_first_not_of("0123456789") == std::string::npos)
            balls.insert(std::stoi(w));
    }
    return balls;
}

// While the break rolls the message is "Ann shoots"; after it, "Ann shoots again" or another's
// turn.
bool shot_rolling(const std::string& screen) {
    for (std::size_t at = screen.find("Ann shoots"); at != std::string::npos;
         at = screen.find("Ann shoots", at + 1))
        if (screen.compare(at, 16, "Ann shoots again") != 0)
            return true;
    return false;
}

} // namespace

TEST_CASE("three hall terminals: a table created, a seat taken, a watcher, the break on all "
          "three",
          "[hall][tui][e2e]") {
    TempDir dir("termpool-hall-tui");
    auto server = serve(dir.path());
    Tmux ann, bob, cid;
    open_terminal(ann, dir.path(), "Ann", 100, 32);
    open_terminal(bob, dir.path(), "Bob", 80, 24);
    open_terminal(cid, dir.path(), "Cid", 200, 60);

    ann.keys("c");
    REQUIRE(ann.wait_for_text("A new table"));
    ann.keys("Enter");
    REQUIRE(ann.wait_for_text("Waiting for an opponent"));
    // The lobby is live: the new table shows on the others' screens by itself.
    REQUIRE(bob.wait_for_text("waiting"));
    REQUIRE(bob.screen().find("Ann") != std::string::npos);
    bob.keys("Enter");
    REQUIRE(bob.wait_for_text("Ann breaks"));
    REQUIRE(ann.wait_for_text("Ann breaks"));
    REQUIRE(cid.wait_for_text("playing"));
    cid.keys("w");
    REQUIRE(cid.wait_for_text("Watching."));
    CHECK(balls_on_table(cid.screen()).size() == 15);

    ann.keys("Enter"); // the cue ball where it is offered
    REQUIRE(ann.wait_for_text("Space shoots"));
    ann.keys("Space");
    // The shot reaches the other two screens and rolls out there too.
    CHECK(bob.wait_for([](const std::string& s) { return shot_rolling(s); }));
    CHECK(cid.wait_for([](const std::string& s) { return shot_rolling(s); }));
    std::set<int> left[3];
    const bool settled = ann.wait_for(
        [&](const std::string& a) {
            const std::string b = bob.screen(), c = cid.screen();
            left[0] = balls_on_table(a);
            left[1] = balls_on_table(b);
            left[2] = balls_on_table(c);
            return !shot_rolling(a) && !shot_rolling(b) && !shot_rolling(c) && !left[0].empty() &&
                   left[0] == left[1] && left[1] == left[2];
        },
        20);
    INFO("Ann:\n" << ann.screen() << "\nBob:\n" << bob.screen() << "\nCid:\n" << cid.screen());
    CHECK(settled);

    // Chat: a line typed at one terminal shows in the panel of the others.
    bob.keys("Tab");
    bob.keys("-l 'good break'");
    bob.keys("Enter");
    CHECK(ann.wait_for_text("Bob: good break"));
    CHECK(cid.wait_for_text("Bob: good break"));

    // Leaving goes back to the lobby; the server keeps running and logged nothing bad.
    cid.keys("q");
    CHECK(cid.wait_for_text("Leave the table?"));
    cid.keys("y");
    CHECK(cid.wait_for_text("c create"));
    CHECK(server->running());
}
