// The hall's log: a time on every line, repeated lines rate-limited per client and kind (and
// told of later), a log file capped by renaming it to PATH.1. The clock is the test's.
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "child_process.hpp"
#include "file_helpers.hpp"
#include "hall/hall_log.hpp"
#include "hall/server.hpp"
#include "hall_helpers.hpp"
#include "server_thread.hpp"
#include "temp_dir.hpp"
#include "tmux_session.hpp" // termpool_binary

using namespace termpool;
using namespace termpool::hall;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

using Time = std::chrono::system_clock::time_point;

// 2026-12-03T21:04:05.123Z
const Time start = Time(std::chrono::seconds(1796331845)) + 123ms;

// A log to `out` whose clock is `now`.
HallLogOptions stream_options(std::ostream& out, const Time& now) {
    HallLogOptions options;
    options.stream = &out;
    options.clock = [&now] { return now; };
    return options;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

} // namespace

TEST_CASE("hall log: every line starts with its time in UTC, ISO 8601 to the millisecond",
          "[hall][hall-log]") {
    CHECK(HallLog::timestamp(start) == "2026-12-03T21:04:05.123Z");
    CHECK(HallLog::timestamp(Time{}) == "1970-01-01T00:00:00.000Z");
    std::ostringstream out;
    Time now = start;
    HallLog log(stream_options(out, now));
    log.write("serving on /tmp/x/hall.sock");
    now += 1500ms;
    log.write_repeated(3, "sync", "client 3 resynchronises table 1");
    CHECK(lines(out.str()) ==
          std::vector<std::string>{
              "2026-12-03T21:04:05.123Z termpool hall: serving on /tmp/x/hall.sock",
              "2026-12-03T21:04:06.623Z termpool hall: client 3 resynchronises table 1"});
}

TEST_CASE("hall log: a client's repeated lines of one kind: a burst, then one a minute, and the "
          "next says how many were left out",
          "[hall][hall-log]") {
    std::ostringstream out;
    Time now = start;
    HallLogOptions options = stream_options(out, now);
    options.burst = 3;
    HallLog log(options);
    for (int i = 0; i < 20; ++i)
        log.write_repeated(7, "sync", "client 7 resynchronises table 1");
    CHECK(lines(out.str()).size() == 3);
    CHECK(log.left_out() == 17);
    // Another client, or another kind of line, has a budget of its own.
    log.write_repeated(8, "sync", "client 8 resynchronises table 1");
    log.write_repeated(7, "accept", "client 7 other");
    CHECK(lines(out.str()).size() == 5);

    // Within the minute: still left out.
    now += 59s;
    out.str("");
    log.write_repeated(7, "sync", "client 7 resynchronises table 1");
    CHECK(out.str().empty());
    // A minute on: one more, after the count of those left out.
    now += 1s;
    log.write_repeated(7, "sync", "client 7 resynchronises table 1");
    const std::string ts = HallLog::timestamp(now);
    CHECK(lines(out.str()) ==
          std::vector<std::string>{ts + " termpool hall: client 7: 18 more 'sync' lines left out "
                                        "(the log takes a few at once, then one a minute)",
                                   ts + " termpool hall: client 7 resynchronises table 1"});
    // The budget is spent again at once: one a minute, not a burst.
    out.str("");
    log.write_repeated(7, "sync", "client 7 resynchronises table 1");
    CHECK(out.str().empty());
}

TEST_CASE("hall log: what a client that went quiet had left out is told within a minute",
          "[hall][hall-log]") {
    std::ostringstream out;
    Time now = start;
    HallLogOptions options = stream_options(out, now);
    options.burst = 2;
    HallLog log(options);
    for (int i = 0; i < 5; ++i)
        log.write_repeated(4, "sync", "client 4 resynchronises table 2");
    now += 61s;
    out.str("");
    log.write("table 2 closed");
    const std::string ts = HallLog::timestamp(now);
    CHECK(lines(out.str()) ==
          std::vector<std::string>{ts + " termpool hall: client 4: 3 more 'sync' lines left out "
                                        "(the log takes a few at once, then one a minute)",
                                   ts + " termpool hall: table 2 closed"});
}

TEST_CASE("hall log: a log file past its cap is renamed to PATH.1, one old file kept",
          "[hall][hall-log]") {
    test::TempDir dir("termpool-hall-log");
    const std::string path = dir.path() + "/hall.log";
    Time now = start;
    HallLogOptions options;
    options.path = path;
    options.cap_bytes = 1000;
    options.clock = [&now] { return now; };
    HallLog log(options);
    REQUIRE(log.open() == "");
    CHECK((test::mode_of(path) & 0777) == 0600);
    const std::string line(59, 'x'); // 100 bytes a line with its time and name
    for (int i = 0; i < 9; ++i)
        log.write(line);
    CHECK(fs::file_size(path) == 900);
    CHECK_FALSE(fs::exists(path + ".1"));
    const std::string longer = line + "!"; // 1001 bytes with the others: past the cap
    log.write(longer);
    CHECK(fs::file_size(path + ".1") == 900);
    CHECK(lines(test::contents(path)) ==
          std::vector<std::string>{HallLog::timestamp(now) + " termpool hall: " + longer});
    // Many caps' worth: never more than the file and one old one, each within the cap.
    for (int i = 0; i < 100; ++i)
        log.write(line);
    CHECK(fs::file_size(path) <= 1000);
    CHECK(fs::file_size(path + ".1") <= 1000);
    CHECK_FALSE(fs::exists(path + ".2"));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path()))
        ++files;
    CHECK(files == 2);
}

TEST_CASE("hall log: a log file is appended to, never opened through a link", "[hall][hall-log]") {
    test::TempDir dir("termpool-hall-log");
    const std::string path = dir.path() + "/hall.log";
    const std::string precious = dir.write("precious", "keep me\n");
    REQUIRE(::symlink(precious.c_str(), path.c_str()) == 0);
    HallLogOptions options;
    options.path = path;
    HallLog linked(options);
    CHECK_THAT(linked.open(), Catch::StartsWith(path + ": "));
    linked.write("not here");
    CHECK(test::contents(precious) == "keep me\n");

    fs::remove(path);
    dir.write("hall.log", "an older line\n");
    HallLog appended(options);
    REQUIRE(appended.open() == "");
    appended.write("a newer line");
    const auto got = lines(test::contents(path));
    REQUIRE(got.size() == 2);
    CHECK(got[0] == "an older line");
    CHECK_THAT(got[1], Catch::EndsWith("Z termpool hall: a newer line"));
}

TEST_CASE("hall log: a client's flood of syncs is logged as a burst", "[hall][hall-log]") {
    test::TempDir dir("termpool-hall");
    std::ostringstream out; // written by the server's thread, read once it has stopped
    Time now = start;
    HallLogOptions log_options = stream_options(out, now);
    log_options.burst = 3;
    HallLog log(log_options);
    ServerOptions options;
    options.log = &log;
    {
        test::ServerThread running(dir.path(), options);
        HallClient ann = test::connected(dir.path(), "Ann");
        const int table = test::create_table(ann);
        test::sit(ann, table, 1);
        for (int i = 0; i < 8; ++i) {
            REQUIRE(ann.send(Sync{}));
            test::expect<RecordEnd>(ann);
        }
    }
    std::size_t syncs = 0;
    for (const std::string& line : lines(out.str())) {
        CHECK_THAT(line, Catch::StartsWith("2026-12-03T21:04:05.123Z termpool hall: "));
        syncs += line.find("resynchronises") != std::string::npos;
    }
    CHECK(syncs == 3);
    CHECK(log.left_out() == 5);
}

TEST_CASE("hall log: hall serve --log FILE --log-cap BYTES: timed lines, the file capped",
          "[hall][hall-log][e2e]") {
    test::TempDir dir("termpool-hall");
    const std::string path = dir.path() + "/hall.log";
    test::ChildProcess server({tmux_session::termpool_binary(), std::string("hall"), "serve",
                               "--socket", dir.path() + "/hall.sock", "--state",
                               dir.path() + "/state", "--idle-exit", "1", "--log", path,
                               "--log-cap", "300"},
                              dir.path() + "/stderr.txt");
    const auto status = server.wait_exit(test::kWait);
    INFO(test::contents(path + ".1") << test::contents(path));
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK(test::contents(dir.path() + "/stderr.txt") == "");
    // Serving, restored, idle, two lines of figures, stopped: more than twice 300 bytes.
    CHECK(fs::file_size(path) <= 300);
    CHECK(fs::file_size(path + ".1") <= 300);
    const auto all = lines(test::contents(path + ".1") + test::contents(path));
    CHECK(all.size() >= 3); // the older lines went with an older FILE.1
    for (const std::string& line : all) {
        INFO(line);
        REQUIRE(line.size() > 24);
        CHECK(line[4] == '-');
        CHECK(line[10] == 'T');
        CHECK(line.substr(19, 1) == ".");
        CHECK(line.substr(23, 17) == "Z termpool hall: ");
    }
}
