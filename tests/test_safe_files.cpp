// Files on a shared host: a save never writes through a link someone planted (its temporary
// file has a new name of its own, made exclusively), every file read is bounded by its kind's
// size and a file over it is refused from its size alone, and whether a folder can take a save
// is known before a table is made on it.
#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <termpool/record.hpp>
#include <termpool/stats.hpp>
#include <unistd.h>
#include <vector>

#include "child_process.hpp"
#include "file_helpers.hpp"
#include "files/atomic_file.hpp"
#include "files/file_limits.hpp"
#include "files/read_file.hpp"
#include "hall/hall_state.hpp"
#include "hall/token_store.hpp"
#include "player/save_read.hpp"
#include "player/stats_file.hpp"
#include "temp_dir.hpp"

using namespace termpool;
using termpool::test::contents;
using termpool::test::names_in;
using termpool::test::TempDir;

namespace {

namespace fs = std::filesystem;

const std::string precious_text = "the player's own file\n";

// A file of `bytes` that takes no room (a hole), made at once.
void make_sparse(const std::string& path, off_t bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    REQUIRE(fd >= 0);
    REQUIRE(::ftruncate(fd, bytes) == 0);
    ::close(fd);
}

bool is_link_to(const std::string& link, const std::string& target) {
    std::error_code error;
    return fs::is_symlink(link, error) && fs::read_symlink(link, error).string() == target;
}

std::string binary() {
    const char* bin = std::getenv("TERMPOOL_BIN");
    return bin && *bin ? bin : "build/termpool";
}

// Runs the game with `args`, HOME and the XDG folders in `dir`; its exit status (bounded in
// time: a refused file is refused at once) and what it printed.
std::pair<int, std::string> run_game(const TempDir& dir, const std::vector<std::string>& args) {
    static int runs = 0;
    const std::string output = dir.path() + "/output-" + std::to_string(++runs);
    std::vector<std::string> argv{binary()};
    argv.insert(argv.end(), args.begin(), args.end());
    test::ChildProcess game(argv, output,
                            {"HOME=" + dir.path(), "XDG_CONFIG_HOME=" + dir.path() + "/config",
                             "XDG_STATE_HOME=" + dir.path() + "/state", "TERM=dumb"});
    const auto status = game.wait_exit(std::chrono::seconds(5));
    REQUIRE(status);
    return {*status, contents(output)};
}

} // namespace

TEST_CASE("no writer of files writes through a link planted at the old temporary name", "[file]") {
    TempDir tmp("termpool-files");
    const std::string precious = tmp.write("precious", precious_text);
    const std::string dir = tmp.path() + "/state";
    REQUIRE(make_directories(dir) == "");
    // Each writer's file, with a link to the precious file where PATH.tmp used to be written.
    auto plant = [&](const std::string& path) {
        fs::create_symlink(precious, path + ".tmp");
        return path;
    };
    std::string error;
    const std::string save = plant(dir + "/game.save");
    CHECK(write_atomically(save, "termpool-record 1\n", error));
    CHECK(error == "");
    CHECK(contents(save) == "termpool-record 1\n");

    hall::SavedTable table;
    table.number = 1;
    const std::string table_file = plant(hall::table_path(dir, 1));
    CHECK(hall::save_table(dir, table) == "");
    CHECK(contents(table_file).starts_with("termpool-hall-table 1\n"));

    const std::string token(32, 'a');
    const std::string token_file = plant(hall::token_path(dir, "Ann"));
    CHECK(hall::save_token(dir, "Ann", token) == "");
    CHECK(hall::load_token(dir, "Ann") == token);

    const std::string stats_file = plant(dir + "/stats");
    const std::string names[2] = {"Ann", "Bob"};
    const PlayerStats stats[2] = {};
    CHECK(save_game_stats(stats_file, names, GameType::eight_ball, stats) == "");
    CHECK(contents(stats_file).find("Ann") != std::string::npos);

    CHECK(contents(precious) == precious_text);
    for (const std::string& path : {save, table_file, token_file}) {
        INFO(path);
        CHECK(is_link_to(path + ".tmp", precious)); // left alone, never opened
    }
    // The statistics' writer, under its lock, removes what killed writers left: the link goes,
    // its target stays.
    CHECK_FALSE(fs::is_symlink(stats_file + ".tmp"));
}

TEST_CASE("a temporary name already taken, by a link or a file, is passed over, never opened",
          "[file]") {
    TempDir tmp("termpool-files");
    const std::string precious = tmp.write("precious", precious_text);
    const std::string path = tmp.path() + "/game.save";
    // Names a planter could guess: a link to the precious file, a dangling link to where a
    // file would appear, a file of someone else's.
    fs::create_symlink(precious, path + ".tmp.AAAAAA");
    fs::create_symlink(tmp.path() + "/appears", path + ".tmp.BBBBBB");
    tmp.write("game.save.tmp.CCCCCC", "theirs");
    const std::vector<std::string> guesses{"AAAAAA", "BBBBBB", "CCCCCC", "DDDDDD"};
    std::size_t next = 0;
    std::string temporary, error;
    const int fd = create_temporary(path, temporary, error, [&] { return guesses.at(next++); });
    REQUIRE(fd >= 0);
    ::close(fd);
    CHECK(temporary == path + ".tmp.DDDDDD");
    CHECK(next == 4);
    CHECK(error == "");
    CHECK(test::mode_of(temporary) == 0600);
    CHECK(contents(precious) == precious_text);
    CHECK_FALSE(fs::exists(tmp.path() + "/appears"));
    CHECK(contents(path + ".tmp.CCCCCC") == "theirs");

    SECTION("every name taken: refused after a bounded number of tries") {
        int tries = 0;
        CHECK(create_temporary(path, temporary, error, [&] {
                  ++tries;
                  return std::string("AAAAAA");
              }) == -1);
        CHECK(tries == temporary_name_attempts);
        CHECK(error == path + ".tmp.*: " + std::to_string(temporary_name_attempts) +
                           " names tried, each taken by another file");
        CHECK(contents(precious) == precious_text);
    }
    SECTION("the random names differ from one save to the next") {
        std::string first, second;
        const int a = create_temporary(path, first, error);
        const int b = create_temporary(path, second, error);
        CHECK((a >= 0 && b >= 0));
        ::close(a);
        ::close(b);
        CHECK(first != second);
        CHECK(first.size() == path.size() + 11); // .tmp. and six letters or digits
    }
}

TEST_CASE("the temporary files a killed save left are removed, links and all, never followed",
          "[file][hall]") {
    TempDir tmp("termpool-files");
    const std::string precious = tmp.write("precious", precious_text);
    const std::string dir = tmp.path() + "/state";
    REQUIRE(make_directories(dir) == "");
    const std::string table = hall::table_path(dir, 3);
    fs::create_symlink(precious, table + ".tmp");        // the old name
    fs::create_symlink(precious, table + ".tmp.x1Y2z3"); // a new one
    tmp.write("state/table-3.save.tmp.q9Q9q9", "half a save");
    tmp.write("state/table-3.save", "a table");
    tmp.write("state/table-3.save.tmp.toolong", "not a temporary of ours");
    tmp.write("state/table-30.save.tmp.abcdef", "another table's");
    hall::forget_table(dir, 3);
    CHECK(names_in(dir) ==
          std::vector<std::string>{"table-3.save.tmp.toolong", "table-30.save.tmp.abcdef"});
    CHECK(contents(precious) == precious_text);

    // A server starting removes every table's leftovers, and loads no table from them.
    fs::create_symlink(precious, dir + "/table-4.save.tmp.AbCdEf");
    std::vector<std::string> problems;
    CHECK(hall::load_tables(dir, problems).empty());
    CHECK(problems.empty());
    CHECK(names_in(dir) == std::vector<std::string>{"table-3.save.tmp.toolong"});
    CHECK(contents(precious) == precious_text);
}

TEST_CASE("a file over its kind's bound is refused from its size, with its size, at once",
          "[file]") {
    TempDir tmp("termpool-files");
    const auto started = std::chrono::steady_clock::now();

    // 400 MB of save: not read at all.
    const std::string save = tmp.path() + "/game.save";
    make_sparse(save, 400'000'000);
    const SaveContents read = read_save(save);
    CHECK_FALSE(read.text);
    CHECK(read.error == save + ": 400000000 bytes, more than the 4194304 allowed");

    // Every kind has its bound; one byte over it is refused, the bound itself is read.
    for (const std::size_t bound : {max_save_bytes, max_stats_bytes, max_config_bytes,
                                    max_token_bytes, max_scenario_bytes, max_proc_file_bytes}) {
        const std::string file = tmp.path() + "/sized";
        make_sparse(file, static_cast<off_t>(bound));
        std::string error;
        CHECK(read_whole_file(file, error, bound).value_or("").size() == bound);
        make_sparse(file, static_cast<off_t>(bound + 1));
        CHECK_FALSE(read_whole_file(file, error, bound));
        CHECK(error == too_large_message(file, bound + 1, bound));
    }

    // A 300 MB table file: moved aside like any bad one, and reported.
    const std::string dir = tmp.path() + "/hall";
    REQUIRE(make_directories(dir) == "");
    make_sparse(hall::table_path(dir, 1), 300'000'000);
    // A link in the state folder, which only the server writes, is not read through.
    const std::string precious = tmp.write("precious", precious_text);
    fs::create_symlink(precious, hall::table_path(dir, 2));
    std::vector<std::string> problems;
    CHECK(hall::load_tables(dir, problems).empty());
    CHECK(problems ==
          std::vector<std::string>{
              hall::table_path(dir, 1) +
                  ": 300000000 bytes, more than the 4194304 allowed (moved aside as " +
                  hall::table_path(dir, 1) + ".bad)",
              hall::table_path(dir, 2) + ": a symbolic link, not read (moved aside as " +
                  hall::table_path(dir, 2) + ".bad)"});
    CHECK(is_link_to(hall::table_path(dir, 2) + ".bad", precious));
    CHECK(contents(precious) == precious_text);

    // A token file that is a link is not read through either.
    const std::string tokens = tmp.path() + "/tokens";
    REQUIRE(make_directories(tokens) == "");
    tmp.write("token-target", std::string(32, 'b') + "\n");
    fs::create_symlink(tmp.path() + "/token-target", hall::token_path(tokens, "Ann"));
    CHECK(hall::load_token(tokens, "Ann") == "");

    // All of it without reading the hundreds of megabytes.
    CHECK(std::chrono::steady_clock::now() - started < std::chrono::seconds(2));
}

TEST_CASE("a command whose input file is over its bound exits with status 2 and says why",
          "[file][cli]") {
    TempDir tmp("termpool-files");
    const std::string big = tmp.path() + "/big.save";
    make_sparse(big, 400'000'000);
    const auto replay = run_game(tmp, {"replay", big});
    CHECK(replay.first == 2);
    CHECK(replay.second ==
          "termpool: cannot read " + big + ": 400000000 bytes, more than the 4194304 allowed\n");
    const auto resume = run_game(tmp, {"--resume", big});
    CHECK(resume.first == 2);
    CHECK(resume.second ==
          "termpool: " + big + ": 400000000 bytes, more than the 4194304 allowed\n");
    const auto simulate = run_game(tmp, {"simulate", big});
    CHECK(simulate.first == 2);
    CHECK(simulate.second ==
          "termpool: " + big + ": 400000000 bytes, more than the 1048576 allowed\n");

    // Statistics over their bound: damaged, so `termpool stats` says so with status 2 and the
    // next game keeps the file aside and starts new totals.
    REQUIRE(make_directories(tmp.path() + "/state/termpool") == "");
    const std::string stats = tmp.path() + "/state/termpool/stats";
    make_sparse(stats, 2'000'000);
    const std::string too_large = stats + ": 2000000 bytes, more than the 1048576 allowed";
    const auto listed = run_game(tmp, {"stats"});
    CHECK(listed.first == 2);
    CHECK(listed.second == too_large +
                               "\ntermpool: the file is left as it is; the next finished game "
                               "moves it aside (.bad) and starts new totals\n");
    const std::string names[2] = {"Ann", "Bob"};
    const PlayerStats figures[2] = {};
    CHECK(save_game_stats(stats, names, GameType::nine_ball, figures) ==
          too_large + "; kept as " + stats + ".bad, new totals started");
    CHECK(fs::file_size(stats + ".bad") == 2'000'000);
    CHECK(contents(stats).find(" Ann\n") != std::string::npos);

    REQUIRE(make_directories(tmp.path() + "/config/termpool") == "");
    const std::string config = tmp.path() + "/config/termpool/config";
    make_sparse(config, 100'000);
    for (const char* command : {"--ascii", "practice"}) {
        INFO(command);
        const auto game = run_game(tmp, {command});
        CHECK(game.first == 2);
        CHECK(game.second ==
              "termpool: " + config + ": 100000 bytes, more than the 65536 allowed\n");
    }
}

TEST_CASE("the largest record the hall keeps fits a save's bound with a margin", "[file]") {
    // 5000 actions (the hall's limit), every one a shot at its longest: numbers of 17
    // significant digits, a raised cue, a call and a push-out; the longest names.
    GameRecord record;
    record.names[0] = std::string(max_player_name_bytes, 'A');
    record.names[1] = std::string(max_player_name_bytes, 'B');
    record.check = RecordCheck{1, 0xffffffffffffffffULL, 0};
    RecordedAction shot;
    shot.strike.speed = 3.1415926535897931;
    shot.strike.angle_deg = -179.12345678901234;
    shot.strike.side = -0.12345678901234567;
    shot.strike.follow = -0.98765432109876543;
    shot.strike.elevation_deg = 12.345678901234567;
    shot.call.call.ball = 15;
    shot.call.call.pocket = 6;
    shot.call.push_out = true;
    record.actions.assign(5000, shot);
    hall::SavedTable table;
    table.number = 999'999;
    table.record = record;
    table.seat_tokens[0] = table.seat_tokens[1] = std::string(64, 'f');
    TempDir tmp("termpool-files");
    REQUIRE(hall::save_table(tmp.path(), table) == "");
    const std::size_t bytes = fs::file_size(hall::table_path(tmp.path(), 999'999));
    INFO("the largest table file: " << bytes << " bytes");
    CHECK(bytes > 500'000);            // the longest shot text is written
    CHECK(bytes * 6 < max_save_bytes); // and the bound is six times that
}

TEST_CASE("whether a folder can take a save: made if missing, nothing left, or why not",
          "[file][hall]") {
    TempDir tmp("termpool-files");
    CHECK(can_write_in(tmp.path()) == "");
    CHECK(names_in(tmp.path()).empty());
    const std::string fresh = tmp.path() + "/state/hall";
    CHECK(can_write_in(fresh) == "");
    CHECK(names_in(fresh).empty());
    CHECK(test::mode_of(fresh) == 0700);

    // A "folder" that is a file: no save can go in it, for root or anyone.
    const std::string file = tmp.write("plain", "x");
    CHECK(can_write_in(file) == file + ": cannot save there: " + std::strerror(ENOTDIR));
    CHECK(can_write_in(file + "/sub") ==
          file + "/sub: cannot create the folder: " + std::strerror(ENOTDIR));

    // A full disk (a file size limit stands in for one, for root too).
    {
        const test::FileSizeLimit full(0);
        CHECK(can_write_in(tmp.path()) ==
              tmp.path() + ": cannot save there: " + std::strerror(EFBIG));
    }
    CHECK(names_in(tmp.path()) == std::vector<std::string>{"plain", "state"});

    // A read-only folder stops everyone but root, whom mode bits do not stop.
    const std::string read_only = tmp.path() + "/read-only";
    REQUIRE(::mkdir(read_only.c_str(), 0500) == 0);
    if (::geteuid() == 0)
        CHECK(can_write_in(read_only) == ""); // root writes there all the same
    else
        CHECK(can_write_in(read_only) ==
              read_only + ": cannot save there: " + std::strerror(EACCES));
    CHECK(names_in(read_only).empty());
    ::chmod(read_only.c_str(), 0700);
}
