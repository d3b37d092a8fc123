// The hall's server through real Unix sockets in a temporary folder, run in-process on a
// thread: whole games played by scripted clients and by the computer, a spectator who joins
// late, and the faults the issue lists. Every wait is bounded (kWait); the server's thread is
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

// Waits (at most kWait) until the server's log holds `line`; whether it came.
bool log_shows(LockedLog& log, const std::string& line) {
    return wait_until([&] { return log.text().find(line) != std::string::npos; }, kWaitSeconds,
                      5ms);
}

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

TEST_CASE("hall server: the computer plays a seat on the worker pool", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient eve = connected(dir.path(), "Eve");
    const int table = create_table(eve, GameType::nine_ball);
    sit(eve, table, 1);
    REQUIRE(eve.send(SeatComputer{2, Level::easy}));
    REQUIRE(eve.wait_for(
        [](const ServerMessage& m) {
            const auto* s = std::get_if<SeatChange>(&m);
            return s && s->seat == 2 && s->view.kind == SeatKind::computer;
        },
        kWait));
    for (int step = 0; step < 400 && eve.match(table)->pending().kind != Pending::over; ++step) {
        const Match& match = *eve.match(table);
        if (match.to_act() == 1)
            REQUIRE(eve.send(Act{chosen_move(match)}));
        await_action(eve, table, match.record().actions.size() + 1);
    }
    REQUIRE(eve.match(table)->pending().kind == Pending::over);
    CHECK(eve.mismatches() == 0);
    CHECK(saved_hash(dir.path(), table) == eve.match(table)->state_hash());
}

TEST_CASE("hall server: a spectator cannot seat or unseat the computer", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient eve = connected(dir.path(), "Eve");
    const int table = create_table(ann);
    sit(ann, table, 1);
    REQUIRE(eve.send(Watch{table}));
    expect<RecordEnd>(eve);
    REQUIRE(eve.send(SeatComputer{2, Level::easy}));
    CHECK(expect_error(eve).code == ErrorCode::not_seated);
    // Ann may; then Eve may not take it away either.
    REQUIRE(ann.send(SeatComputer{2, Level::easy}));
    REQUIRE(eve.wait_for(
        [](const ServerMessage& m) {
            const auto* s = std::get_if<SeatChange>(&m);
            return s && s->seat == 2 && s->view.kind == SeatKind::computer;
        },
        kWait));
    REQUIRE(eve.send(SeatComputer{2, std::nullopt}));
    CHECK(expect_error(eve).code == ErrorCode::not_seated);
    REQUIRE(eve.send(Sync{}));
    expect<RecordEnd>(eve);
    const auto seat = eve.wait_for(
        [](const ServerMessage& m) {
            const auto* s = std::get_if<SeatChange>(&m);
            return s && s->seat == 2;
        },
        kWait);
    REQUIRE(seat);
    CHECK(std::get<SeatChange>(*seat).view.kind == SeatKind::computer);
}

TEST_CASE("hall server: bad input gets an error, the server goes on", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());

    SECTION("garbage bytes") {
        HallClient client = connected(dir.path(), "Ann");
        client.send_raw("\xff\xfe\x01 garbage\n");
        CHECK(expect_error(client).code == ErrorCode::syntax);
        client.send(Ping{});
        CHECK(client.wait_for(is<Pong>, kWait));
    }
    SECTION("before hello") {
        HallClient client;
        REQUIRE(client.connect(dir.path() + "/hall.sock") == "");
        client.send(Ping{});
        CHECK(expect_error(client).code == ErrorCode::hello_first);
    }
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
    SECTION("repeated errors end the connection") {
        HallClient client = connected(dir.path(), "Ann");
        for (int i = 0; i < 10; ++i)
            client.send_raw("nonsense\n");
        client.send(Ping{});
        CHECK_FALSE(client.wait_for(is<Pong>, kWait));
        CHECK(client.closed());
    }
    CHECK(still_serves(dir.path()));
}

TEST_CASE("hall server: an out-of-turn action is refused and changes nothing", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.chat_interval = std::chrono::hours(1); // the second chat is too soon however slow
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    REQUIRE(ann.match(table)->to_act() == 1);
    const std::uint64_t before = ann.match(table)->state_hash();

    REQUIRE(bob.send(Act{chosen_move(*bob.match(table))}));
    const Error error = expect_error(bob);
    CHECK(error.code == ErrorCode::refused);
    CHECK(error.text == match_error_text(MatchError::wrong_player));
    // A spectator may not play either, nor may anyone chat twice within chat_interval.
    bob.send(Chat{"hi"});
    expect<ChatShown>(ann);
    bob.send(Chat{"again"});
    CHECK(expect_error(bob).code == ErrorCode::rate);

    // The game is as it was: the next action is still action 1, and Ann's.
    play_one(ann, bob, table, {&ann, &bob});
    CHECK(ann.match(table)->record().actions.size() == 1);
    CHECK(ann.match(table)->state_hash() != before);
    CHECK(bob.match(table)->state_hash() == ann.match(table)->state_hash());
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

TEST_CASE("hall server: a table whose creator goes without sitting closes", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    {
        HallClient ann = connected(dir.path(), "Ann");
        create_table(ann);
        CHECK(running.server().table_count() == 1);
    }
    // Nobody sat, nobody can come back to it: were it kept, such tables would fill the hall.
    HallClient bob = connected(dir.path(), "Bob");
    int tables = 0;
    for (auto m = bob.receive(kWait); m && !is<LobbyEnd>(*m); m = bob.receive(kWait))
        tables += is<TableView>(*m) ? 1 : 0;
    CHECK(tables == 0);
    CHECK(running.server().table_count() == 0);
    std::vector<std::string> problems;
    CHECK(load_tables(dir.path(), problems).empty());
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

// The seat tokens table `number` is saved with (none for a table not saved).
std::array<std::string, 2> saved_tokens(const std::string& dir, int number) {
    std::vector<std::string> problems;
    for (const SavedTable& stored : load_tables(dir, problems))
        if (stored.number == number)
            return {stored.seat_tokens[0], stored.seat_tokens[1]};
    return {};
}

TEST_CASE("hall server: sitting again in one's own seat changes nothing", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(ann, table, 1); // the record comes again; the seat stays Ann's
    CHECK(ann.match(table)->record().names[0] == "Ann");
    CHECK(saved_tokens(dir.path(), table)[0] == seat_token_hash(ann.token()));
    bob.send(Sit{table, 1});
    CHECK(expect_error(bob).code == ErrorCode::seat_taken);

    // Ann again, from a second connection: she may not hold both seats (the table may be gone:
    // her first connection gave way, and nobody else was at it).
    HallClient again = connected(dir.path(), "Ann", ann.token());
    again.send(Sit{table, 2});
    REQUIRE(again.wait_for([](const ServerMessage& m) { return is<Error>(m) || is<RecordEnd>(m); },
                           kWait));
    const auto tokens = saved_tokens(dir.path(), table);
    CHECK_FALSE((tokens[0] == tokens[1] && !tokens[0].empty()));
}

// Waits (at most kWait) until the server holds `count` tables.
bool tables_become(RunningServer& running, std::size_t count) {
    return wait_until([&] { return running.server().table_count() == count; }, kWaitSeconds, 5ms);
}

TEST_CASE("hall server: a table nobody plays at goes", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());

    SECTION("its creator disconnects before anyone came") {
        HallClient ann = connected(dir.path(), "Ann");
        create_table(ann);
        CHECK(running.server().table_count() == 1);
        ann.disconnect();
        CHECK(tables_become(running, 0));
    }
    SECTION("the only player drops before the first action") {
        HallClient ann = connected(dir.path(), "Ann");
        sit(ann, create_table(ann), 1);
        ann.disconnect();
        CHECK(tables_become(running, 0));
    }
    SECTION("one token may have a few tables waiting") {
        HallClient ann = connected(dir.path(), "Ann");
        for (int i = 0; i < 3; ++i)
            create_table(ann);
        ann.send(Create{GameType::eight_ball, TableSize::nine_foot, 1});
        CHECK(expect_error(ann).code == ErrorCode::full);
        CHECK(running.server().table_count() == 3);
    }
    CHECK(still_serves(dir.path()));
}

TEST_CASE("hall server: an away seat is freed after away_limit", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.away_limit = 300ms;
    int table = 0;
    {
        RunningServer running(dir.path(), options);
        HallClient ann = connected(dir.path(), "Ann");
        HallClient bob = connected(dir.path(), "Bob");
        table = create_table(ann);
        sit(ann, table, 1);
        sit(bob, table, 2);
        play_one(ann, bob, table, {&ann, &bob});
        ann.disconnect();
        const auto seat_is = [&](SeatKind kind) {
            return bob.wait_for(
                [&](const ServerMessage& m) {
                    const auto* s = std::get_if<SeatChange>(&m);
                    return s && s->seat == 1 && s->view.kind == kind;
                },
                kWait);
        };
        REQUIRE(seat_is(SeatKind::away));
        REQUIRE(seat_is(SeatKind::empty));
        CHECK(saved_tokens(dir.path(), table)[0].empty());
        // Bob goes away too; the server stops before his seat is due.
        running.stop();
    }
    CHECK(saved_tokens(dir.path(), table)[1] != "");
    // Restarted after his time was up (the file's time says when he left): the table is gone.
    const timespec an_hour_ago[2] = {{std::time(nullptr) - 3600, 0},
                                     {std::time(nullptr) - 3600, 0}};
    REQUIRE(::utimensat(AT_FDCWD, table_path(dir.path(), table).c_str(), an_hour_ago, 0) == 0);
    RunningServer running(dir.path(), options);
    CHECK(running.server().table_count() == 0);
}

TEST_CASE("hall server: the lobby's changes go out coalesced, requests have a budget", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient lobby = connected(dir.path(), "Lou");
    REQUIRE(lobby.wait_for(is<LobbyEnd>, kWait));
    // Every snapshot made from here on may still be unread.
    const auto since = std::chrono::steady_clock::now();
    HallClient ann = connected(dir.path(), "Ann");
    HallClient eve = connected(dir.path(), "Eve");
    const int table = create_table(ann);
    sit(ann, table, 1); // the table stays while Eve comes and goes

    SECTION("a watcher toggling does not flood the lobby") {
        for (int i = 0; i < 9; ++i) { // 18 requests, and the sit below: within the budget
            REQUIRE(eve.send(Watch{table}));
            expect<RecordEnd>(eve);
            REQUIRE(eve.send(Leave{}));
            expect<Left>(eve);
        }
        // The last change, unlike any before it: Eve sits. The lobby is read up to the snapshot
        // that shows it (so the changes were not lost), counting every snapshot on the way: at
        // most one every lobby_interval (250 ms) since `since`, and one made just before it.
        sit(eve, table, 2);
        int snapshots = 0;
        bool shows_eve = false; // the snapshot being read has Eve in seat 2
        const auto last = lobby.wait_for(
            [&](const ServerMessage& m) {
                if (is<LobbyBegin>(m)) {
                    ++snapshots;
                    shows_eve = false;
                }
                if (const auto* t = std::get_if<TableView>(&m))
                    shows_eve = shows_eve || (t->number == table && t->seats[1].name == "Eve");
                return is<LobbyEnd>(m) && shows_eve;
            },
            kWait);
        const auto elapsed = std::chrono::steady_clock::now() - since;
        REQUIRE(last);
        INFO(snapshots << " snapshots in " << elapsed / 1ms << " ms");
        CHECK(snapshots <= 2 + static_cast<int>(elapsed / 250ms));
    }
    SECTION("too many syncs are refused") {
        REQUIRE(eve.send(Watch{table}));
        expect<RecordEnd>(eve);
        std::string syncs;
        for (int i = 0; i < 25; ++i)
            syncs += "sync\n";
        eve.send_raw(syncs);
        CHECK(expect_error(eve).code == ErrorCode::rate);
    }
}

TEST_CASE("hall server: the computer's answer for a table that changed is dropped", "[hall]") {
    test::TempDir dir("termpool-hall");
    LockedLog sink;
    std::ostream log(&sink);
    ServerOptions options;
    HallLog hall_log(log);
    options.log = &hall_log;
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    HallClient eve = connected(dir.path(), "Eve");
    const int table = create_table(ann);
    REQUIRE(eve.send(Watch{table}));
    expect<RecordEnd>(eve);
    REQUIRE(eve.match(table)->to_act() == 1);
    // Read in one round, before the computer's answer can be: Ann sits, seats the computer
    // to break (it starts thinking) and leaves.
    ann.send_raw("sit " + std::to_string(table) + " 2\ncomputer 1 easy\nleave\n");
    REQUIRE(ann.wait_for(is<Left>, kWait));
    // The answer comes, and the server says it dropped it...
    REQUIRE(log_shows(sink, "table " + std::to_string(table) +
                                ": the computer's answer is for the table as it was: dropped"));
    // ...so seat 2 is empty and the computer did not break: nothing came before the record.
    REQUIRE(eve.send(Sync{}));
    bool acted = false;
    REQUIRE(eve.wait_for(
        [&](const ServerMessage& m) {
            acted = acted || is<ActionDone>(m);
            return is<RecordEnd>(m);
        },
        kWait));
    CHECK_FALSE(acted);
    CHECK(eve.match(table)->record().actions.empty());
    CHECK(eve.match(table)->record().names[1] == "Player 2");
}

TEST_CASE("hall server: connections that never say hello do not hold the hall", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.max_clients = 2;
    options.hello_timeout = 300ms;
    RunningServer running(dir.path(), options);
    std::vector<HallClient> silent(3);
    for (HallClient& client : silent)
        REQUIRE(client.connect(dir.path() + "/hall.sock") == "");
    // Only people count toward max_clients.
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    HallClient carl;
    REQUIRE(carl.connect(dir.path() + "/hall.sock") == "");
    const std::string refused = carl.hello("Carl", "", kWait);
    CHECK(refused.rfind("full", 0) == 0); // the reply arrives before the close
    // The silent ones are closed once their time is up.
    for (HallClient& client : silent) {
        const auto end = std::chrono::steady_clock::now() + kWait;
        while (!client.closed() && std::chrono::steady_clock::now() < end)
            client.receive(50ms);
        CHECK(client.closed());
    }
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

TEST_CASE("hall server: a seat's actions have a budget", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.max_errors = 1000; // the refusals must not end the connection first
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    // Bob is not to act: each action is refused by the match, until the budget runs out.
    const std::string line = format_client(Act{chosen_move(*ann.match(table))});
    std::string flood;
    for (int i = 0; i < 100; ++i)
        flood += line;
    REQUIRE(bob.send_raw(flood));
    int refused = 0;
    int rate = 0;
    for (int i = 0; i < 100; ++i) {
        const auto m = bob.wait_for(is<Error>, kWait);
        REQUIRE(m);
        const Error& error = std::get<Error>(*m);
        (error.code == ErrorCode::rate ? rate : refused) += 1;
    }
    CHECK(refused >= 40);
    CHECK(rate > 0);
    // Ann's seat has its own budget.
    play_one(ann, bob, table, {&ann, &bob});
}

TEST_CASE("hall server: an action that cannot be saved is not taken", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    // A folder where the save's temporary file goes makes the atomic write fail (a chmod
    // would not stop the tests' root).
    const std::string in_the_way = table_path(dir.path(), table) + ".tmp";
    REQUIRE(::mkdir(in_the_way.c_str(), 0700) == 0);
    const RecordedAction move = chosen_move(*ann.match(table));
    REQUIRE(ann.send(Act{move}));
    CHECK(expect_error(ann).code == ErrorCode::internal);
    REQUIRE(::rmdir(in_the_way.c_str()) == 0);
    // Nothing changed: the same move is action 1 still, for everyone and in the file.
    REQUIRE(ann.send(Act{move}));
    await_action(bob, table, 1);
    await_action(ann, table, 1);
    CHECK(bob.match(table)->record().actions.size() == 1);
    CHECK(ann.mismatches() + bob.mismatches() == 0);
    CHECK(saved_hash(dir.path(), table) == ann.match(table)->state_hash());
}

TEST_CASE("hall server: a request sent with an action finds the action taken", "[hall]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    // One write: the server reads both lines in one round, the action waiting for its save
    // when the sync comes; the record sent back must hold it.
    const RecordedAction move = chosen_move(*ann.match(table));
    REQUIRE(ann.send_raw(format_client(Act{move}) + format_client(Sync{})));
    await_action(ann, table, 1);
    const RecordEnd end = expect<RecordEnd>(ann);
    CHECK(end.seq == 1);
    REQUIRE(ann.match(table));
    CHECK(end.hash == ann.match(table)->state_hash());
    await_action(bob, table, 1);
    CHECK(ann.mismatches() + bob.mismatches() == 0);
    CHECK(saved_hash(dir.path(), table) == end.hash);
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

TEST_CASE("hall server: a table keeps at most max_actions actions", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.max_actions = 3;
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    const int table = create_table(ann);
    sit(ann, table, 1);
    sit(bob, table, 2);
    for (int k = 0; k < 3 && ann.match(table)->pending().kind != Pending::over; ++k)
        play_one(ann, bob, table, {&ann, &bob});
    REQUIRE(ann.match(table)->record().actions.size() == 3);
    HallClient& actor = ann.match(table)->to_act() == 1 ? ann : bob;
    REQUIRE(actor.send(Act{chosen_move(*actor.match(table))}));
    const Error error = expect_error(actor);
    CHECK(error.code == ErrorCode::refused);
    CHECK(error.text.find("the most a table keeps") != std::string::npos);
    CHECK(saved_hash(dir.path(), table) == ann.match(table)->state_hash());
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

namespace {
// The test as the server: a socket at `path` that `client` connects to; the server's end.
UniqueFd fake_server_for(HallClient& client, const std::string& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(path.size() < sizeof address.sun_path);
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    const UniqueFd listener(::socket(AF_UNIX, SOCK_STREAM, 0));
    REQUIRE(::bind(listener.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) ==
            0);
    REQUIRE(::listen(listener.get(), 1) == 0);
    REQUIRE(client.connect(path) == "");
    UniqueFd peer(::accept(listener.get(), nullptr, nullptr));
    REQUIRE(peer);
    return peer;
}

} // namespace

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

TEST_CASE("hall server: idle_exit: a table keeps the hall, and once it goes the hall goes",
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
    // The restored seats count from the table file's last change, which the server reads to
    // the second: the file is dated this whole second, and away_limit ends 400 ms from now, so
    // the table goes then (and not before: it is there once restored), well within the hall's
    // first idle second.
    const auto now = std::chrono::system_clock::now();
    const auto changed = std::chrono::floor<std::chrono::seconds>(now);
    const std::time_t changed_t = std::chrono::system_clock::to_time_t(changed);
    const timespec times[2] = {{changed_t, 0}, {changed_t, 0}};
    REQUIRE(::utimensat(AT_FDCWD, table_path(dir.path(), table).c_str(), times, 0) == 0);
    LockedLog sink;
    std::ostream log(&sink);
    ServerOptions options;
    options.socket_path = dir.path() + "/hall.sock";
    options.state_dir = dir.path();
    options.idle_exit = std::chrono::seconds(1);
    options.away_limit = std::chrono::ceil<std::chrono::milliseconds>(now - changed) + 400ms;
    HallLog hall_log(log);
    options.log = &hall_log;
    const auto freed = changed + options.away_limit; // on the system clock
    Server server(options);
    REQUIRE(server.open() == "");
    REQUIRE(server.table_count() == 1);
    std::atomic<bool> done{false};
    int status = -1;
    std::thread loop([&] {
        status = server.run();
        done = true;
    });
    // Stopped whatever way the test ends.
    struct Join {
        Server& server;
        std::thread& loop;
        ~Join() {
            server.stop();
            loop.join();
        }
    } join{server, loop};
    // Nobody connects. The hall goes by itself (the bound is only a deadline)...
    wait_until([&] { return done.load(); }, 10, 5ms);
    const auto ended = std::chrono::system_clock::now();
    REQUIRE(done);
    CHECK(status == 0);
    CHECK(server.table_count() == 0);
    // ...its idle second counted from when the table went, not from its start: a hall that
    // did not count the table would have gone 1 s after it started, 400 ms sooner. (The
    // server turns the file's date into its own clock's time; 50 ms allow for that.)
    INFO("ended " << (ended - freed) / 1ms << " ms after the seats were due");
    CHECK(ended - freed >= 1s - 50ms);
    // In that order: the seats freed, the table closed, and only then the hall.
    const std::string said = sink.text();
    INFO(said);
    const std::string name = "table " + std::to_string(table);
    const auto seat_freed = said.find(name + ": seat 1 was away too long: freed");
    const auto closed = said.find(name + " closed");
    const auto exiting = said.find("no connection and no table for 1 s: exiting");
    REQUIRE(seat_freed != std::string::npos);
    REQUIRE(closed != std::string::npos);
    REQUIRE(exiting != std::string::npos);
    CHECK(seat_freed < closed);
    CHECK(closed < exiting);
}

TEST_CASE("hall server: idle_exit: a connection keeps the hall past the idle time", "[hall]") {
    test::TempDir dir("termpool-hall");
    ServerOptions options;
    options.idle_exit = std::chrono::seconds(1);
    RunningServer running(dir.path(), options);
    HallClient ann = connected(dir.path(), "Ann");
    // The loop ran before Ann was welcomed: were her connection not to count, the hall would
    // have gone by 1 s after this.
    const auto welcomed = std::chrono::steady_clock::now();
    // Ann says nothing past that moment (with a margin)...
    std::this_thread::sleep_until(welcomed + options.idle_exit + 100ms);
    // ...then two round trips: the second is read in a round that began after the first was
    // answered, with the hall's idle check, past the moment.
    for (int i = 0; i < 2; ++i) {
        REQUIRE(ann.send(Ping{}));
        REQUIRE(ann.wait_for(is<Pong>, kWait));
    }
    CHECK_FALSE(running.finished());
    CHECK_FALSE(ann.closed());
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

TEST_CASE("hall server: a snooker table is a snooker table, and a concession ends the frame",
          "[hall][snooker]") {
    test::TempDir dir("termpool-hall");
    RunningServer running(dir.path());
    HallClient ann = connected(dir.path(), "Ann");
    HallClient bob = connected(dir.path(), "Bob");
    // Asked for on a 7 ft table (create_table's size): played on the snooker table.
    const int table = create_table(ann, GameType::snooker);
    sit(ann, table, 1);
    sit(bob, table, 2);
    REQUIRE(ann.match(table));
    CHECK(ann.match(table)->setup().game == GameType::snooker);
    CHECK(ann.match(table)->setup().table == TableSize::snooker);
    CHECK(ann.match(table)->table().size == TableSize::snooker);
    // The cue ball placed in the D, the break played, then the player to act concedes.
    for (int step = 0; step < 2; ++step)
        play_one(ann, bob, table, {&ann, &bob});
    const int conceding = ann.match(table)->to_act();
    REQUIRE((conceding == 1 || conceding == 2));
    RecordedAction concede;
    concede.kind = RecordedAction::Kind::choose;
    concede.choice = Choice::concede;
    const std::size_t seq = ann.match(table)->record().actions.size() + 1;
    REQUIRE((conceding == 1 ? ann : bob).send(Act{concede}));
    await_action(ann, table, seq);
    await_action(bob, table, seq);
    CHECK(ann.match(table)->game().winner() == 3 - conceding);
    CHECK(ann.match(table)->game().win_reason() == WinReason::conceded);
    CHECK(bob.match(table)->state_hash() == ann.match(table)->state_hash());
    CHECK(saved_hash(dir.path(), table) == ann.match(table)->state_hash());
}
