// The hall's server end to end, through real Unix sockets in a temporary folder, run
// in-process on a thread: a whole game and a spectator who joins late, a player who comes back,
// a restart, and what only the connection layer does (lines too long, slow readers, floods,
// file descriptors running out). The hall's rules are tested by direct calls on its core with a
// fake clock (test_hall_core.cpp). Every wait is bounded (kWait); the server's thread is
// stopped and joined by RunningServer whatever way a test ends.
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <mutex>
#include <ostream>
#include <poll.h>
#include <streambuf>
#include <string>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <termpool/match.hpp>
#include <thread>
#include <unistd.h>
#include <variant>
#include <vector>

#include "file_helpers.hpp"
#include "hall/client.hpp"
#include "hall/hall_state.hpp"
#include "hall/server.hpp"
#include "hall_helpers.hpp"
#include "temp_dir.hpp"
#include "wait_until.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;

namespace {

// A log the server's thread writes while the test reads it.
class LockedLog : public std::streambuf {
public:
    std::string text() {
        const std::lock_guard lock(mutex_);
        return text_;
    }

protected:
    int overflow(int c) override {
        const std::lock_guard lock(mutex_);
        if (c != EOF)
            text_ += static_cast<char>(c);
        return c == EOF ? 0 : c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        const std::lock_guard lock(mutex_);
        text_.append(s, static_cast<std::size_t>(n));
        return n;
    }

private:
    std::mutex mutex_;
    std::string text_;
};

// A server on `dir`/hall.sock, serving on a thread until destroyed.
class RunningServer {
public:
    RunningServer(const std::string& dir, ServerOptions options = {}) {
        options.socket_path = dir + "/hall.sock";
        // The same racks on every run: a rack dealt at random could end before the test is
        // done with it (an 8 potted early), one run in some hundreds.
        if (!options.deal_seed)
            options.deal_seed = 7;
        options.state_dir = dir;
        server_ = std::make_unique<Server>(options);
        const std::string problem = server_->open();
        REQUIRE(problem == "");
        thread_ = std::thread([this] {
            status_ = server_->run();
            finished_ = true;
        });
    }
    ~RunningServer() { stop(); }
    RunningServer(const RunningServer&) = delete;
    RunningServer& operator=(const RunningServer&) = delete;

    void stop() {
        if (thread_.joinable()) {
            server_->stop();
            thread_.join();
        }
        server_.reset(); // closes every connection, removes the socket file
    }
    Server& server() { return *server_; }
    /// True once `run` returned (by itself: idle_exit).
    bool finished() const { return finished_; }

private:
    std::unique_ptr<Server> server_;
    std::thread thread_;
    int status_ = 0;
    std::atomic<bool> finished_{false};
};

Error expect_error(HallClient& client) {
    return expect<Error>(client);
}

bool still_serves(const std::string& dir) {
    HallClient probe = connected(dir, "Probe");
    probe.send(Ping{});
    return probe.wait_for(is<Pong>, kWait).has_value();
}

} // namespace

TEST_CASE("hall server: two clients play a whole game, a late spectator follows", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob Smith");
    HallClient eve = connected(dir.path(), "Eve");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);

    bool watching = false;
    for (int step = 0; step < 400 && ann.match(table)->pending().kind != Pending::over; ++step) {
        std::vector<HallClient*> all = {&ann, &bob};
        if (watching)
            all.push_back(&eve);
        play_one(ann, bob, table, all);
        // After the fourth action, or at the end of a rack that ended sooner (its deal is the
        // server's: an 8 on the break can end it in three).
        if (!watching && (step == 3 || ann.match(table)->pending().kind == Pending::over)) {
            REQUIRE(eve.send(Watch{table}));
            expect<RecordEnd>(eve);
            watching = true;
        }
    }
    REQUIRE(ann.match(table)->pending().kind == Pending::over);
    REQUIRE(watching);
    const std::uint64_t hash = ann.match(table)->state_hash();
    CHECK(bob.match(table)->state_hash() == hash);
    REQUIRE(eve.match(table));
    CHECK(eve.match(table)->state_hash() == hash);
    CHECK(ann.mismatches() + bob.mismatches() + eve.mismatches() == 0);
    CHECK(ann.match(table)->record().names[1] == "Bob Smith");
    CHECK(saved_hash(dir.path(), table) == hash);
}

TEST_CASE("hall server: bad input gets an error, the server goes on", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());

    SECTION("an oversized line ends the connection") {
        HallClient client = connected(dir.path(), "Ann");
        client.send_raw("chat " + std::string(5000, 'x'));
        CHECK(expect_error(client).code == ErrorCode::too_long);
        CHECK_FALSE(client.wait_for(is<Pong>, kWait));
        CHECK(client.closed());
    }
    SECTION("a wrong protocol version ends the connection") {
        HallClient client;
        REQUIRE(client.connect(dir.path() + "/hall.sock") == "");
        client.send_raw("hello 4 - Ann\n");
        CHECK(expect_error(client).code == ErrorCode::version);
        CHECK_FALSE(client.wait_for(is<Pong>, kWait));
        CHECK(client.closed());
    }
    CHECK(still_serves(dir.path()));
}

TEST_CASE("hall server: a player who drops keeps the seat and takes it back", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    for (int i = 0; i < 2; ++i)
        play_one(ann, bob, table, {&ann, &bob});
    const std::string token = ann.token();
    ann.disconnect();

    const auto away = bob.wait_for(
        [](const ServerMessage& m) {
            const auto* s = std::get_if<SeatChange>(&m);
            return s && s->seat == 1 && s->view.kind == SeatKind::away;
        },
        kWait);
    REQUIRE(away);

    // Someone else cannot take it; its owner can.
    HallClient mallory = connected(dir.path(), "Mallory");
    mallory.send(Sit{table, 1});
    CHECK(expect_error(mallory).code == ErrorCode::seat_taken);

    HallClient again;
    REQUIRE(again.connect(dir.path() + "/hall.sock") == "");
    REQUIRE(again.hello("Ann", token, kWait) == "");
    const Yours yours = expect<Yours>(again);
    CHECK(yours.table == table);
    CHECK(yours.seat == 1);
    sit(again, table, 1);
    CHECK(again.match(table)->state_hash() == bob.match(table)->state_hash());
    for (int i = 0; i < 2; ++i)
        play_one(again, bob, table, {&again, &bob});
    CHECK(again.match(table)->state_hash() == bob.match(table)->state_hash());
}

TEST_CASE("hall server: a client that stops reading is disconnected", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.output_limit = 64 * 1024;
    options.request_burst = 1e6; // the output bound must cut it, not the request budget
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    const int table = create_table(ann);
    ann.send(Watch{table});
    // Each sync asks for the whole record; never read, they pile up past the bound.
    std::string syncs;
    for (int i = 0; i < 4000; ++i)
        syncs += "sync\n";
    ann.send_raw(syncs);
    // Read everything: the connection must end (the server closed it), within the bound.
    const auto end = std::chrono::steady_clock::now() + kWait;
    while (!ann.closed() && std::chrono::steady_clock::now() < end)
        ann.receive(100ms);
    CHECK(ann.closed());
    CHECK(still_serves(dir.path()));
}

TEST_CASE("hall server: a thousand connects and disconnects", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.max_clients = 8; // every closed connection must be freed for the next
    RunningServer running(dir.path(), options);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 1000; ++i) {
        HallClient client;
        REQUIRE(client.connect(dir.path() + "/hall.sock") == "");
        if (i % 2 == 0)
            REQUIRE(client.hello("Guest", "", kWait) == "");
    }
    CHECK(std::chrono::steady_clock::now() - start < 30s);
    HallClient last = connected(dir.path(), "Last");
    // The lobby lists only who is connected.
    int players = 0;
    for (auto m = last.receive(kWait); m && !is<LobbyEnd>(*m); m = last.receive(kWait))
        players += is<PlayerView>(*m) ? 1 : 0;
    CHECK(players == 1);
}

TEST_CASE("hall server: a restart restores the tables and the seats", "[hall]") {
    test::TempDir dir("termpool-hall");
    std::string ann_token;
    std::string bob_token;
    std::uint64_t hash = 0;
    int table = 0;
    {
        RunningServer running(dir.path());
        HallClient ann = connected(dir.path(), "Ann");
        HallClient bob = connected(dir.path(), "Bob");
        table = create_table(ann);
        sit(ann, table, 1);
        sit(bob, table, 2);
        for (int i = 0; i < 3; ++i)
            play_one(ann, bob, table, {&ann, &bob});
        hash = ann.match(table)->state_hash();
        ann_token = ann.token();
        bob_token = bob.token();
        running.stop(); // as SIGTERM does: the clients are still connected
    }
    RunningServer running(dir.path());
    CHECK(running.server().table_count() == 1);
    HallClient ann = connected(dir.path(), "Ann", ann_token);
    HallClient bob = connected(dir.path(), "Bob", bob_token);
    sit(ann, table, 1);
    sit(bob, table, 2);
    CHECK(ann.match(table)->state_hash() == hash);
    play_one(ann, bob, table, {&ann, &bob});
    CHECK(bob.match(table)->state_hash() == ann.match(table)->state_hash());
    CHECK(ann.match(table)->record().actions.size() == 4);
}

TEST_CASE("hall server: out of file descriptors, the server waits rather than spin", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string path = dir.path() + "/hall.sock";
    REQUIRE(path.size() < sizeof address.sun_path);
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    const int waiting = ::socket(AF_UNIX, SOCK_STREAM, 0);
    REQUIRE(waiting >= 0);
    // The lowest free descriptor is the next one made: a limit at it leaves accept none.
    const int next = ::dup(waiting);
    REQUIRE(next >= 0);
    ::close(next);
    rlimit saved{};
    REQUIRE(::getrlimit(RLIMIT_NOFILE, &saved) == 0);
    rlimit tight = saved;
    tight.rlim_cur = static_cast<rlim_t>(next);
    Server& server = running.server();
    REQUIRE(server.accept_pauses() == 0);
    const auto start = std::chrono::steady_clock::now();
    REQUIRE(::setrlimit(RLIMIT_NOFILE, &tight) == 0);
    const int connected_ok =
        ::connect(waiting, reinterpret_cast<const sockaddr*>(&address), sizeof address);
    // Each failed accept leaves the listener out of poll for 100 ms. Watched from its first
    // failure until three more (nothing here may open a descriptor, nor fail the test, before
    // the limit is back): a loop that spins on the listener fails accept in every round, so
    // reaches them at once; one that spins elsewhere makes rounds without them. Both counts
    // are the server's own: a slow or loaded machine makes fewer rounds, never more.
    const auto pauses_reach = [&](std::size_t count) {
        return wait_until([&] { return server.accept_pauses() >= count; }, kWaitSeconds, 1ms);
    };
    const bool paused = pauses_reach(1);
    const std::size_t first_pauses = server.accept_pauses();
    const std::size_t first_rounds = server.rounds();
    const bool paused_again = paused && pauses_reach(first_pauses + 3);
    const std::size_t last_rounds = server.rounds();
    const std::size_t last_pauses = server.accept_pauses(); // read after the rounds
    const auto elapsed = std::chrono::steady_clock::now() - start;
    REQUIRE(::setrlimit(RLIMIT_NOFILE, &saved) == 0);
    ::close(waiting);
    REQUIRE(connected_ok == 0);
    REQUIRE(paused);
    REQUIRE(paused_again);
    INFO(last_pauses << " pauses, " << last_rounds - first_rounds << " rounds from the first, in "
                     << elapsed / 1ms << " ms");
    // Every pause lasted its 100 ms before accept was tried again...
    CHECK(elapsed >= static_cast<long>(last_pauses - 1) * 100ms);
    // ...and the loop slept through it: two rounds a pause (its end, then accept's failure),
    // a few more for the lobby and anything else due.
    CHECK(last_rounds - first_rounds <= 2 * (last_pauses - first_pauses) + 10);
    // Descriptors back, it serves again.
    CHECK(still_serves(dir.path()));
    ann.send(Ping{});
    CHECK(ann.wait_for(is<Pong>, kWait));
}

// A log that can hold the server's thread in the middle of a round: armed, the next write
// waits (at most kWait) until released. What arrives meanwhile is all there at the next poll.
class GateLog : public std::streambuf {
public:
    void arm() {
        const std::lock_guard lock(mutex_);
        armed_ = true;
        held_ = false;
    }
    bool wait_held() {
        std::unique_lock lock(mutex_);
        return changed_.wait_for(lock, kWait, [&] { return held_; });
    }
    void release() {
        const std::lock_guard lock(mutex_);
        armed_ = false;
        changed_.notify_all();
    }

protected:
    int overflow(int c) override {
        hold();
        return c == EOF ? 0 : c;
    }
    std::streamsize xsputn(const char*, std::streamsize n) override {
        hold();
        return n;
    }

private:
    void hold() {
        std::unique_lock lock(mutex_);
        if (!armed_)
            return;
        held_ = true;
        changed_.notify_all();
        changed_.wait_for(lock, kWait, [&] { return !armed_; });
    }
    std::mutex mutex_;
    std::condition_variable changed_;
    bool armed_ = false;
    bool held_ = false;
};

TEST_CASE("hall server: a flood of lines from one client does not starve another", "[hall]") {
    test::TempDir dir("termpool-hall");
    GateLog gate;
    std::ostream log(&gate);
    ServerOptions options;
    HallLog hall_log(log);
    options.log = &hall_log;
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    for (HallClient* client : {&ann, &bob}) {
        REQUIRE(client->send(Watch{table}));
        expect<RecordEnd>(*client);
    }
    // The server is held by the log of Ann's sync while her flood (within one read of the
    // server's) and then Bob's ping arrive: both are read in the same round, Ann's first.
    // The flood ends with a chat, which Bob sees at the table: were the whole flood handled at
    // once, the chat would come before the answer to Bob's ping.
    gate.arm();
    REQUIRE(ann.send(Sync{}));
    REQUIRE(gate.wait_held());
    std::string flood;
    for (int i = 0; i < 5000; ++i)
        flood += "ping\n";
    flood += "chat done\n";
    REQUIRE(ann.send_raw(flood));
    REQUIRE(bob.send(Ping{}));
    gate.release();
    const auto first =
        bob.wait_for([](const ServerMessage& m) { return is<Pong>(m) || is<ChatShown>(m); }, kWait);
    REQUIRE(first);
    CHECK(is<Pong>(*first));
    // Ann is served in full all the same.
    REQUIRE(ann.wait_for(is<ChatShown>, kWait));
    CHECK(still_serves(dir.path()));
}

TEST_CASE("hall server: actions at several tables at once are each saved and taken", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    constexpr int tables = 4;
    std::vector<HallClient> players;
    std::vector<int> numbers;
    for (int t = 0; t < tables; ++t) {
        players.push_back(connected(dir.path(), "A" + std::to_string(t)));
        players.push_back(connected(dir.path(), "B" + std::to_string(t)));
        numbers.push_back(create_table(players[2 * t]));
        sit(players[2 * t], numbers.back(), 1);
        sit(players[2 * t + 1], numbers.back(), 2);
    }
    for (int round = 0; round < 3; ++round) {
        // Every table's move goes out before any answer is read: the server gets them together.
        std::vector<std::size_t> seqs;
        for (int t = 0; t < tables; ++t) {
            const Match& local = *players[2 * t].match(numbers[t]);
            seqs.push_back(local.record().actions.size() + 1);
            HallClient& actor = players[2 * t + (local.to_act() == 1 ? 0 : 1)];
            REQUIRE(actor.send(Act{chosen_move(*actor.match(numbers[t]))}));
        }
        for (int t = 0; t < tables; ++t)
            for (int p = 0; p < 2; ++p)
                await_action(players[2 * t + p], numbers[t], seqs[t]);
    }
    for (int t = 0; t < tables; ++t) {
        CHECK(players[2 * t].mismatches() + players[2 * t + 1].mismatches() == 0);
        CHECK(saved_hash(dir.path(), numbers[t]) ==
              players[2 * t + 1].match(numbers[t])->state_hash());
    }
}

TEST_CASE("hall server: a file at the socket's path that is not its socket is left alone",
          "[hall]") {
    test::TempDir dir("termpool-hall");
    const std::string path = dir.path() + "/hall.sock";
    std::ofstream(path) << "not a socket\n";
    ServerOptions options;
    options.socket_path = path;
    Server server(options);
    CHECK(server.open().find("not a socket of this user's") != std::string::npos);
    std::ifstream in(path);
    std::string text;
    std::getline(in, text);
    CHECK(text == "not a socket");
}

namespace {

std::string hex(std::uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

} // namespace

TEST_CASE("hall server: a sync with the client's copy is logged against the server's", "[hall]") {
    test::TempDir dir("termpool-hall");
    LockedLog sink;
    std::ostream log(&sink);
    ServerOptions options;
    HallLog hall_log(log);
    options.log = &hall_log;
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    play_one(ann, bob, table, {&ann, &bob});
    const std::uint64_t after_one = ann.match(table)->state_hash();
    play_one(ann, bob, table, {&ann, &bob});
    const std::uint64_t after_two = ann.match(table)->state_hash();
    const std::string at = "table " + std::to_string(table) + ": ";

    // The server logs before it sends the record: once the record is here, so is the line.
    const auto sync = [&](const Sync& message) {
        REQUIRE(ann.send(message));
        expect<RecordEnd>(ann);
        return sink.text();
    };
    CHECK_THAT(sync(Sync{2, 0x0123456789abcdefull}),
               Catch::Contains(at +
                               "Ann's copy after action 2 hashed 0123456789abcdef, the "
                               "server's " +
                               hex(after_two) + "; record sent again"));
    // An earlier action's hash is kept too.
    CHECK_THAT(sync(Sync{1, 0xfedcba9876543210ull}),
               Catch::Contains(at +
                               "Ann's copy after action 1 hashed fedcba9876543210, the "
                               "server's " +
                               hex(after_one) + "; record sent again"));
    // A copy that agreed there but could not take the next action.
    CHECK_THAT(sync(Sync{1, after_one}),
               Catch::Contains(at + "Ann's copy after action 1 hashed " + hex(after_one) +
                               ", as the server's did (it could not take action 2)"));
    CHECK_THAT(sync(Sync{9, 0}), Catch::Contains("but the server holds 2 actions"));
    // A plain sync says only that it came.
    CHECK_THAT(sync(Sync{}), Catch::Contains("resynchronises table " + std::to_string(table)));
}

TEST_CASE("hall client: a copy that disagrees asks sync with what it came to", "[hall]") {
    // The test is the server: a record, then an action whose hash is wrong.
    test::TempDir dir("termpool-hall");
    HallClient client;
    const UniqueFd peer = fake_server_for(client, dir.path() + "/fake.sock");
    const auto say = [&](const ServerMessage& m) {
        const std::string line = format_server(m);
        REQUIRE(::send(peer.get(), line.data(), line.size(), MSG_NOSIGNAL) ==
                static_cast<ssize_t>(line.size()));
    };

    GameRecord header;
    header.setup.table = TableSize::seven_foot;
    auto started = Match::start(header, 7);
    REQUIRE(std::holds_alternative<Match>(started));
    Match ours = std::get<Match>(started);
    say(Joined{3, 0});
    const std::string text = format_record(ours.record());
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = text.find('\n', start);
        say(RecordLine{3, text.substr(start, end - start)});
        start = end + 1;
    }
    say(RecordEnd{3, 0, ours.state_hash()});
    const RecordedAction move = chosen_move(ours);
    REQUIRE(ours.apply(move) == MatchError::none);
    say(ActionDone{3, 1, ours.state_hash() ^ 1, move});
    REQUIRE(client.wait_for(is<ActionDone>, kWait));
    CHECK(client.mismatches() == 1);

    // What the client sent back: its copy after action 1, hashed as ours is.
    std::string got;
    pollfd p{peer.get(), POLLIN, 0};
    for (int i = 0; i < 100 && got.find('\n') == std::string::npos; ++i) {
        REQUIRE(::poll(&p, 1, static_cast<int>(kWait.count())) == 1);
        char buffer[256];
        const ssize_t n = ::recv(peer.get(), buffer, sizeof buffer, 0);
        REQUIRE(n > 0);
        got.append(buffer, static_cast<std::size_t>(n));
    }
    CHECK(got == format_client(Sync{1, ours.state_hash()}));
}

TEST_CASE("hall server: idle_exit: a game on disk does not keep the hall; the next one restores "
          "it, the file's date untouched",
          "[hall]") {
    test::TempDir dir("termpool-hall");
    int table = 0;
    {
        // A game under way whose players both went: the table stays, its seats away.
        RunningServer first(dir.path());
        HallClient ann = connected(dir.path(), "Ann");
        HallClient bob = connected(dir.path(), "Bob");
        table = create_table(ann);
        sit(ann, table, 1);
        sit(bob, table, 2);
        play_one(ann, bob, table, {&ann, &bob});
    }
    // The away seats count from the file's date: an hour ago. A hall that rewrote the file on
    // its way out would give them the hour back.
    const std::string file = table_path(dir.path(), table);
    const std::time_t changed = std::time(nullptr) - 3600;
    const timespec times[2] = {{changed, 0}, {changed, 0}};
    REQUIRE(::utimensat(AT_FDCWD, file.c_str(), times, 0) == 0);
    LockedLog sink;
    std::ostream log(&sink);
    ServerOptions options;
    options.socket_path = dir.path() + "/hall.sock";
    options.state_dir = dir.path();
    options.idle_exit = std::chrono::seconds(1);
    HallLog hall_log(log);
    options.log = &hall_log;
    {
        Server server(options);
        REQUIRE(server.open() == "");
        REQUIRE(server.table_count() == 1);
        std::atomic<bool> done{false};
        int status = -1;
        std::thread loop([&] {
            status = server.run();
            done = true;
        });
        struct Join { // stopped whatever way the test ends
            Server& server;
            std::thread& loop;
            ~Join() {
                server.stop();
                loop.join();
            }
        } join{server, loop};
        // Nobody connects: the hall goes by itself (the bound is only a deadline), the table
        // still held, waiting on disk.
        wait_until([&] { return done.load(); }, 10, 5ms);
        REQUIRE(done);
        CHECK(status == 0);
        CHECK(server.table_count() == 1);
    }
    INFO(sink.text());
    CHECK(sink.text().find("(1 table in the state folder)") != std::string::npos);
    struct stat st {};
    REQUIRE(::stat(file.c_str(), &st) == 0);
    CHECK(st.st_mtime == changed);
    // The next hall (as the next `termpool hall` starts it) has the game, as it was.
    RunningServer second(dir.path());
    CHECK(second.server().table_count() == 1);
}

TEST_CASE("hall client: a server line longer than 4 KiB ends the connection, never a spin",
          "[hall]") {
    test::TempDir dir("termpool-hall");
    HallClient client;
    const UniqueFd peer = fake_server_for(client, dir.path() + "/fake.sock");
    const std::string endless(2 * max_line_bytes, 'x'); // no newline, and the peer stays open
    REQUIRE(::send(peer.get(), endless.data(), endless.size(), MSG_NOSIGNAL) ==
            static_cast<ssize_t>(endless.size()));
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 10 && !client.closed(); ++i)
        CHECK_FALSE(client.receive(std::chrono::milliseconds(200)));
    CHECK(client.closed());
    CHECK(client.bad_lines() == 1);
    CHECK(client.fd() == -1); // nothing left for a loop to wait on
    CHECK(std::chrono::steady_clock::now() - start < kWait);
}
