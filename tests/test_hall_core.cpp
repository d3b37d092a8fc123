// The hall's core by direct calls with a fake clock: the rules of tables, seats, budgets and
// time, without a socket or a sleep (tests/fake_hall.hpp). What only the connection layer does
// (bytes, slow readers, file descriptors) is in test_hall_server.cpp, over real sockets.
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <ctime>
#include <fcntl.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <termpool/match.hpp>
#include <vector>

#include "fake_hall.hpp"
#include "file_helpers.hpp"
#include "hall/hall_state.hpp"
#include "hall_helpers.hpp"
#include "temp_dir.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;

namespace {

// Options whose tables are saved in `dir`.
ServerOptions saved_in(const std::string& dir, ServerOptions options = {}) {
    options.state_dir = dir;
    return options;
}

// The seat tokens table `number` is saved with (none for a table not saved).
std::array<std::string, 2> saved_tokens(const std::string& dir, int number) {
    std::vector<std::string> problems;
    for (const SavedTable& stored : load_tables(dir, problems))
        if (stored.number == number)
            return {stored.seat_tokens[0], stored.seat_tokens[1]};
    return {};
}

// True when `id` was told seat `seat` of a table is now `kind`.
bool told_seat(FakeHall& hall, int id, int seat, SeatKind kind) {
    for (const ServerMessage& m : hall.take(id))
        if (const auto* s = std::get_if<SeatChange>(&m);
            s && s->seat == seat && s->view.kind == kind)
            return true;
    return false;
}

} // namespace

TEST_CASE("hall core: the computer plays a seat on the worker pool", "[hall][core]") {
    test::TempDir dir("termpool-core");
    FakeHall hall(saved_in(dir.path()));
    const int eve = hall.hello("Eve");
    const int table = hall.create(eve, GameType::nine_ball);
    hall.sit(eve, table, 1);
    hall.send(eve, SeatComputer{2, Level::easy});
    CHECK(told_seat(hall, eve, 2, SeatKind::computer));
    for (int step = 0; step < 400 && hall.core().match(table)->pending().kind != Pending::over;
         ++step) {
        if (hall.core().match(table)->to_act() == 1)
            hall.play_one(eve, 0, table);
        else
            REQUIRE(hall.computer());
    }
    REQUIRE(hall.core().match(table)->pending().kind == Pending::over);
    CHECK(saved_hash(dir.path(), table) == hall.core().match(table)->state_hash());
}

TEST_CASE("hall core: a spectator cannot seat or unseat the computer", "[hall][core]") {
    FakeHall hall;
    const int ann = hall.hello("Ann");
    const int eve = hall.hello("Eve");
    const int table = hall.create(ann);
    hall.sit(ann, table, 1);
    hall.send(eve, Watch{table});
    REQUIRE(hall.find<RecordEnd>(eve));
    hall.send(eve, SeatComputer{2, Level::easy});
    CHECK(hall.error(eve) == ErrorCode::not_seated);
    hall.send(ann, SeatComputer{2, Level::easy});
    CHECK(told_seat(hall, eve, 2, SeatKind::computer));
    hall.send(eve, SeatComputer{2, std::nullopt});
    CHECK(hall.error(eve) == ErrorCode::not_seated);
    CHECK(hall.core().match(table)->name(2).find("Computer") == 0);
}

TEST_CASE("hall core: bad input gets an error", "[hall][core]") {
    FakeHall hall;
    SECTION("garbage bytes") {
        const int ann = hall.hello("Ann");
        hall.send_raw(ann, "\xff\xfe\x01 garbage");
        CHECK(hall.error(ann) == ErrorCode::syntax);
        hall.send(ann, Ping{});
        CHECK(hall.find<Pong>(ann));
    }
    SECTION("before hello") {
        const int id = hall.connect();
        hall.send(id, Ping{});
        CHECK(hall.error(id) == ErrorCode::hello_first);
        CHECK_FALSE(hall.closed(id));
    }
    SECTION("a wrong protocol version ends the connection") {
        const int id = hall.connect();
        hall.send_raw(id, "hello 4 - Ann");
        CHECK(hall.error(id) == ErrorCode::version);
        CHECK(hall.closed(id));
    }
    SECTION("repeated errors end the connection, one forgiven every 30 s") {
        const int ann = hall.hello("Ann");
        for (int i = 0; i < 9; ++i)
            hall.send_raw(ann, "nonsense");
        hall.now += 30s; // one forgiven
        hall.send_raw(ann, "nonsense");
        CHECK_FALSE(hall.closed(ann));
        hall.send_raw(ann, "nonsense");
        CHECK(hall.closed(ann));
    }
}

TEST_CASE("hall core: an out-of-turn action is refused, chat has its interval", "[hall][core]") {
    FakeHall hall;
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    const std::uint64_t before = hall.core().match(table)->state_hash();
    hall.send(bob, Act{chosen_move(*hall.core().match(table))});
    hall.tick();
    const auto error = hall.find<Error>(bob);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::refused);
    CHECK(error->text == match_error_text(MatchError::wrong_player));
    CHECK(hall.core().match(table)->state_hash() == before);

    hall.send(bob, Chat{"hi"});
    CHECK(hall.find<ChatShown>(ann));
    hall.now += 999ms;
    hall.send(bob, Chat{"again"});
    CHECK(hall.error(bob) == ErrorCode::rate);
    hall.now += 1ms;
    hall.send(bob, Chat{"now"});
    CHECK(hall.find<ChatShown>(ann));
}

TEST_CASE("hall core: a player who drops keeps the seat and takes it back", "[hall][core]") {
    FakeHall hall;
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    for (int i = 0; i < 2; ++i)
        hall.play_one(ann, bob, table);
    const std::string token = hall.token(ann);
    hall.disconnect(ann);
    CHECK(told_seat(hall, bob, 1, SeatKind::away));

    const int mallory = hall.hello("Mallory");
    hall.send(mallory, Sit{table, 1});
    CHECK(hall.error(mallory) == ErrorCode::seat_taken);

    const int again = hall.hello("Ann", token);
    const auto yours = hall.find<Yours>(again);
    REQUIRE(yours);
    CHECK(yours->table == table);
    CHECK(yours->seat == 1);
    hall.sit(again, table, 1);
    hall.play_one(again, bob, table);
}

TEST_CASE("hall core: a table nobody plays at goes", "[hall][core]") {
    test::TempDir dir("termpool-core");
    FakeHall hall(saved_in(dir.path()));
    const int ann = hall.hello("Ann");
    SECTION("its creator disconnects before anyone came") {
        hall.create(ann);
        CHECK(hall.core().table_count() == 1);
        hall.disconnect(ann);
        CHECK(hall.core().table_count() == 0);
        std::vector<std::string> problems;
        CHECK(load_tables(dir.path(), problems).empty());
    }
    SECTION("the only player drops before the first action") {
        hall.sit(ann, hall.create(ann), 1);
        hall.disconnect(ann);
        CHECK(hall.core().table_count() == 0);
    }
    SECTION("one token may have a few tables waiting") {
        for (int i = 0; i < 3; ++i)
            hall.create(ann);
        hall.send(ann, Create{GameType::eight_ball, TableSize::nine_foot, 1});
        CHECK(hall.error(ann) == ErrorCode::full);
        CHECK(hall.core().table_count() == 3);
    }
}

TEST_CASE("hall core: a restart restores the tables and the seats", "[hall][core]") {
    test::TempDir dir("termpool-core");
    std::string ann_token;
    std::uint64_t hash = 0;
    int table = 0;
    {
        FakeHall hall(saved_in(dir.path()));
        const int ann = hall.hello("Ann");
        const int bob = hall.hello("Bob");
        table = hall.create(ann);
        hall.sit(ann, table, 1);
        hall.sit(bob, table, 2);
        for (int i = 0; i < 3; ++i)
            hall.play_one(ann, bob, table);
        hash = hall.core().match(table)->state_hash();
        ann_token = hall.token(ann);
        REQUIRE(hall.core().save_all() == 0);
    }
    FakeHall hall(saved_in(dir.path()));
    hall.restore();
    CHECK(hall.core().table_count() == 1);
    REQUIRE(hall.core().match(table));
    CHECK(hall.core().match(table)->state_hash() == hash);
    const int ann = hall.hello("Ann", ann_token);
    CHECK(hall.find<Yours>(ann));
    hall.sit(ann, table, 1);
    const int mallory = hall.hello("Mallory");
    hall.send(mallory, Sit{table, 2});
    CHECK(hall.error(mallory) == ErrorCode::seat_taken);
}

TEST_CASE("hall core: sitting again in one's own seat changes nothing", "[hall][core]") {
    test::TempDir dir("termpool-core");
    FakeHall hall(saved_in(dir.path()));
    const int ann = hall.hello("Ann");
    const int bob = hall.hello("Bob");
    const int table = hall.create(ann);
    hall.sit(ann, table, 1);
    hall.sit(ann, table, 1);
    CHECK(hall.core().match(table)->record().names[0] == "Ann");
    CHECK(saved_tokens(dir.path(), table)[0] == seat_token_hash(hall.token(ann)));
    hall.send(bob, Sit{table, 1});
    CHECK(hall.error(bob) == ErrorCode::seat_taken);
    // Ann again, from a second connection: she may not hold both seats.
    const int again = hall.hello("Ann", hall.token(ann));
    hall.send(again, Sit{table, 2});
    const auto tokens = saved_tokens(dir.path(), table);
    CHECK_FALSE((tokens[0] == tokens[1] && !tokens[0].empty()));
}

TEST_CASE("hall core: an away seat is freed after away_limit, to the millisecond", "[hall][core]") {
    test::TempDir dir("termpool-core");
    ServerOptions options = saved_in(dir.path());
    options.away_limit = 7 * 24h;
    int table = 0;
    {
        FakeHall hall(options);
        const int ann = hall.hello("Ann");
        const int bob = hall.hello("Bob");
        table = hall.create(ann);
        hall.sit(ann, table, 1);
        hall.sit(bob, table, 2);
        hall.play_one(ann, bob, table);
        hall.disconnect(ann);
        CHECK(told_seat(hall, bob, 1, SeatKind::away));
        hall.advance(1s);
        hall.advance(options.away_limit - 1s - 1ms);
        CHECK_FALSE(told_seat(hall, bob, 1, SeatKind::empty));
        hall.advance(1ms);
        CHECK(told_seat(hall, bob, 1, SeatKind::empty));
        CHECK(saved_tokens(dir.path(), table)[0].empty());
        CHECK(saved_tokens(dir.path(), table)[1] != "");
        REQUIRE(hall.core().save_all() == 0);
    }
    // Restarted after Bob's time was up (the file's time says when he left): the table goes.
    FakeHall hall(options);
    hall.wall_now += options.away_limit + 1h;
    hall.restore();
    CHECK(hall.core().table_count() == 0);
}

TEST_CASE("hall core: the lobby's changes go out coalesced, requests have a budget",
          "[hall][core]") {
    FakeHall hall;
    const int lou = hall.hello("Lou");
    const int ann = hall.hello("Ann");
    const int eve = hall.hello("Eve");
    const int table = hall.create(ann);
    hall.sit(ann, table, 1);
    hall.advance(1s); // the lobby's changes so far go out
    hall.take(lou);
    const auto snapshots = [&] {
        int count = 0;
        for (const ServerMessage& m : hall.take(lou))
            count += std::holds_alternative<LobbyBegin>(m) ? 1 : 0;
        return count;
    };
    SECTION("a watcher toggling does not flood the lobby") {
        for (int i = 0; i < 9; ++i) {
            hall.send(eve, Watch{table});
            hall.send(eve, Leave{});
            hall.advance(10ms);
        }
        CHECK(snapshots() == 0); // 90 ms since the last snapshot: they wait for lobby_interval
        hall.advance(160ms);
        CHECK(snapshots() == 1); // all 18 changes in one
        hall.advance(250ms);
        CHECK(snapshots() == 0); // nothing changed since
    }
    SECTION("too many syncs are refused, and the budget refills") {
        hall.send(eve, Watch{table});
        for (int i = 0; i < 19; ++i)
            hall.send(eve, Sync{});
        CHECK_FALSE(hall.error(eve));
        hall.send(eve, Sync{});
        CHECK(hall.error(eve) == ErrorCode::rate);
        hall.now += 200ms; // 5 a second
        hall.send(eve, Sync{});
        CHECK_FALSE(hall.error(eve));
    }
}

TEST_CASE("hall core: the computer's answer for a table that changed is dropped", "[hall][core]") {
    std::ostringstream text;
    HallLog log(text);
    ServerOptions options;
    options.log = &log;
    FakeHall hall(options);
    const int ann = hall.hello("Ann");
    const int eve = hall.hello("Eve");
    const int table = hall.create(ann);
    hall.send(eve, Watch{table});
    hall.sit(ann, table, 2);
    hall.send(ann, SeatComputer{1, Level::easy}); // it breaks: a search starts
    hall.send(ann, Leave{});
    REQUIRE(hall.computer());
    CHECK(text.str().find("table " + std::to_string(table) +
                          ": the computer's answer is for the table as it was: dropped") !=
          std::string::npos);
    CHECK(hall.core().match(table)->record().actions.empty());
    CHECK(hall.core().match(table)->record().names[1] == "Player 2");
}

TEST_CASE("hall core: connections that never say hello do not hold the hall", "[hall][core]") {
    ServerOptions options;
    options.max_clients = 2;
    options.hello_timeout = 10s;
    FakeHall hall(options);
    std::vector<int> silent;
    for (int i = 0; i < 3; ++i)
        silent.push_back(hall.connect());
    // Only people count toward max_clients.
    hall.hello("Ann");
    hall.hello("Bob");
    const int carl = hall.connect();
    hall.send(carl, Hello{protocol_version, "", "Carl"});
    CHECK(hall.error(carl) == ErrorCode::full);
    CHECK(hall.closed(carl));
    hall.advance(10s - 1ms);
    for (const int id : silent)
        CHECK_FALSE(hall.closed(id));
    hall.advance(1ms);
    for (const int id : silent)
        CHECK(hall.closed(id));
}

TEST_CASE("hall core: a seat's actions have a budget", "[hall][core]") {
    ServerOptions options;
    options.max_errors = 1000;
    FakeHall hall(options);
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    const Act move{chosen_move(*hall.core().match(table))};
    int refused = 0;
    int rate = 0;
    for (int i = 0; i < 100; ++i) {
        hall.send(bob, move);
        const auto code = hall.error(bob);
        REQUIRE(code);
        (*code == ErrorCode::rate ? rate : refused) += 1;
    }
    CHECK(refused == 40);
    CHECK(rate == 60);
    hall.now += 50ms; // one more at 20 a second
    hall.send(bob, move);
    CHECK(hall.error(bob) == ErrorCode::refused);
    hall.play_one(ann, bob, table); // Ann's seat has its own budget
}

TEST_CASE("hall core: an action that cannot be saved is not taken", "[hall][core]") {
    test::TempDir dir("termpool-core");
    FakeHall hall(saved_in(dir.path()));
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    // A full disk (a file size limit; a chmod would not stop the tests' root) makes the
    // atomic write fail.
    const RecordedAction move = chosen_move(*hall.core().match(table));
    {
        const test::FileSizeLimit full(0);
        hall.send(ann, Act{move});
        hall.tick();
    }
    CHECK(hall.error(ann) == ErrorCode::internal);
    CHECK(hall.core().match(table)->record().actions.empty());
    hall.play_one(ann, bob, table);
    CHECK(saved_hash(dir.path(), table) == hall.core().match(table)->state_hash());
}

TEST_CASE("hall core: a request sent with an action finds the action taken", "[hall][core]") {
    FakeHall hall;
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.send(ann, Act{chosen_move(*hall.core().match(table))});
    hall.send(ann, Sync{}); // in the same round, before its end
    REQUIRE(hall.find<ActionDone>(ann));
    const auto end = hall.find<RecordEnd>(ann);
    REQUIRE(end);
    CHECK(end->seq == 1);
}

TEST_CASE("hall core: a table keeps at most max_actions actions", "[hall][core]") {
    ServerOptions options;
    options.max_actions = 3;
    FakeHall hall(options);
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    for (int k = 0; k < 3 && hall.core().match(table)->pending().kind != Pending::over; ++k)
        hall.play_one(ann, bob, table);
    REQUIRE(hall.core().match(table)->record().actions.size() == 3);
    const int actor = hall.core().match(table)->to_act() == 1 ? ann : bob;
    hall.send(actor, Act{chosen_move(*hall.core().match(table))});
    const auto error = hall.find<Error>(actor);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::refused);
    CHECK(error->text.find("the most a table keeps") != std::string::npos);
}

TEST_CASE("hall core: idle_exit counts from when the last table and connection went",
          "[hall][core]") {
    ServerOptions options;
    options.idle_exit = 60s;
    FakeHall hall(options);
    CHECK_FALSE(hall.core().idle_for_good(hall.now));
    const int ann = hall.hello("Ann");
    hall.create(ann);
    hall.now += 120s;
    CHECK_FALSE(hall.core().idle_for_good(hall.now)); // a connection and a table keep it
    hall.disconnect(ann);                             // the table not started goes with her
    CHECK(hall.core().table_count() == 0);
    CHECK_FALSE(hall.core().idle_for_good(hall.now));
    CHECK(hall.core().idle_timeout(hall.now) == 60000);
    hall.now += 60s - 1ms;
    CHECK_FALSE(hall.core().idle_for_good(hall.now));
    hall.now += 1ms;
    CHECK(hall.core().idle_for_good(hall.now));
}

TEST_CASE("hall core: a snooker table is a snooker table, and a concession ends the frame",
          "[hall][core][snooker]") {
    FakeHall hall;
    const int ann = hall.hello("Ann");
    const int bob = hall.hello("Bob");
    const int table = hall.create(ann, GameType::snooker);
    hall.sit(ann, table, 1);
    hall.sit(bob, table, 2);
    const Match& match = *hall.core().match(table);
    CHECK(match.setup().table == TableSize::snooker);
    for (int step = 0; step < 2; ++step)
        hall.play_one(ann, bob, table);
    const int conceding = hall.core().match(table)->to_act();
    RecordedAction concede;
    concede.kind = RecordedAction::Kind::choose;
    concede.choice = Choice::concede;
    hall.send(conceding == 1 ? ann : bob, Act{concede});
    hall.tick();
    CHECK(hall.core().match(table)->game().winner() == 3 - conceding);
    CHECK(hall.core().match(table)->game().win_reason() == WinReason::conceded);
}
