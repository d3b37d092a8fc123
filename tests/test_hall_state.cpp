// The hall's folders: the socket folder made private and refused when someone else could
// reach into it (tmux's rule), the default paths, and the state folder, where every table is
// saved atomically with its seat tokens' hashes and read back, a damaged file moved aside.
#include <atomic>
#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <thread>
#include <unistd.h>
#include <vector>

#include "file_helpers.hpp"
#include "hall/hall_state.hpp"
#include "hall/sha256.hpp"
#include "hall/socket_dir.hpp"
#include "hall/socket_trust.hpp"
#include "match_helpers.hpp"
#include "scoped_env.hpp"
#include "temp_dir.hpp"
#include "wait_until.hpp"

using namespace termpool;
using namespace termpool::hall;
using termpool::test::contents;
using termpool::test::mode_of;
using termpool::test::names_in;
using termpool::test::ScopedEnv;
using termpool::test::TempDir;
using termpool::test::wait_until;

namespace {

namespace fs = std::filesystem;

// A match of two computers, `moves` actions in (fewer if it ends first).
Match played(GameType game, TableSize size, std::uint64_t seed, int race_to, int moves) {
    GameRecord header;
    header.setup.game = game;
    header.setup.table = size;
    header.seed = seed;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    header.computers[0] = Level::easy;
    header.computers[1] = Level::medium;
    header.race_to = race_to;
    Match match = test::started(header, seed);
    for (int k = 0; k < moves && match.pending().kind != Pending::over; ++k)
        REQUIRE(test::play_computer_move(match) == MatchError::none);
    return match;
}

SavedTable table_of(int number, const Match& match, std::string token1, std::string token2) {
    SavedTable table;
    table.number = number;
    table.record = match.record();
    table.seat_tokens[0] = std::move(token1);
    table.seat_tokens[1] = std::move(token2);
    return table;
}

} // namespace

TEST_CASE("the socket folder is made private, and refused when someone else could reach in",
          "[hall]") {
    TempDir tmp("termpool-hall");
    const std::string folder = tmp.path() + "/sock";

    SECTION("made with mode 0700, and found good again") {
        CHECK(prepare_socket_dir(folder + "/hall.sock") == "");
        CHECK(fs::is_directory(folder));
        CHECK(mode_of(folder) == 0700);
        CHECK(prepare_socket_dir(folder + "/hall.sock") == "");
    }
    SECTION("a folder others or its group may only read is refused too: they could reach the "
            "hall") {
        REQUIRE(::mkdir(folder.c_str(), 0700) == 0);
        for (const mode_t mode : {mode_t{0755}, mode_t{0750}, mode_t{0711}}) {
            INFO("mode " << std::oct << mode);
            REQUIRE(::chmod(folder.c_str(), mode) == 0);
            CHECK_THAT(prepare_socket_dir(folder + "/hall.sock"),
                       Catch::StartsWith(folder + ": the socket folder is open to ") &&
                           Catch::Contains("make it private with chmod 700"));
        }
    }
    SECTION("group-writable and world-writable folders are refused, naming the folder") {
        REQUIRE(::mkdir(folder.c_str(), 0700) == 0);
        REQUIRE(::chmod(folder.c_str(), 0770) == 0);
        const std::string group = prepare_socket_dir(folder + "/hall.sock");
        CHECK(group.starts_with(folder + ": "));
        CHECK_THAT(group, Catch::Contains("writable by its group") && Catch::Contains("0770"));
        REQUIRE(::chmod(folder.c_str(), 01777) == 0); // as /tmp is
        CHECK_THAT(prepare_socket_dir(folder + "/hall.sock"),
                   Catch::StartsWith(folder + ": ") && Catch::Contains("writable by others") &&
                       Catch::Contains("1777"));
    }
    SECTION("a file, or a symbolic link to a good folder, is not a directory") {
        tmp.write("plain", "not a folder\n");
        CHECK_THAT(prepare_socket_dir(tmp.path() + "/plain/hall.sock"),
                   Catch::StartsWith(
                       tmp.path() + "/plain: the socket folder is not a directory (owned by uid "));
        REQUIRE(::mkdir(folder.c_str(), 0700) == 0);
        REQUIRE(::symlink(folder.c_str(), (tmp.path() + "/link").c_str()) == 0);
        CHECK_THAT(prepare_socket_dir(tmp.path() + "/link/hall.sock"),
                   Catch::StartsWith(tmp.path() + "/link: ") && Catch::Contains("symbolic link"));
    }
    SECTION("a folder owned by someone else is refused") {
        // Without root, / is someone else's; as root, a folder given away to nobody is.
        std::string theirs = "/";
        if (::geteuid() == 0) {
            theirs = folder;
            REQUIRE(::mkdir(theirs.c_str(), 0700) == 0);
            REQUIRE(::chown(theirs.c_str(), 65534, 65534) == 0);
        }
        const std::string problem =
            prepare_socket_dir((theirs == "/" ? "" : theirs) + "/hall.sock");
        CHECK_THAT(problem, Catch::StartsWith(theirs + ": ") && Catch::Contains("owned by uid") &&
                                Catch::Contains("not by this user"));
    }
    SECTION("a missing parent and a path too long for a socket are said so") {
        CHECK(prepare_socket_dir(tmp.path() + "/no/such/hall.sock") ==
              tmp.path() + "/no/such: cannot create the socket folder: " + std::strerror(ENOENT));
        const std::string too_long = folder + "/" + std::string(max_socket_path_bytes(), 'x');
        CHECK_THAT(prepare_socket_dir(too_long), Catch::Contains("too long for a Unix socket"));
        CHECK_FALSE(fs::exists(folder)); // refused before anything was made
    }
}

TEST_CASE("the socket and the state folder follow XDG, with the fallbacks", "[hall]") {
    {
        ScopedEnv runtime("XDG_RUNTIME_DIR", "/run/user/4242");
        CHECK(default_socket_path() == "/run/user/4242/termpool/hall.sock");
    }
    for (const std::optional<std::string>& unset : {std::optional<std::string>(), {""}}) {
        ScopedEnv runtime("XDG_RUNTIME_DIR", unset);
        CHECK(default_socket_path() ==
              "/tmp/termpool-" + std::to_string(::geteuid()) + "/hall.sock");
    }
    {
        ScopedEnv state("XDG_STATE_HOME", "/srv/pool/state");
        CHECK(default_state_dir() == "/srv/pool/state/termpool/hall");
    }
    {
        ScopedEnv state("XDG_STATE_HOME", std::nullopt);
        ScopedEnv home("HOME", "/home/pool");
        CHECK(default_state_dir() == "/home/pool/.local/state/termpool/hall");
    }
}

TEST_CASE("seat tokens are random, and the state file keeps their SHA-256", "[hall]") {
    const std::string a = new_seat_token(), b = new_seat_token();
    CHECK(a.size() == 32);
    CHECK(a.find_first_not_of("0123456789abcdef") == std::string::npos);
    CHECK(a != b);
    // FIPS 180-4's own example, and what the file keeps of a token (tests/test_sha256.cpp
    // checks the rest of the standard's vectors).
    CHECK(seat_token_hash("abc") ==
          "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    CHECK(seat_token_hash(a) == sha256_hex(a));
    CHECK(seat_token_hash(a) != seat_token_hash(b));
    CHECK(valid_seat_token_hash(seat_token_hash(a)));
    CHECK(valid_seat_token_hash(seat_token_hash("")));
    const std::string upper = "BA7816BF8F01CFEA414140DE5DAE2223B00361A396177A9CB410FF61F20015AD";
    CHECK_FALSE(valid_seat_token_hash(upper));
    CHECK_FALSE(valid_seat_token_hash(seat_token_hash(a).substr(1)));
    CHECK_FALSE(valid_seat_token_hash(seat_token_hash(a) + "0"));
    CHECK_FALSE(valid_seat_token_hash("af63dc4c8601ec8c")); // an older build's FNV-1a 64
    CHECK_FALSE(valid_seat_token_hash(a));
}

TEST_CASE("tables save and load back with their seat tokens, in number order", "[hall]") {
    TempDir tmp("termpool-hall");
    const std::string dir = tmp.path() + "/state/hall"; // made by the first save
    const std::string token1 = new_seat_token(), token2 = new_seat_token();
    Match eight = played(GameType::eight_ball, TableSize::nine_foot, 7, 1, 6);
    const Match nine = played(GameType::nine_ball, TableSize::seven_foot, 8, 1, 4);
    const Match race = played(GameType::eight_ball_bar, TableSize::eight_foot, 9, 3, 3);
    const std::vector<SavedTable> saved = {
        table_of(10, eight, seat_token_hash(token1), seat_token_hash(token2)),
        table_of(2, nine, "", seat_token_hash(token2)),
        table_of(3, race, "", ""),
    };
    for (const SavedTable& table : saved)
        REQUIRE(save_table(dir, table) == "");
    CHECK(mode_of(tmp.path() + "/state") == 0700);
    CHECK(mode_of(dir) == 0700);
    CHECK(mode_of(table_path(dir, 10)) == 0600);
    // Files the hall does not own are left alone.
    std::ofstream(dir + "/notes.txt") << "hello\n";
    std::ofstream(dir + "/table-02.save") << "not a name the hall writes\n";

    // Readable text: the hash is there and the raw token is not.
    const std::string text = contents(table_path(dir, 10));
    CHECK_THAT(text,
               Catch::StartsWith("termpool-hall-table 1\nnumber 10\nseat1-token-hash sha256 " +
                                 seat_token_hash(token1) + "\nseat2-token-hash sha256 " +
                                 seat_token_hash(token2) + "\ntermpool-record "));
    CHECK(text.find(token1) == std::string::npos);
    CHECK_THAT(contents(table_path(dir, 3)),
               Catch::StartsWith("termpool-hall-table 1\nnumber 3\ntermpool-record 6\n"));

    std::vector<std::string> problems;
    std::vector<SavedTable> loaded = load_tables(dir, problems);
    CHECK(problems.empty());
    REQUIRE(loaded.size() == 3);
    const std::vector<const Match*> live = {&nine, &race, &eight}; // 2, 3, 10: as numbers
    for (std::size_t k = 0; k < loaded.size(); ++k) {
        const SavedTable& back = loaded[k];
        const SavedTable& original =
            *std::find_if(saved.begin(), saved.end(),
                          [&](const SavedTable& t) { return t.number == back.number; });
        INFO("table " << back.number);
        CHECK(back.number == (k == 0 ? 2 : k == 1 ? 3 : 10));
        CHECK(format_record(back.record) == format_record(original.record));
        CHECK(back.seat_tokens[0] == original.seat_tokens[0]);
        CHECK(back.seat_tokens[1] == original.seat_tokens[1]);
        const auto replayed = Match::replay(back.record);
        REQUIRE(std::holds_alternative<Match>(replayed));
        CHECK(std::get<Match>(replayed).state_hash() == live[k]->state_hash());
    }
    CHECK(loaded[2].seat_tokens[0] == seat_token_hash(token1)); // a returning player's proof

    // A save after more play replaces the old one; a forgotten table is gone.
    REQUIRE(test::play_computer_move(eight) == MatchError::none);
    REQUIRE(save_table(dir, table_of(10, eight, seat_token_hash(token1), "")) == "");
    forget_table(dir, 2);
    forget_table(dir, 99); // never saved: nothing happens
    loaded = load_tables(dir, problems);
    CHECK(problems.empty());
    REQUIRE(loaded.size() == 2);
    CHECK(loaded[0].number == 3);
    CHECK(loaded[1].number == 10);
    CHECK(loaded[1].record.actions.size() == eight.record().actions.size());
    CHECK(loaded[1].seat_tokens[1] == "");
    CHECK(names_in(dir) ==
          std::vector<std::string>{"notes.txt", "table-02.save", "table-10.save", "table-3.save"});
    CHECK(load_tables(tmp.path() + "/never-made", problems).empty());
    CHECK(problems.empty());
}

TEST_CASE("a save is atomic: a temporary file in the same folder, synced, renamed", "[hall]") {
    TempDir tmp("termpool-hall");
    const std::string dir = tmp.path();
    const Match short_game = played(GameType::eight_ball, TableSize::nine_foot, 3, 1, 1);
    const Match long_game = played(GameType::nine_ball, TableSize::nine_foot, 4, 3, 12);
    const SavedTable first = table_of(1, short_game, "", "");
    const SavedTable second = table_of(1, long_game, seat_token_hash("x"), "");
    REQUIRE(save_table(dir, second) == "");
    const std::string long_text = contents(table_path(dir, 1));
    REQUIRE(save_table(dir, first) == "");
    const std::string short_text = contents(table_path(dir, 1));
    REQUIRE(short_text.size() < long_text.size());
    CHECK(names_in(dir) == std::vector<std::string>{"table-1.save"}); // no temporary file left

    SECTION("a failed save leaves the old file whole and says why") {
        // A full disk (a file size limit, which stops root too): the text cannot be written.
        {
            const test::FileSizeLimit full(0);
            CHECK_THAT(save_table(dir, second),
                       Catch::StartsWith(table_path(dir, 1) + ".tmp.") &&
                           Catch::EndsWith(": cannot write: " + std::string(std::strerror(EFBIG))));
        }
        CHECK(contents(table_path(dir, 1)) == short_text);
        CHECK(names_in(dir) == std::vector<std::string>{"table-1.save"}); // the temporary went
        // The file's own name taken by a folder that is not empty: the rename fails, and the
        // temporary file goes.
        REQUIRE(::mkdir(table_path(dir, 2).c_str(), 0700) == 0);
        tmp.write("table-2.save/inside", "x");
        CHECK_THAT(save_table(dir, table_of(2, short_game, "", "")),
                   Catch::StartsWith(table_path(dir, 2) + ": cannot rename " + table_path(dir, 2) +
                                     ".tmp.") &&
                       Catch::Contains(" to it: "));
        CHECK(names_in(dir) == std::vector<std::string>{"table-1.save", "table-2.save"});
        CHECK(names_in(table_path(dir, 2)) == std::vector<std::string>{"inside"});
        CHECK_THAT(save_table(tmp.path() + "/table-1.save/sub", first),
                   Catch::Contains("cannot create the folder: ") &&
                       Catch::Contains(std::strerror(ENOTDIR)));
    }
    SECTION("bad numbers and hashes are refused before anything is written") {
        CHECK_THAT(save_table(dir, table_of(0, short_game, "", "")),
                   Catch::Contains("table number 0 out of range"));
        CHECK_THAT(save_table(dir, table_of(1, short_game, "", "raw-token\nend")),
                   Catch::Contains("seat 2's token hash is not 64 lowercase hex digits"));
        CHECK(contents(table_path(dir, 1)) == short_text);
    }
    SECTION("a writer killed at any moment leaves the old file or the new one") {
        // The writer counts its saves in memory it shares with this process: each round it is
        // killed once it has made a few (1, 4, 7, ... 16), so in the middle of its loop,
        // wherever in a save that lands; never after a fixed time.
        static_assert(std::atomic<int>::is_always_lock_free);
        void* shared = ::mmap(nullptr, sizeof(std::atomic<int>), PROT_READ | PROT_WRITE,
                              MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        REQUIRE(shared != MAP_FAILED);
        struct Unmap {
            void* memory;
            ~Unmap() { ::munmap(memory, sizeof(std::atomic<int>)); }
        } unmap{shared};
        auto* saves = new (shared) std::atomic<int>(0);
        for (int round = 0; round < 6; ++round) {
            saves->store(0);
            const pid_t child = ::fork();
            REQUIRE(child >= 0);
            if (child == 0) {
                // Saves the two versions in turn until killed (bounded in count and time).
                const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
                for (int k = 0; k < 100000 && std::chrono::steady_clock::now() < until; ++k) {
                    if (!save_table(dir, k % 2 == 0 ? second : first).empty())
                        ::_exit(1);
                    ++*saves;
                }
                ::_exit(0);
            }
            const int target = 1 + 3 * round;
            int status = 0;
            bool gone = false; // it exited by itself (and is reaped)
            wait_until(
                [&] {
                    gone = ::waitpid(child, &status, WNOHANG) == child;
                    return gone || *saves >= target;
                },
                5, std::chrono::microseconds(100));
            const int made = *saves;
            if (!gone) {
                ::kill(child, SIGKILL);
                REQUIRE(::waitpid(child, &status, 0) == child);
            }
            CHECK(made >= target);
            CHECK(WIFSIGNALED(status)); // killed mid-loop, not finished or failed
            const std::string text = contents(table_path(dir, 1));
            CHECK((text == short_text || text == long_text));
            std::vector<std::string> problems;
            CHECK(load_tables(dir, problems).size() == 1);
            CHECK(problems.empty()); // a leftover table-1.save.tmp.XXXXXX is not a table
            // ... and the server starting (load_tables) removed it.
            CHECK(names_in(dir) == std::vector<std::string>{"table-1.save"});
        }
        REQUIRE(save_table(dir, first) == "");
        CHECK(names_in(dir) == std::vector<std::string>{"table-1.save"});
    }
}

TEST_CASE("a damaged table file is moved aside as .bad, never over an older one, the good "
          "ones load",
          "[hall]") {
    TempDir tmp("termpool-hall");
    const std::string dir = tmp.path();
    const Match game = played(GameType::eight_ball, TableSize::nine_foot, 11, 1, 4);
    REQUIRE(save_table(dir, table_of(1, game, "", "")) == "");
    REQUIRE(save_table(dir, table_of(2, game, seat_token_hash("a"), "")) == "");
    const std::string good = contents(table_path(dir, 2));
    REQUIRE(good.find("termpool-hall-table 1\nnumber 2\nseat1-token-hash sha256 "
                      "ca978112ca1bbdcafac231b39a23dc4da786eff8147c4e72b9807785afee48bb\n"
                      "termpool-record 6\n") == 0);
    // The line (from 1) that starts with `start`, and the text with that line replaced.
    auto line_of = [](const std::string& text, const std::string& start) {
        const std::size_t at = text.find("\n" + start);
        REQUIRE(at != std::string::npos);
        return 2 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    };
    auto replace_line = [](std::string text, const std::string& start, const std::string& with) {
        const std::size_t at = text.find("\n" + start) + 1;
        return text.replace(at, text.find('\n', at) - at, with);
    };
    const int first_shot = line_of(good, "shot ");
    const int check_line = line_of(good, "check ");
    const int end_line = line_of(good, "end");

    struct Damage {
        std::string text;
        int line;
        std::string message;
    };
    const std::vector<Damage> damages = {
        {replace_line(good, "shot ", "shot banana"), first_shot, "shot"},
        {replace_line(good, "shot ", "place 0.01 0.01"), first_shot, "cannot be placed"},
        // A state other than the one the table was saved in: edited, or another simulator.
        {replace_line(good, "check ", "check 0123456789abcdef"), check_line, "edited or damaged"},
        {good.substr(0, good.size() - 4), end_line - 1, "truncated"},
        {replace_line(good, "number 2", "number 5"), 2, "does not match the file's name"},
        {replace_line(good, "termpool-hall-table 1", "termpool-hall-table 9"), 1, "newer"},
        {replace_line(good, "seat1-token-hash", "seat1-token-hash sha256 secret"), 3,
         "64 lowercase hex digits"},
        {replace_line(good, "seat1-token-hash", "seat1-token-hash sha256 00"), 3,
         "64 lowercase hex digits"},
        // What an older build wrote: a hash anyone could forge a token for.
        {replace_line(good, "seat1-token-hash", "seat1-token-hash fnv1a64 af63dc4c8601ec8c"), 3,
         "unknown token hash 'fnv1a64' (sha256 expected)"},
        {replace_line(good, "number 2", "colour blue"), 2, "unknown or malformed line 'colour'"},
        {replace_line(good, "seat1-token-hash", "number 2"), 3, "a second 'number' line"},
        {"", 1, "empty"},
    };
    const std::string damaged = table_path(dir, 2);
    for (std::size_t round = 0; round < damages.size(); ++round) {
        const Damage& damage = damages[round];
        INFO(damage.message);
        tmp.write("table-2.save", damage.text);
        std::vector<std::string> problems;
        const std::vector<SavedTable> loaded = load_tables(dir, problems);
        REQUIRE(loaded.size() == 1);
        CHECK(loaded[0].number == 1);
        REQUIRE(problems.size() == 1);
        // Each damaged file goes aside under a name of its own, never over an older one.
        const std::string aside =
            damaged + ".bad" + (round == 0 ? "" : "." + std::to_string(round));
        CHECK_THAT(problems[0],
                   Catch::StartsWith(damaged + ":" + std::to_string(damage.line) + ": ") &&
                       Catch::Contains(damage.message) &&
                       Catch::EndsWith(" (moved aside as " + aside + ")"));
        CHECK_FALSE(fs::exists(damaged));
        CHECK(contents(aside) == damage.text);
    }
    CHECK(contents(damaged + ".bad") == damages.front().text);
    // What cannot be read at all goes aside too, so that no new table writes over it.
    REQUIRE(::mkdir(table_path(dir, 4).c_str(), 0700) == 0);
    std::vector<std::string> unreadable;
    CHECK(load_tables(dir, unreadable).size() == 1);
    REQUIRE(unreadable.size() == 1);
    CHECK(unreadable[0] == table_path(dir, 4) + ": cannot read: " + std::strerror(EISDIR) +
                               " (moved aside as " + table_path(dir, 4) + ".bad)");
    // The good text under the same name loads again: the damage was in the text alone.
    tmp.write("table-2.save", good);
    std::vector<std::string> problems;
    CHECK(load_tables(dir, problems).size() == 2);
    CHECK(problems.empty());
}

TEST_CASE("a table file someone else put in the state folder is not restored", "[hall]") {
    TempDir tmp("termpool-hall");
    const std::string dir = tmp.path();
    const Match game = played(GameType::nine_ball, TableSize::seven_foot, 5, 1, 2);
    REQUIRE(save_table(dir, table_of(1, game, seat_token_hash("a"), "")) == "");
    std::vector<std::string> problems;
    REQUIRE(load_tables(dir, problems).size() == 1); // this user's
    CHECK(problems.empty());
    // Read as another user would read it (only root could give the file away): it is theirs,
    // not this user's, and goes aside.
    const uid_t me = ::geteuid();
    const uid_t someone = me + 1;
    CHECK(load_tables(dir, problems, someone).empty());
    REQUIRE(problems.size() == 1);
    const std::string path = table_path(dir, 1);
    CHECK(problems[0] == path + ": the table file is owned by " + describe_uid(me) +
                             ", not by this user (" + describe_uid(someone) +
                             "); someone else put it there (moved aside as " + path + ".bad)");
    CHECK_FALSE(fs::exists(path));
    CHECK(fs::exists(path + ".bad"));
}
