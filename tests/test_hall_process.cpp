// The hall as a host runs it: the real binary's `termpool hall serve` in a child process, with
// HallClients as the players. A server killed mid-game and started again on the same state
// folder, SIGTERM, the socket folder's check and bad arguments, a thousand connections against
// the server's memory, and `termpool hall bench`. Every child is reaped by ChildProcess
// whatever way a test ends, every wait is bounded (kWait), and each child's XDG folders and
// TMPDIR are inside the test's own folder.
#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <termpool/match.hpp>
#include <thread>
#include <unistd.h>
#include <vector>

#include "child_process.hpp"
#include "hall/client.hpp"
#include "hall/hall_state.hpp"
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

namespace {

// Under AddressSanitizer (make check) freed memory waits in a quarantine of hundreds of MB
// before it is used again, so the server's resident memory grows whatever it does; there
// LeakSanitizer checks the server at its exit instead (a leak makes its exit status 1).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// Nothing of the user's is read or written: the child's folders are all in `dir`.
std::vector<std::string> private_env(const std::string& dir) {
    return {"XDG_RUNTIME_DIR=" + dir + "/runtime", "XDG_STATE_HOME=" + dir + "/xdg-state",
            "XDG_CONFIG_HOME=" + dir + "/xdg-config", "TMPDIR=" + dir};
}

// `termpool` with `args`, its output appended to `log`.
std::unique_ptr<ChildProcess> run_termpool(const std::string& dir, std::vector<std::string> args,
                                           const std::string& log) {
    args.insert(args.begin(), termpool_binary());
    auto child = std::make_unique<ChildProcess>(args, log, private_env(dir));
    REQUIRE(child->pid() > 0);
    return child;
}

std::string socket_of(const std::string& dir) {
    return dir + "/hall.sock";
}

// `termpool hall serve` on `dir`/hall.sock with its tables in `dir`/state, once it answers.
// Every server of a test logs to `dir`/server.log.
std::unique_ptr<ChildProcess> start_hall(const std::string& dir) {
    const std::string log = dir + "/server.log";
    auto server = run_termpool(
        dir, {"hall", "serve", "--socket", socket_of(dir), "--state", dir + "/state"}, log);
    for (const auto end = Clock::now() + kWait;;) {
        HallClient probe;
        if (probe.connect(socket_of(dir)).empty())
            return server;
        if (!server->running() || Clock::now() >= end)
            FAIL("the hall did not start:\n" << file_text(log));
        std::this_thread::sleep_for(10ms);
    }
}

// Reads what the server sent before it went, up to the connection's end.
void drain(HallClient& client) {
    for (const auto end = Clock::now() + kWait; Clock::now() < end;)
        if (!client.receive(100ms) && client.closed())
            break;
    CHECK(client.closed());
    CHECK(client.bad_lines() == 0);
}

// The resident memory of process `pid`, in kB (VmRSS), -1 when it cannot be read.
long resident_kb(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);)
        if (line.starts_with("VmRSS:"))
            return std::stol(line.substr(6));
    return -1;
}

// The players and tables the lobby lists to a newcomer.
struct LobbyCount {
    int players = 0;
    int tables = 0;
};
LobbyCount lobby_count(const std::string& dir) {
    HallClient probe = connected(dir, "Probe");
    LobbyCount count;
    for (auto m = probe.receive(kWait); m && !is<LobbyEnd>(*m); m = probe.receive(kWait)) {
        count.players += is<PlayerView>(*m) ? 1 : 0;
        count.tables += is<TableView>(*m) ? 1 : 0;
    }
    return count;
}

} // namespace

TEST_CASE("hall process: SIGKILL mid-game, a new server on the same state, nothing acknowledged "
          "is lost",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    auto server = start_hall(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    HallClient* players[2] = {&ann, &bob};
    const std::string names[2] = {"Ann", "Bob"};
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);

    // How each round kills the server: at rest, every action told to both players; just after
    // the player to act sent a move, sooner or later (the server may not have read it yet, or
    // applied and saved it but told nobody, or told one player or both: the delays reach these
    // windows on this machine, and the checks hold whichever it hit); or as soon as the server
    // acknowledged the move to its player, whether or not the other has it yet.
    struct Kill {
        bool in_flight = false;
        std::chrono::microseconds delay{0};
        bool acknowledged = false;
    };
    const Kill kills[] = {
        {}, {true, 0us}, {true, 250us}, {true, 500us}, {true, 1000us}, {true, 0us, true}};
    play_one(ann, bob, table, {&ann, &bob});
    play_one(ann, bob, table, {&ann, &bob});
    for (const Kill& way : kills) {
        INFO("kill " << &way - kills);
        if (ann.match(table)->pending().kind == Pending::over)
            break; // a short game: the rest of it is played below
        play_one(ann, bob, table, {&ann, &bob});
        if (ann.match(table)->pending().kind == Pending::over)
            break; // the rest is checked below; an over table may close once its players go
        std::optional<RecordedAction> in_flight;
        if (way.in_flight) {
            HallClient& actor = ann.match(table)->to_act() == 1 ? ann : bob;
            in_flight = chosen_move(*actor.match(table));
            // A move that would end the game is played below, not killed in flight: the server
            // may close a finished table, and then there is no seat to offer back.
            Match after = *actor.match(table);
            if (after.apply(*in_flight) != MatchError::none ||
                after.pending().kind == Pending::over) {
                in_flight.reset();
                break;
            }
            const std::size_t seq = actor.match(table)->record().actions.size() + 1;
            REQUIRE(actor.send(Act{*in_flight}));
            if (way.acknowledged)
                await_action(actor, table, seq);
            else if (way.delay.count() > 0)
                std::this_thread::sleep_for(way.delay);
        }
        CHECK(server->kill() == 128 + SIGKILL);
        CHECK(server->gone());
        // What reached a player's socket before the server died is theirs: it was told.
        drain(ann);
        drain(bob);
        const Match seen[2] = {*ann.match(table), *bob.match(table)};

        // The dead server's socket file is still there; the new one replaces it.
        server = start_hall(dir.path());
        for (int s = 0; s < 2; ++s) {
            INFO("the servers' log:\n" << file_text(dir.path() + "/server.log"));
            const std::string token = players[s]->token();
            REQUIRE(players[s]->connect(socket_of(dir.path())) == "");
            REQUIRE(players[s]->hello(names[s], token, kWait) == "");
            const Yours yours = expect<Yours>(*players[s]);
            CHECK(yours.table == table);
            CHECK(yours.seat == s + 1);
        }
        for (int s = 0; s < 2; ++s) {
            const RecordEnd end = sit(*players[s], table, s + 1);
            // The server holds every action this player was told, and at most the one in
            // flight besides (saved before it could be told).
            Match expected = seen[s];
            const std::size_t told = expected.record().actions.size();
            INFO("kill " << &way - kills << ", seat " << s + 1 << ": told " << told << ", restored "
                         << end.seq);
            REQUIRE(end.seq >= told);
            REQUIRE(end.seq <= told + (in_flight ? 1 : 0));
            if (end.seq > told)
                REQUIRE(expected.apply(*in_flight) == MatchError::none);
            CHECK(end.hash == expected.state_hash());
            CHECK(players[s]->match(table)->state_hash() == end.hash);
        }
    }

    // And the game goes on to its end.
    for (int step = 0; step < 400 && ann.match(table)->pending().kind != Pending::over; ++step)
        play_one(ann, bob, table, {&ann, &bob});
    REQUIRE(ann.match(table)->pending().kind == Pending::over);
    const std::uint64_t hash = ann.match(table)->state_hash();
    CHECK(bob.match(table)->state_hash() == hash);
    CHECK(ann.mismatches() + bob.mismatches() == 0);
    CHECK(saved_hash(dir.path() + "/state", table) == hash);
    server->signal(SIGTERM);
    CHECK(server->wait_exit(kWait) == 0);
    CHECK(server->gone());
}

TEST_CASE("hall process: SIGTERM saves the tables, removes the socket and exits 0", "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    auto server = start_hall(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    HallClient eve = connected(dir.path(), "Eve");
    const int playing = create_table(ann);
    sit(ann, playing, 1);
    sit(bob, playing, 2);
    for (int i = 0; i < 2; ++i)
        play_one(ann, bob, playing, {&ann, &bob});
    const int waiting = create_table(eve, GameType::nine_ball);
    sit(eve, waiting, 1);

    // With everyone still connected, as systemd stops a service.
    server->signal(SIGTERM);
    const auto status = server->wait_exit(kWait);
    INFO(file_text(dir.path() + "/server.log"));
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK(server->gone());
    CHECK(::access(socket_of(dir.path()).c_str(), F_OK) != 0);
    CHECK(errno == ENOENT);
    drain(ann);

    std::vector<std::string> problems;
    const auto tables = load_tables(dir.path() + "/state", problems);
    CHECK(problems.empty());
    REQUIRE(tables.size() == 2);
    CHECK(tables[0].number == playing);
    CHECK(tables[0].record.actions.size() == 2);
    CHECK(saved_hash(dir.path() + "/state", playing) == ann.match(playing)->state_hash());
    CHECK(tables[0].seat_tokens[0] == seat_token_hash(ann.token()));
    CHECK(tables[0].seat_tokens[1] == seat_token_hash(bob.token()));
    CHECK(tables[1].number == waiting);
    CHECK(tables[1].seat_tokens[0] == seat_token_hash(eve.token()));
    CHECK(tables[1].seat_tokens[1] == "");
}

TEST_CASE("hall process: a log whose reader is gone does not stop the server", "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    // The server logs to a pipe (a FIFO, opened for reading before the server opens it).
    const std::string fifo = dir.path() + "/log.fifo";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    REQUIRE(reader >= 0);
    auto server = run_termpool(
        dir.path(),
        {"hall", "serve", "--socket", socket_of(dir.path()), "--state", dir.path() + "/state"},
        fifo);
    bool up = false;
    for (const auto end = Clock::now() + kWait; !up && server->running() && Clock::now() < end;) {
        HallClient probe;
        up = probe.connect(socket_of(dir.path())).empty();
        if (!up)
            std::this_thread::sleep_for(10ms);
    }
    REQUIRE(up);
    ::close(reader);
    // Creating a table is logged: the write meets a pipe nobody reads.
    HallClient ann = connected(dir.path(), "Ann");
    create_table(ann);
    ann.send(Ping{});
    CHECK(ann.wait_for(is<Pong>, kWait));
    CHECK(server->running());
}

TEST_CASE("hall process: serve refuses a socket folder others may write to, and bad arguments",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    const std::string log = dir.path() + "/out.log";

    for (const mode_t mode : {mode_t{0770}, mode_t{0777}}) {
        const std::string folder = dir.path() + "/open-" + std::to_string(mode);
        REQUIRE(::mkdir(folder.c_str(), 0700) == 0);
        REQUIRE(::chmod(folder.c_str(), mode) == 0); // the umask does not decide
        std::ofstream(log, std::ios::trunc).close();
        auto server = run_termpool(
            dir.path(), {"hall", "serve", "--socket", folder + "/hall.sock", "--state", dir.path()},
            log);
        const auto status = server->wait_exit(kWait);
        const std::string said = file_text(log);
        INFO("mode " << std::oct << mode << ": " << said);
        CHECK(status == 1);
        CHECK(said.find(folder + ": the socket folder is writable by") != std::string::npos);
        CHECK(::access((folder + "/hall.sock").c_str(), F_OK) != 0);
        CHECK(server->gone());
    }

    const std::vector<std::vector<std::string>> bad = {
        {"hall", "--bogus"},
        {"hall", "--name"},
        {"hall", "frobnicate"},
        {"hall", "serve", "--bogus", "1"},
        {"hall", "serve", "stray"},
        {"hall", "serve", "--socket"},
        {"hall", "serve", "--max-clients", "0"},
        {"hall", "serve", "--max-tables", "many"},
    };
    for (const auto& args : bad) {
        std::ofstream(log, std::ios::trunc).close();
        auto server = run_termpool(dir.path(), args, log);
        const auto status = server->wait_exit(kWait);
        const std::string said = file_text(log);
        std::string command;
        for (const std::string& a : args)
            command += " " + a;
        INFO("termpool" << command << ": " << said);
        CHECK(status == 2);
        CHECK(said.find("usage: termpool hall serve") != std::string::npos);
        CHECK(server->gone());
    }
    // A name it cannot take is said on one line, without the usage that would push the reason
    // off the screen (under an SSH forced command, the player's only view of it).
    std::ofstream(log, std::ios::trunc).close();
    auto named = run_termpool(dir.path(), {"hall", "--name", "bad\x01name"}, log);
    CHECK(named->wait_exit(kWait) == 2);
    CHECK(file_text(log) == "termpool hall: --name: a name may not hold U+0001 (a control "
                            "character) (termpool hall --help: usage)\n");
    CHECK(named->gone());
}

TEST_CASE("hall process: a thousand connects and disconnects, the server's memory stays put",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    auto server = start_hall(dir.path());
    // Some only connect, some say hello, some send garbage, some make a table and go (it
    // closes with them): everything each one cost must be given back.
    const auto come_and_go = [&](int count) {
        for (int i = 0; i < count; ++i) {
            HallClient client;
            REQUIRE(client.connect(socket_of(dir.path())) == "");
            if (i % 2 == 0)
                REQUIRE(client.hello("Guest " + std::to_string(i % 7), "", kWait) == "");
            if (i % 4 == 0)
                create_table(client);
            if (i % 3 == 0)
                client.send_raw("nonsense\n");
        }
    };
    // The allocator's first arenas and the buffers' first growth are not a leak.
    come_and_go(100);
    const LobbyCount warm = lobby_count(dir.path());
    const long before_kb = resident_kb(server->pid());

    const auto start = Clock::now();
    come_and_go(1000);
    const auto elapsed = Clock::now() - start;
    // Every connection before this one is gone, with its table.
    const LobbyCount after = lobby_count(dir.path());
    const long after_kb = resident_kb(server->pid());

    CHECK(elapsed < 20s);
    CHECK(warm.players == 1);
    CHECK(after.players == 1);
    CHECK(after.tables == 0);
    REQUIRE(before_kb > 0);
    REQUIRE(after_kb > 0);
    INFO("VmRSS before " << before_kb << " kB, after " << after_kb << " kB");
    if (!kSanitized)
        CHECK(after_kb - before_kb <= 2048);
    server->signal(SIGTERM);
    CHECK(server->wait_exit(kWait) == 0);
    CHECK(server->gone());
}

TEST_CASE("hall process: termpool hall bench plays its tables and checks them", "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    const std::string log = dir.path() + "/bench.log";
    auto bench =
        run_termpool(dir.path(), {"hall", "bench", "--tables", "2", "--seconds", "1"}, log);
    // It plays for its one second, then has kWait to check the tables and stop its server.
    const auto status = bench->wait_exit(1s + kWait);
    const std::string said = file_text(log);
    INFO(said);
    CHECK(status == 0);
    CHECK(said.find("2 of 2 agree") != std::string::npos);
    // The server's own figures, read from its log (each line after its time).
    CHECK(said.find("\nserver handling    ") != std::string::npos);
    CHECK(said.find("\nserver saving      ") != std::string::npos);
    CHECK(bench->gone());
    // Its private folder (in TMPDIR, here the test's) is removed when all went well.
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
        CHECK(entry.path().filename() == "bench.log");
}

TEST_CASE("hall process: --idle-exit: a hall nobody uses saves and exits 0", "[hall][e2e]") {
    TempDir dir("termpool-hall-idle");
    const std::string log = dir.path() + "/server.log";
    auto server = run_termpool(dir.path(),
                               {"hall", "serve", "--socket", socket_of(dir.path()), "--state",
                                dir.path() + "/state", "--idle-exit", "1"},
                               log);
    HallClient ann;
    for (const auto end = Clock::now() + kWait; !ann.connect(socket_of(dir.path())).empty();) {
        REQUIRE(server->running());
        REQUIRE(Clock::now() < end);
        std::this_thread::sleep_for(10ms);
    }
    REQUIRE(ann.hello("Ann", "", kWait) == "");
    // A connection keeps it: past the idle second the hall still answers (a hall that had
    // gone would have closed the connection; a slow machine only sends the ping later).
    std::this_thread::sleep_for(1100ms);
    REQUIRE(ann.send(Ping{}));
    REQUIRE(ann.wait_for(is<Pong>, kWait));
    // Gone, the hall follows a second later: saved, its socket removed, status 0. Its idle
    // second starts when it sees Ann go, after `left` (the same monotonic clock in both
    // processes): not a millisecond sooner.
    const auto left = Clock::now();
    ann.disconnect();
    const auto status = server->wait_exit(kWait);
    const auto ended = Clock::now();
    INFO(file_text(log));
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK(ended - left >= 1s);
    CHECK_FALSE(std::filesystem::exists(socket_of(dir.path())));
    CHECK(file_text(log).find("no connection for 1 s and every table saved: exiting (0 tables in "
                              "the state folder)") != std::string::npos);
}

TEST_CASE("hall process: --idle-exit takes whole seconds from 0, --archive-after hours from 1",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-idle");
    int run = 0;
    const std::pair<std::string, std::string> refused[] = {
        {"--idle-exit", "-1"},     {"--idle-exit", "x"},       {"--idle-exit", "1.5"},
        {"--idle-exit", ""},       {"--archive-after", "0"},   {"--archive-after", "1.5"},
        {"--archive-after", "-2"}, {"--archive-after", "1e9"}, {"--archive-after", "100001"}};
    for (const auto& [option, bad] : refused) {
        INFO(option << " " << bad);
        const std::string log = dir.path() + "/out-" + std::to_string(++run) + ".log";
        auto server = run_termpool(
            dir.path(), {"hall", "serve", "--socket", socket_of(dir.path()), option, bad}, log);
        const auto status = server->wait_exit(kWait);
        REQUIRE(status);
        CHECK(*status == 2);
        CHECK(file_text(log).find(option + " takes a whole number of") != std::string::npos);
    }
}

TEST_CASE("hall process: a second server on another socket is refused the same state folder",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    auto server = start_hall(dir.path());
    const std::string log = dir.path() + "/second.log";
    auto second = run_termpool(
        dir.path(),
        {"hall", "serve", "--socket", dir.path() + "/other.sock", "--state", dir.path() + "/state"},
        log);
    CHECK(second->wait_exit(kWait) == 1);
    CHECK(file_text(log).find("another hall already keeps its tables in") != std::string::npos);
    CHECK(server->running());
    HallClient probe;
    CHECK(probe.connect(socket_of(dir.path())).empty());
}

TEST_CASE("hall process: a state folder others may write to is refused, the hall does not start",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    const std::string state = dir.path() + "/state"; // start_hall's
    REQUIRE(::mkdir(state.c_str(), 0700) == 0);
    REQUIRE(::chmod(state.c_str(), 0777) == 0);
    const std::string log = dir.path() + "/refused.log";
    auto refused = run_termpool(
        dir.path(), {"hall", "serve", "--socket", socket_of(dir.path()), "--state", state}, log);
    CHECK(refused->wait_exit(kWait) == 1);
    CHECK(file_text(log).find(state + ": the state folder is writable by others (mode 0777") !=
          std::string::npos);
    // Made private, it serves.
    REQUIRE(::chmod(state.c_str(), 0700) == 0);
    auto server = start_hall(dir.path());
    CHECK(server->running());
}

TEST_CASE("hall process: a state folder inside a folder others may write to is refused; one "
          "reached through a link is used where it really is",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-proc");
    // Without the sticky bit, anyone could rename the state folder away and put theirs there.
    const std::string open = dir.path() + "/open";
    REQUIRE(::mkdir(open.c_str(), 0700) == 0);
    REQUIRE(::chmod(open.c_str(), 0777) == 0);
    const std::string log = dir.path() + "/refused.log";
    auto refused = run_termpool(
        dir.path(),
        {"hall", "serve", "--socket", socket_of(dir.path()), "--state", open + "/state"}, log);
    CHECK(refused->wait_exit(kWait) == 1);
    CHECK(file_text(log).find(open + ": a folder above the state folder is writable by others "
                                     "(mode 0777)") != std::string::npos);
    // With the sticky bit (as /tmp has) only the state folder's owner may rename it.
    REQUIRE(::chmod(open.c_str(), 01777) == 0);
    // A link to the state folder: the lock is taken in the folder it points to, and the link
    // pointed elsewhere after the start takes nothing with it: the next save goes where the
    // folder really is.
    REQUIRE(::symlink((open + "/state").c_str(), (dir.path() + "/state").c_str()) == 0);
    auto server = start_hall(dir.path());
    CHECK(server->running());
    CHECK(std::filesystem::exists(open + "/state/hall.lock"));
    const std::string elsewhere = dir.path() + "/elsewhere";
    REQUIRE(::mkdir(elsewhere.c_str(), 0700) == 0);
    REQUIRE(::unlink((dir.path() + "/state").c_str()) == 0);
    REQUIRE(::symlink(elsewhere.c_str(), (dir.path() + "/state").c_str()) == 0);
    HallClient ann = connected(dir.path(), "Ann");
    const int table = create_table(ann);
    CHECK(std::filesystem::exists(table_path(open + "/state", table)));
    CHECK_FALSE(std::filesystem::exists(table_path(elsewhere, table)));
}

TEST_CASE("hall process: hall who prints a running hall for its host, exits 1 with none",
          "[hall][e2e]") {
    TempDir dir("termpool-hall-who");
    {
        const std::string log = dir.path() + "/who-none.log";
        auto who =
            run_termpool(dir.path(), {"hall", "who", "--socket", socket_of(dir.path())}, log);
        const auto status = who->wait_exit(kWait);
        REQUIRE(status);
        CHECK(*status == 1);
        CHECK(file_text(log).find("termpool hall who: no hall answers on " +
                                  socket_of(dir.path())) != std::string::npos);
    }
    auto server = start_hall(dir.path());
    HallClient ann;
    REQUIRE(ann.connect(socket_of(dir.path())) == "");
    REQUIRE(ann.hello("Ann", "", kWait) == "");
    ann.send(Create{GameType::nine_ball, TableSize::seven_foot, 3});
    REQUIRE(ann.wait_for(is<Created>, kWait));
    const std::string log = dir.path() + "/who.log";
    auto who = run_termpool(dir.path(), {"hall", "who", "--socket", socket_of(dir.path())}, log);
    const auto status = who->wait_exit(kWait);
    const std::string text = file_text(log);
    INFO(text);
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK(text.find("hall: 1 of 256 people, 0 connections waiting for hello, 1 of 100 tables\n") ==
          0);
    CHECK(text.find("table 1: 9-ball, race to 3, waiting, 0 actions; seat 1 empty, seat 2 empty, 0 "
                    "watching\n") != std::string::npos);
    CHECK(text.find(": Ann in the lobby, connected ") != std::string::npos);
    CHECK(text.find(ann.token()) == std::string::npos);
}
