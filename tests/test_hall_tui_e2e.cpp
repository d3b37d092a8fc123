// The hall as its players see it: `termpool hall serve` in a child process and `termpool
// hall` terminals in tmux at different sizes (100x32, 80x24, 200x60), all under one account's
// folders as friends over SSH are. One creates a table, one sits, one watches; the break is
// played on the first and rolls out on the others. A terminal killed mid-shot comes back to
// its seat; a server killed mid-game is started again by the terminals and the game goes on.
// Every wait is bounded; a server a terminal started is stopped by its pid.
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "child_process.hpp"
#include "hall/client.hpp"
#include "hall_helpers.hpp"
#include "temp_dir.hpp"
#include "tmux_session.hpp"
#include "tui/aim.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using tmux_session::file_text;
using tmux_session::termpool_binary;
using tmux_session::Tmux;

namespace {

// The account's folders: the server and every terminal share them, as the pool account does.
std::string account_env(const std::string& dir) {
    return "XDG_STATE_HOME=" + dir + "/xdg-state XDG_RUNTIME_DIR=" + dir + "/runtime";
}

// `termpool hall serve` on `dir`/hall.sock, its tables in the account's state folder, once it
// answers.
std::unique_ptr<ChildProcess> serve(const std::string& dir) {
    const std::string log = dir + "/server.log";
    auto server = std::make_unique<ChildProcess>(
        std::vector<std::string>{termpool_binary(), "hall", "serve", "--socket",
                                 dir + "/hall.sock"},
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

// `termpool hall` for `name` in `tmux` at `width` x `height`.
void open_terminal(const Tmux& tmux, const std::string& dir, const std::string& name, int width,
                   int height) {
    tmux.start("env " + account_env(dir) + " " + termpool_binary() + " hall --socket " + dir +
                   "/hall.sock --name " + name,
               width, height);
    REQUIRE(tmux.wait_for_text("Welcome, " + name));
}

// The player at `tmux` creates a table with the form's first settings and sits at it.
void create_table(const Tmux& tmux) {
    tmux.keys("c");
    REQUIRE(tmux.wait_for_text("A new table"));
    tmux.keys("Enter");
    REQUIRE(tmux.wait_for_text("Waiting for an opponent"));
}

// The lobby on `tmux` shows a table whose creator `name` has sat down: between the create and
// the creator's sit the row shows both seats empty, and Enter then would pick seat 1.
bool lobby_shows_seated(const Tmux& tmux, const std::string& name) {
    return tmux.wait_for([&](const std::string& s) {
        std::istringstream lines(s);
        for (std::string line; std::getline(lines, line);)
            if (line.find("waiting") != std::string::npos && line.find(name) != std::string::npos)
                return true;
        return false;
    });
}

// A server the terminals started themselves: stopped with SIGTERM by the pid its socket
// gives, and waited for (this machine's init may leave it a zombie, which runs nothing).
struct StartedServer {
    std::string socket;
    ~StartedServer() {
        HallClient probe;
        if (!probe.connect(socket).empty())
            return;
        const pid_t pid = probe.server_pid();
        probe.disconnect();
        if (pid <= 0)
            return;
        ::kill(pid, SIGTERM);
        for (const auto end = Clock::now() + kWait; Clock::now() < end;) {
            std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
            std::string pid_field, comm, state;
            if (!(stat >> pid_field >> comm >> state) || state == "Z")
                return;
            std::this_thread::sleep_for(20ms);
        }
        ::kill(pid, SIGKILL);
    }
};

// The balls the panel's legend lists as on the table, as numbers (10 to 15 may show as A-F);
// none when the legend is missing or a box (a choice, game over) covers part of it.
std::set<int> balls_on_table(const std::string& screen) {
    std::set<int> balls;
    const std::size_t at = screen.find("on table ");
    if (at == std::string::npos)
        return balls;
    const std::string legend = screen.substr(at + 9, screen.find('\n', at) - at - 9);
    for (const char* box : {"\u2502", "\u2570", "\u256F", "\u2500"})
        if (legend.find(box) != std::string::npos)
            return balls;
    std::istringstream words(legend);
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
bool shot_rolling(const std::string& screen, const std::string& who = "Ann") {
    const std::string shoots = who + " shoots";
    for (std::size_t at = screen.find(shoots); at != std::string::npos;
         at = screen.find(shoots, at + 1))
        if (screen.compare(at, shoots.size() + 6, shoots + " again") != 0)
            return true;
    return false;
}

// True when the player at this screen owes a choice (the others' screens say whom they wait for).
bool owes_choice(const std::string& screen) {
    return screen.find(", choose:") != std::string::npos &&
           screen.find("waiting for") == std::string::npos;
}

// Waits until every screen has stopped rolling a shot and the legends that show agree (a box
// may cover some, never all); false after `seconds`. A screen that rolls a shot is sent x,
// which skips to its end, as a player who has seen enough would. A player who owes a choice
// takes the first: its box covers every legend (an 8 potted on the break, an illegal break;
// the hall deals each rack at random, so any test may meet one).
bool same_table(const std::vector<const Tmux*>& terminals, double seconds = 20) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
        bool settled = true;
        std::optional<std::set<int>> shown;
        for (std::size_t i = 0; i < terminals.size() && settled; ++i) {
            const std::string s = terminals[i]->screen();
            if (shot_rolling(s) || shot_rolling(s, "Bob"))
                terminals[i]->keys("x");
            else if (owes_choice(s))
                terminals[i]->keys("1");
            const std::set<int> left = balls_on_table(s);
            if (!left.empty() && !shown)
                shown = left;
            // At the table (its legend and hint show), not in the lobby.
            settled = s.find("on table ") != std::string::npos &&
                      s.find("q leave") != std::string::npos && !shot_rolling(s) &&
                      !shot_rolling(s, "Bob") && (left.empty() || left == *shown) &&
                      s.find("The hall is away") == std::string::npos;
        }
        if (settled && shown)
            return true;
        std::this_thread::sleep_for(100ms);
    }
    return false;
}

// The terminal of `terminals` whose player is to act, and plays its turn: takes the first
// option of a choice (an 8 on the break, a push-out), puts the cue ball down where it is
// offered when it has ball in hand, then shoots. Returns it, or nullptr.
const Tmux* play_turn(const std::vector<const Tmux*>& terminals) {
    // A terminal that has just sat back down after a restart may take a few seconds under load.
    for (int tries = 0; tries < 400; ++tries) {
        for (const Tmux* t : terminals) {
            const std::string s = t->screen();
            if (owes_choice(s)) {
                t->keys("1");
                std::this_thread::sleep_for(200ms);
                continue;
            }
            if (s.find("place the cue ball") != std::string::npos &&
                s.find("waiting for") == std::string::npos) {
                t->keys("Enter");
                // Not "Space shoots": an 80-column panel wraps the hint between those words.
                if (!t->wait_for([](const std::string& now) {
                        return now.find("aim (mouse") != std::string::npos &&
                               now.find("place the cue ball") == std::string::npos;
                    }))
                    return nullptr;
                t->keys("Space");
                return t;
            }
            // The aim shows on both screens; the other player's says whom it waits for.
            if (s.find("[ shoot ]") != std::string::npos &&
                s.find("waiting for") == std::string::npos) {
                t->keys("Space");
                return t;
            }
        }
        std::this_thread::sleep_for(50ms);
    }
    return nullptr;
}

} // namespace

TEST_CASE("three hall terminals: a table created, a seat taken, a watcher, the raised cue's "
          "break on all three",
          "[hall][tui][e2e]") {
    TempDir dir("termpool-hall-tui");
    auto server = serve(dir.path());
    Tmux ann, bob, cid;
    open_terminal(ann, dir.path(), "Ann", 100, 32);
    open_terminal(bob, dir.path(), "Bob", 80, 24);
    open_terminal(cid, dir.path(), "Cid", 200, 60);

    create_table(ann);
    // The lobby is live: the new table shows on the others' screens by itself.
    REQUIRE(lobby_shows_seated(bob, "Ann"));
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
    // The cue raised a little: the aim the others watch carries it, and so does the shot.
    ann.keys("e");
    REQUIRE(ann.wait_for_text("elev 5\u00B0"));
    CHECK(bob.wait_for_text("elev 5\u00B0"));
    CHECK(cid.wait_for_text("elev 5\u00B0"));
    ann.keys("Space");
    // The shot reaches the other two screens and rolls out there too (x skips to its end).
    CHECK(bob.wait_for([](const std::string& s) { return shot_rolling(s); }));
    CHECK(cid.wait_for([](const std::string& s) { return shot_rolling(s); }));
    const bool settled = same_table({&ann, &bob, &cid});
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

TEST_CASE("leaving a table whose game has not started says no seat waits", "[hall][tui][e2e]") {
    TempDir dir("termpool-hall-tui");
    auto server = serve(dir.path());
    Tmux ann;
    open_terminal(ann, dir.path(), "Ann", 100, 32);
    create_table(ann);
    // No action yet: the hall frees the seat as she leaves, and her lobby must not promise it.
    ann.keys("q");
    REQUIRE(ann.wait_for_text("Leave the table?"));
    ann.keys("y");
    REQUIRE(ann.wait_for_text("Back in the lobby from table 1"));
    CHECK(ann.screen().find("waits for you") == std::string::npos);
}

TEST_CASE("a name the hall refuses brings the prompt back, to come in under another",
          "[hall][tui][e2e]") {
    TempDir dir("termpool-hall-tui");
    auto server = serve(dir.path());
    Tmux ann, other;
    open_terminal(ann, dir.path(), "Ann", 100, 32);
    other.start("env " + account_env(dir.path()) + " " + termpool_binary() + " hall --socket " +
                    dir.path() + "/hall.sock",
                100, 32);
    REQUIRE(other.wait_for_text("Your name:"));
    CHECK(other.screen().find("No tables yet") == std::string::npos); // not in the hall yet
    other.keys("-l ANN");
    other.keys("Enter");
    REQUIRE(other.wait_for_text("someone in the hall is called Ann already"));
    const std::string refused = other.screen();
    CHECK(refused.find("Your name:") != std::string::npos);
    CHECK(refused.find("trying again") == std::string::npos);
    other.keys("-l Bea");
    other.keys("Enter");
    CHECK(other.wait_for_text("Welcome, Bea."));
    CHECK(ann.wait_for_text("Bea"));
}

TEST_CASE("hall faults: a terminal killed mid-shot takes its seat back, a server killed "
          "mid-game is started again by the terminals and the game goes on",
          "[hall][tui][e2e]") {
    TempDir dir("termpool-hall-faults");
    auto server = serve(dir.path());
    const StartedServer restarted{dir.path() + "/hall.sock"};
    Tmux ann, bob;
    open_terminal(ann, dir.path(), "Ann", 100, 32);
    open_terminal(bob, dir.path(), "Bob", 80, 24);
    create_table(ann);
    REQUIRE(lobby_shows_seated(bob, "Ann"));
    bob.keys("Enter");
    {
        const bool seated = ann.wait_for_text("Ann breaks");
        INFO("Ann:\n" << ann.screen() << "\nBob:\n" << bob.screen());
        REQUIRE(seated);
    }
    ann.keys("Enter");
    REQUIRE(ann.wait_for_text("Space shoots"));

    // Ann's terminal goes while her break rolls: her seat waits, shown away.
    ann.keys("Space");
    REQUIRE(bob.wait_for([](const std::string& s) { return shot_rolling(s); }));
    ann.tmux("kill-server");
    CHECK(bob.wait_for_text("Ann (away)"));

    // She comes back under her name: the lobby offers her seat, and she plays on from where the
    // game stands.
    Tmux ann2;
    open_terminal(ann2, dir.path(), "Ann", 100, 32);
    REQUIRE(ann2.wait_for_text("waits for you"));
    ann2.keys("Enter");
    CHECK(bob.wait_for([](const std::string& s) { return s.find("(away)") == std::string::npos; }));
    {
        const bool settled = same_table({&ann2, &bob});
        INFO("Ann:\n" << ann2.screen() << "\nBob:\n" << bob.screen());
        REQUIRE(settled);
    }

    // The server is killed mid-game: both terminals say so, one starts a new server (which
    // restores the table from its save), both sit back down, and the game goes on.
    server->kill();
    CHECK(bob.wait_for_text("The hall is away"));
    {
        const bool settled = same_table({&ann2, &bob});
        INFO("Ann:\n" << ann2.screen() << "\nBob:\n" << bob.screen());
        REQUIRE(settled);
    }
    const Tmux* shooter = play_turn({&ann2, &bob});
    INFO("Ann:\n" << ann2.screen() << "\nBob:\n" << bob.screen());
    REQUIRE(shooter != nullptr);
    CHECK(same_table({&ann2, &bob}));
    // The new server is the terminals' own: it holds the table saved by the one killed.
    HallClient probe;
    REQUIRE(probe.connect(dir.path() + "/hall.sock").empty());
    CHECK(probe.server_pid() != server->pid());
}

TEST_CASE("a hall table's assist: chosen in the create form, shown in the lobby, played by "
          "both seats",
          "[hall][tui][e2e][assist]") {
    TempDir dir("termpool-hall-tui");
    auto server = serve(dir.path());
    Tmux ann, bob;
    open_terminal(ann, dir.path(), "Ann", 100, 32);
    open_terminal(bob, dir.path(), "Bob", 100, 32);

    // The form starts at standard; a goes to pro, then guided.
    ann.keys("c");
    REQUIRE(ann.wait_for_text("assist    standard"));
    ann.keys("a");
    REQUIRE(ann.wait_for_text("assist    pro"));
    ann.keys("a");
    REQUIRE(ann.wait_for_text("assist    guided"));
    ann.keys("Enter");
    REQUIRE(ann.wait_for_text("Waiting for an opponent"));
    REQUIRE(lobby_shows_seated(bob, "Ann"));
    CHECK(bob.wait_for_text("guided"));
    bob.keys("Enter");
    REQUIRE(ann.wait_for_text("Ann breaks"));

    // A watcher follows the table: its copy of the match, and each seat's aim as it is sent.
    HallClient cid = connected(dir.path(), "Cid");
    REQUIRE(cid.send(Watch{1}));
    expect<RecordEnd>(cid);
    REQUIRE(cid.match(1));
    CHECK(cid.match(1)->record().assist == Assist::guided);

    // Each seat's turn opens at the easiest pot, as guided opens it, on either terminal; Space
    // plays it. A seat that has shown its opening calls a safety next, so that the turn passes.
    const Tmux* seat[2] = {&ann, &bob};
    std::set<int> judged_seats;
    for (int action = 0; action < 20 && judged_seats.size() < 2; ++action) {
        CAPTURE(action);
        const Match& m = *cid.match(1);
        const PendingAction p = m.pending();
        if (p.kind == Pending::over || p.kind == Pending::next_rack)
            break;
        const std::size_t seq = m.record().actions.size();
        const Tmux& t = *seat[p.player - 1];
        if (p.kind == Pending::place) {
            REQUIRE(t.wait_for([](const std::string& s) {
                return s.find("place the cue ball") != std::string::npos ||
                       s.find("ball in hand") != std::string::npos;
            }));
            t.keys("Enter");
        } else if (p.kind == Pending::choose) {
            REQUIRE(t.wait_for_text("choose:"));
            t.keys("1");
        } else {
            // The terminal's turn has begun once its aim comes: the opening aim.
            const auto aim = cid.wait_for(
                [&](const ServerMessage& msg) {
                    const auto* shown = std::get_if<AimShown>(&msg);
                    return shown && shown->seat == p.player;
                },
                kWait * 4);
            REQUIRE(aim);
            const bool is_break = m.game().is_break();
            if (!is_break && !judged_seats.count(p.player)) {
                const Game& g = m.game();
                Vec2 cue;
                for (const Ball& b : g.balls())
                    if (b.id == 0)
                        cue = b.position;
                const auto open = tui::rank_openings(g.table(), g.balls(), g.params().ball_radius,
                                                     cue, g.legal_targets(), Assist::guided);
                REQUIRE_FALSE(open.empty());
                CAPTURE(p.player);
                CHECK(std::get<AimShown>(*aim).strike.angle_deg ==
                      Approx(open[0].aim_deg).margin(1e-9));
                judged_seats.insert(p.player);
            } else if (!is_break) {
                t.keys("0"); // a safety: the turn passes
            }
            t.keys("Space");
        }
        // The action comes back from the server; the shot rolls out at once on both screens.
        REQUIRE(cid.wait_for(
            [&](const ServerMessage&) {
                return cid.match(1) && cid.match(1)->record().actions.size() > seq;
            },
            kWait * 4));
        ann.keys("x");
        bob.keys("x");
    }
    CHECK(judged_seats.size() == 2);
}
