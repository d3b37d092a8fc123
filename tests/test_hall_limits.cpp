// What one person may take of the hall, by direct calls on its core with a fake clock: tables
// held in any state (issue 26, finding 3: "one person can fill every table for a week"), and
// newcomers let in by idle connections giving way (finding 4: "new players can be locked out").
#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <sys/stat.h>

#include "fake_hall.hpp"
#include "hall/hall_state.hpp"
#include "temp_dir.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;

namespace {

// The attack of finding 3, once: a new connection (a new token, unless `token` is given) as
// `name` creates a table, sits, seats the computer, places the cue ball and leaves, so that the
// table stays with an away seat. The table's number, or 0 when the hello or the create was
// refused; `token_used`, when given, gets the connection's token.
int hold_a_table(FakeHall& hall, const std::string& name, const std::string& token = "",
                 std::string* token_used = nullptr) {
    const int id = hall.connect();
    hall.send(id, Hello{protocol_version, token, name});
    const auto welcome = hall.find<Welcome>(id);
    if (!welcome)
        return 0;
    if (token_used)
        *token_used = welcome->token;
    hall.send(id, Create{GameType::eight_ball, TableSize::seven_foot, 1});
    int table = 0;
    for (const ServerMessage& m : hall.take(id))
        if (const auto* c = std::get_if<Created>(&m))
            table = c->table;
    if (table == 0) {
        hall.disconnect(id);
        return 0;
    }
    hall.sit(id, table, 1);
    hall.send(id, SeatComputer{2, Level::easy});
    REQUIRE(hall.core().match(table)->to_act() == 1);
    hall.play_one(id, 0, table); // the cue ball placed for the break
    hall.send(id, Leave{});
    hall.disconnect(id);
    REQUIRE(hall.core().match(table)); // away, it stays
    return table;
}

bool archived(const std::string& dir, int table) {
    struct stat info {};
    return ::stat((dir + "/archive/table-" + std::to_string(table) + ".save").c_str(), &info) ==
               0 &&
           ::stat(table_path(dir, table).c_str(), &info) != 0;
}

} // namespace

TEST_CASE("hall limits: one name cannot fill the hall, with a new token per hello or not",
          "[hall][core][limits]") {
    ServerOptions options;
    options.max_tables = 20;
    FakeHall hall(options);
    // A new token per hello: her name waits for her at her away seat, so every later hello
    // under it, however typed, is turned away at the door.
    std::string token;
    int held = hold_a_table(hall, "Mallory", "", &token) != 0 ? 1 : 0;
    REQUIRE(held == 1);
    for (int i = 0; i < 20; ++i)
        held += hold_a_table(hall, i % 2 ? "Mallory" : "MALLORY") != 0 ? 1 : 0;
    CHECK(held == 1);
    // Her own token, under her name or new ones, is one person: up to the most one person may
    // hold, and no more.
    for (int i = 0; i < 20; ++i)
        held += hold_a_table(hall, i % 2 ? "Mallory" : "M" + std::to_string(i), token) != 0 ? 1 : 0;
    CHECK(held == options.max_tables_per_person);
    // Nor may she sit at someone else's table.
    const int ann = hall.hello("Ann");
    const int table = hall.create(ann);
    const int again = hall.hello("mallory", token);
    hall.send(again, Sit{table, 2});
    const auto error = hall.find<Error>(again);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::full);
    CHECK(error->text.find("the most one person may") != std::string::npos);
    hall.sit(ann, table, 1);
}

TEST_CASE("hall limits: tables one name created are counted under a new token too",
          "[hall][core][limits]") {
    // Mallory creates a table, never sits, and goes; someone watching keeps the waiting table.
    // No seat keeps her name, so a new token comes in under it, and is held to her tables.
    ServerOptions options;
    FakeHall hall(options);
    for (int i = 0; i < options.max_tables_per_person; ++i) {
        const int mallory = hall.hello("Mallory");
        const int table = hall.create(mallory);
        const int watcher = hall.hello("W" + std::to_string(i));
        hall.send(watcher, Watch{table});
        hall.tick();
        hall.disconnect(mallory);
        REQUIRE(hall.core().match(table));
    }
    const int again = hall.hello("MALLORY");
    hall.send(again, Create{GameType::eight_ball, TableSize::seven_foot, 1});
    const auto error = hall.find<Error>(again);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::full);
    CHECK(error->text == "you hold " + std::to_string(options.max_tables_per_person) +
                             " tables already, the most one person may: finish or leave one");
    // Under another name she is another person.
    CHECK(hall.create(hall.hello("Nora")) != 0);
}

TEST_CASE("hall limits: the last free tables are kept for people who hold none",
          "[hall][core][limits]") {
    ServerOptions options;
    options.max_tables = 20; // a reserve of 2
    FakeHall hall(options);
    std::string p0_token;
    REQUIRE(hold_a_table(hall, "P0", "", &p0_token) != 0);
    for (int i = 1; i < 18; ++i)
        REQUIRE(hold_a_table(hall, "P" + std::to_string(i)) != 0);
    // P0 comes back (her token): she holds one, so the last two are not for her.
    CHECK(hold_a_table(hall, "P0", p0_token) == 0);
    CHECK(hall.core().table_count() == 18);
    const int ann = hall.hello("Ann");
    hall.create(ann); // holds none
    hall.send(ann, Create{GameType::eight_ball, TableSize::seven_foot, 1});
    const auto error = hall.find<Error>(ann);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::full);
    CHECK(error->text.find("kept for people who hold none") != std::string::npos);
    const int bob = hall.hello("Bob");
    hall.create(bob);
    CHECK(hall.core().table_count() == 20);
}

TEST_CASE("hall limits: a table everyone left is archived after a day without an action",
          "[hall][core][limits]") {
    test::TempDir dir("termpool-limits");
    ServerOptions options;
    options.state_dir = dir.path();
    FakeHall hall(options);
    const int left = hold_a_table(hall, "Mallory");
    // A table someone sits at stays however long nothing happens.
    const int ann = hall.hello("Ann");
    const int kept = hall.create(ann);
    hall.sit(ann, kept, 1);
    hall.advance(24h - 2min);
    CHECK(hall.core().match(left));
    hall.advance(2min);
    CHECK_FALSE(hall.core().match(left));
    CHECK(archived(dir.path(), left));
    CHECK(hall.core().match(kept));
    // Its file is kept, out of the state folder: a restart does not bring it back, and its
    // number may be used again without touching the archived file.
    FakeHall restarted(options);
    restarted.restore();
    CHECK_FALSE(restarted.core().match(left));
    const int next = hold_a_table(hall, "Bob");
    CHECK(next == left);
    hall.advance(24h);
    CHECK(archived(dir.path(), left)); // the first
    struct stat info {};
    CHECK(::stat((dir.path() + "/archive/table-" + std::to_string(left) + ".save.1").c_str(),
                 &info) == 0);
}

TEST_CASE("hall limits: one connection too many waiting for hello closes the oldest",
          "[hall][core][limits]") {
    ServerOptions options;
    options.max_unwelcomed = 3;
    FakeHall hall(options);
    std::vector<int> silent;
    for (int i = 0; i < 3; ++i) {
        silent.push_back(hall.connect());
        hall.now += 1s;
    }
    // A newcomer: the oldest silent one gives way, told why.
    const int ann = hall.connect();
    CHECK(hall.closed(silent[0]));
    const auto error = hall.find<Error>(silent[0]);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::full);
    CHECK(error->text.find("waited longest") != std::string::npos);
    CHECK_FALSE(hall.closed(silent[1]));
    CHECK_FALSE(hall.closed(ann));
    hall.send(ann, Hello{protocol_version, "", "Ann"});
    CHECK(hall.find<Welcome>(ann));
}

TEST_CASE("hall limits: a full hall lets a newcomer in by closing the idlest in the lobby",
          "[hall][core][limits]") {
    ServerOptions options;
    options.max_clients = 3;
    options.lobby_idle_limit = 5min;
    FakeHall hall(options);
    const int ann = hall.hello("Ann"); // idle in the lobby from now
    const int bob = hall.hello("Bob");
    const int cid = hall.hello("Cid");
    const int table = hall.create(bob);
    hall.sit(bob, table, 1); // at a table: never closed for a newcomer
    hall.now += 3min;
    hall.send(cid, Chat{"hello?"}); // heard from (an error, but something said)
    for (int i = 0; i < 10; ++i) {
        hall.now += 10s;
        hall.send(ann, Ping{}); // pings alone do not count
    }
    hall.now += 2min;
    // Ann has said nothing but pings for 5 min 40 s, Cid for 2 min 40 s.
    const int dan = hall.hello("Dan");
    CHECK(hall.closed(ann));
    const auto error = hall.find<Error>(ann);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::full);
    CHECK(error->text.find("idle in the lobby longest") != std::string::npos);
    CHECK_FALSE(hall.closed(dan));
    CHECK_FALSE(hall.closed(bob));
    CHECK_FALSE(hall.closed(cid));
    // Nobody else idle long enough: the next newcomer is refused as before.
    const int eve = hall.connect();
    hall.send(eve, Hello{protocol_version, "", "Eve"});
    CHECK(hall.error(eve) == ErrorCode::full);
    CHECK(hall.closed(eve));
    CHECK_FALSE(hall.closed(cid));
}
