// What a hall's host and its players rely on between games: a table's chat kept for whoever
// comes back, `who` for the host, a state folder that cannot take a save refusing new tables,
// and a hall that goes idle with its unfinished games on disk. By direct calls on the core
// with a fake clock (tests/fake_hall.hpp).
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <sys/stat.h>

#include "fake_hall.hpp"
#include "hall/hall_state.hpp"
#include "hall_helpers.hpp"
#include "temp_dir.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;

namespace {

// The chat lines `id` received (not taken yet), in order; the rest is dropped.
std::vector<std::string> chat_of(FakeHall& hall, int id) {
    std::vector<std::string> lines;
    for (const ServerMessage& m : hall.take(id))
        if (const auto* chat = std::get_if<ChatShown>(&m))
            lines.push_back(chat->name + ": " + chat->text);
    return lines;
}

// The lines of the hall's answer to `who` asked on connection `id`, up to who-end.
std::vector<std::string> who_of(FakeHall& hall, int id) {
    hall.send(id, Who{});
    std::vector<std::string> lines;
    for (const ServerMessage& m : hall.take(id)) {
        if (const auto* line = std::get_if<WhoLine>(&m))
            lines.push_back(line->text);
        if (std::holds_alternative<WhoEnd>(m))
            return lines;
    }
    FAIL("no who-end");
    return lines;
}

} // namespace

TEST_CASE("hall core: a table keeps its last 50 chat lines for whoever sits or watches",
          "[hall][core]") {
    FakeHall hall;
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.play_one(ann, bob, table);
    for (int i = 1; i <= 55; ++i) {
        hall.send(i % 2 ? ann : bob, Chat{"line " + std::to_string(i)});
        hall.advance(1s); // one line a second each
    }
    CHECK(chat_of(hall, ann).size() == 55); // both saw every line as it was said
    // Ann drops and comes back: she reads the last 50, after the record, oldest first.
    const std::string token = hall.token(ann);
    hall.disconnect(ann);
    const int again = hall.hello("Ann", token);
    hall.take(again);
    hall.send(again, Sit{table, 1});
    const auto came = hall.take(again);
    std::vector<std::string> said;
    bool record_ended = false;
    for (const ServerMessage& m : came) {
        record_ended = record_ended || std::holds_alternative<RecordEnd>(m);
        if (const auto* chat = std::get_if<ChatShown>(&m)) {
            CHECK(record_ended);
            CHECK(chat->table == table);
            said.push_back(chat->name + ": " + chat->text);
        }
    }
    REQUIRE(said.size() == serving::chat_lines_kept);
    CHECK(said.front() == "Bob: line 6");
    CHECK(said.back() == "Ann: line 55");
    // A spectator who comes in reads them too; a sync (the record again) does not repeat them.
    const int carol = hall.hello("Carol");
    hall.take(carol);
    hall.send(carol, Watch{table});
    CHECK(chat_of(hall, carol).size() == serving::chat_lines_kept);
    hall.send(carol, Sync{});
    CHECK(chat_of(hall, carol).empty());
}

TEST_CASE("hall core: who tells the host the tables, people and connections, never a token",
          "[hall][core]") {
    FakeHall hall;
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.play_one(ann, bob, table);
    hall.advance(90s);
    const int silent = hall.connect();
    (void)silent;
    const int host = hall.connect(); // who comes before any hello
    const std::vector<std::string> lines = who_of(hall, host);
    std::string all;
    for (const std::string& line : lines)
        all += line + "\n";
    INFO(all);
    REQUIRE(lines.size() == 6); // the hall, one table, four connections
    CHECK(lines[0] == "hall: 2 of 256 people, 1 connections waiting for hello, 1 of 100 tables");
    CHECK(lines[1] == "table 1: 8-ball, race to 1, playing, 1 actions; seat 1 player Ann, seat 2 "
                      "player Bob, 0 watching");
    CHECK(lines[2] == "connection 1: Ann at table 1 in seat 1, connected 1 min, 0 bytes to send");
    CHECK(lines[4] == "connection 3: no hello yet, connected 0 s, 0 bytes to send");
    CHECK(lines[5] == "connection 4: this question, connected 0 s, 0 bytes to send");
    for (const int id : {ann, bob})
        CHECK(all.find(hall.token(id)) == std::string::npos);
    CHECK(all.find(seat_token_hash(hall.token(ann))) == std::string::npos);
    // An away seat says for how long.
    hall.disconnect(bob);
    hall.advance(2h + 5min);
    CHECK(who_of(hall, hall.connect())[1].find("seat 2 away Bob for 2 h 05 min") !=
          std::string::npos);
}

TEST_CASE("hall core: a state folder that cannot take a save refuses new tables, and says why",
          "[hall][core]") {
    test::TempDir dir("termpool-core");
    // A folder under a plain file can never be made, as root too (a read-only mode is no
    // obstacle to root).
    const std::string blocker = dir.path() + "/not-a-folder";
    std::ofstream(blocker) << "x\n";
    ServerOptions options;
    options.state_dir = blocker + "/hall";
    FakeHall hall(options);
    const int ann = hall.hello("Ann");
    hall.take(ann);
    hall.send(ann, Create{GameType::eight_ball, TableSize::seven_foot, 1});
    const auto error = hall.find<Error>(ann);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::internal);
    CHECK(error->text.find("the hall cannot save tables (") == 0);
    CHECK(error->text.find("no table was made; tell the hall's host") != std::string::npos);
    CHECK(hall.core().table_count() == 0);
    hall.tick();
    bool table_shown = false;
    for (const ServerMessage& m : hall.take(ann))
        table_shown = table_shown || std::holds_alternative<TableView>(m);
    CHECK_FALSE(table_shown);
}

TEST_CASE("hall core: with a state folder, unfinished games wait on disk and do not keep the hall",
          "[hall][core]") {
    test::TempDir dir("termpool-core");
    ServerOptions options;
    options.state_dir = dir.path() + "/state";
    options.idle_exit = 60s;
    FakeHall hall(options);
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.play_one(ann, bob, table);
    hall.disconnect(ann);
    hall.disconnect(bob);
    REQUIRE(hall.core().table_count() == 1); // the game goes on, both seats away
    CHECK_FALSE(hall.core().idle_for_good(hall.now));
    hall.now += 60s;
    CHECK(hall.core().idle_for_good(hall.now));
    // At the end nothing is written again: the file's date is what an away seat counts from.
    const std::string file = table_path(options.state_dir, table);
    const timespec old_times[2] = {{1000000000, 0}, {1000000000, 0}};
    REQUIRE(::utimensat(AT_FDCWD, file.c_str(), old_times, 0) == 0);
    CHECK(hall.core().save_all() == 0);
    struct stat st {};
    REQUIRE(::stat(file.c_str(), &st) == 0);
    CHECK(st.st_mtime == 1000000000);
}

TEST_CASE("hall core: without a state folder a table keeps the hall", "[hall][core]") {
    ServerOptions options;
    options.idle_exit = 60s;
    FakeHall hall(options);
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.play_one(ann, bob, table);
    hall.disconnect(ann);
    hall.disconnect(bob);
    CHECK_FALSE(hall.core().idle_for_good(hall.now));
    hall.now += 1h;
    CHECK_FALSE(hall.core().idle_for_good(hall.now));
}

TEST_CASE("hall core: a table whose save failed keeps the hall and is counted at the end",
          "[hall][core]") {
    test::TempDir dir("termpool-core");
    ServerOptions options;
    options.state_dir = dir.path() + "/state";
    options.idle_exit = 60s;
    FakeHall hall(options);
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.play_one(ann, bob, table);
    // The state folder goes (a plain file in its place): Ann's seat going away is not saved.
    const std::string aside = dir.path() + "/state.aside";
    REQUIRE(std::rename(options.state_dir.c_str(), aside.c_str()) == 0);
    std::ofstream(options.state_dir) << "x\n";
    hall.disconnect(ann);
    hall.disconnect(bob);
    hall.now += 1h;
    CHECK_FALSE(hall.core().idle_for_good(hall.now)); // it lives only here now
    CHECK(hall.core().save_all() == 1);
    // The folder back, the table is saved at the end and the hall may go.
    REQUIRE(std::remove(options.state_dir.c_str()) == 0);
    REQUIRE(std::rename(aside.c_str(), options.state_dir.c_str()) == 0);
    CHECK(hall.core().save_all() == 0);
    CHECK_FALSE(hall.core().idle_for_good(hall.now)); // idle from now
    hall.now += 60s;
    CHECK(hall.core().idle_for_good(hall.now));
    (void)table;
}

TEST_CASE("hall core: a name already in the hall is refused, however it is typed", "[hall][core]") {
    FakeHall hall;
    const int ann = hall.hello("Ann");
    for (const char* same : {"Ann", "ANN", "\xef\xbc\xa1\xef\xbd\x8e\xef\xbd\x8e" /* ＡＮＮ */}) {
        const int other = hall.connect();
        hall.send(other, Hello{protocol_version, "", same});
        const auto error = hall.find<Error>(other);
        REQUIRE(error);
        CHECK(error->code == ErrorCode::name_taken);
        CHECK(error->text ==
              "someone in the hall is called Ann already: come in under another name");
        CHECK(hall.closed(other));
    }
    // Ann herself, with her token, from another terminal: the old connection gives way.
    const int again = hall.hello("Ann", hall.token(ann));
    CHECK(hall.closed(ann));
    // Once she has gone, the name is free for anyone.
    hall.disconnect(again);
    hall.tick();
    CHECK(hall.hello("ANN") != 0);
}

TEST_CASE("hall core: the name of a player away from a seat waits for them", "[hall][core]") {
    FakeHall hall;
    const auto [ann, bob, table] = hall.ann_and_bob_seated();
    hall.play_one(ann, bob, table);
    const std::string token = hall.token(bob);
    hall.disconnect(bob);
    hall.tick();
    // Someone else cannot take "Bob" while his seat waits: he could not come back as Bob.
    for (const char* same : {"Bob", "BOB"}) {
        const int other = hall.connect();
        hall.send(other, Hello{protocol_version, "", same});
        const auto error = hall.find<Error>(other);
        REQUIRE(error);
        CHECK(error->code == ErrorCode::name_taken);
        CHECK(error->text == "Bob holds a seat at table " + std::to_string(table) +
                                 ": if it is yours, come in as Bob exactly; if not, under "
                                 "another name");
        CHECK(hall.closed(other));
    }
    // Bob himself, with his token, comes back under his name and sits again.
    const int again = hall.hello("Bob", token);
    REQUIRE(again != 0);
    CHECK_FALSE(hall.closed(again));
    hall.sit(again, table, 2);
    CHECK(hall.core().match(table)->name(2) == "Bob");
    // Gone again for longer than the away limit, his seat is freed and the name with it.
    hall.disconnect(again);
    hall.advance(ServerOptions{}.away_limit + 1s);
    CHECK(hall.core().match(table)->name(2) != "Bob");
    CHECK(hall.hello("BOB") != 0);
    (void)ann;
}

TEST_CASE("hall core: a token whose seat shows the name comes in under it, even where another "
          "token's seat shows it too (a state folder from before the rule)",
          "[hall][core]") {
    test::TempDir dir("termpool-hosting");
    ServerOptions options;
    options.state_dir = dir.path();
    std::string fay_token;
    {
        FakeHall hall(options);
        const int fay = hall.hello("Fay");
        const int ann = hall.hello("Ann");
        fay_token = hall.token(fay);
        const int table = hall.create(fay);
        hall.sit(fay, table, 1);
        hall.sit(ann, table, 2);
        hall.play_one(fay, ann, table);
        hall.disconnect(fay);
        hall.disconnect(ann);
        REQUIRE(hall.core().save_all() == 0);
    }
    // What an older hall let happen: a second Fay, another token, at a seat of table 2.
    std::vector<std::string> problems;
    std::vector<SavedTable> saved = load_tables(dir.path(), problems);
    REQUIRE(saved.size() == 1);
    SavedTable second = saved[0];
    second.number = 2;
    const std::string other_token = "0123456789abcdef0123456789abcdef";
    second.seat_tokens[0] = seat_token_hash(other_token);
    second.seat_tokens[1] = "";
    REQUIRE(save_table(dir.path(), second) == "");
    FakeHall hall(options);
    hall.restore();
    REQUIRE(hall.core().table_count() == 2);
    // Each Fay comes in with her own token (one at a time: two connected under one name
    // are still refused), and each is told her own seat.
    const int first = hall.hello("Fay", fay_token);
    CHECK(hall.find<Yours>(first));
    hall.disconnect(first);
    const int second_fay = hall.hello("Fay", other_token);
    CHECK_FALSE(hall.closed(second_fay));
    hall.disconnect(second_fay);
    // A third token still meets the door.
    const int third = hall.connect();
    hall.send(third, Hello{protocol_version, "", "Fay"});
    const auto error = hall.find<Error>(third);
    REQUIRE(error);
    CHECK(error->code == ErrorCode::name_taken);
    CHECK(hall.closed(third));
}
