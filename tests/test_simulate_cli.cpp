// End-to-end tests of `termpool simulate` and `termpool bench`: they run the real binary.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "lines_of.hpp"
#include "temp_dir.hpp"

using termpool::test::lines_of;

namespace {

// Scratch directories of this file's own name.
struct TempDir : termpool::test::TempDir {
    TempDir() : termpool::test::TempDir("termpool-cli") {}
};

/// What one run of the binary did.
struct Run {
    int status = -1;
    std::string out;
    std::string err;
};

std::string binary() {
    const char* bin = std::getenv("TERMPOOL_BIN");
    return bin && *bin ? bin : "build/termpool";
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Runs `termpool ARGS` through the shell (so ARGS may redirect stdin), capturing both streams.
/// Paths are made by TempDir and contain no quotes or spaces.
Run run(const TempDir& dir, const std::string& args) {
    const std::string out = dir.path() + "/stdout", err = dir.path() + "/stderr";
    const std::string command = "'" + binary() + "' " + args + " >" + out + " 2>" + err;
    const int raw = std::system(command.c_str());
    Run r;
    r.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

const char* const simple_shot = "# a cut shot with some follow\n"
                                "table 9ft\n"
                                "ball 0 0.635 0.635\n"
                                "ball 1 1.5 0.66\n"
                                "ball 2 2.0 0.3 mass=0.16\n"
                                "strike 3 0 0 0.2\n";

/// The referee's lines: everything after the `rest` line.
std::vector<std::string> referee_lines(const std::string& out) {
    const std::vector<std::string> lines = lines_of(out);
    auto rest = lines.begin();
    while (rest != lines.end() && !rest->starts_with("rest "))
        ++rest;
    REQUIRE(rest != lines.end());
    return {rest + 1, lines.end()};
}

/// Runs a scenario with a game context that must succeed; returns its referee's lines, joined.
std::string verdict_of(const TempDir& dir, const std::string& scenario) {
    const Run r = run(dir, "simulate " + dir.write("game.txt", scenario));
    INFO(scenario << "stderr: " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    std::string joined;
    for (const std::string& line : referee_lines(r.out))
        joined += line + "\n";
    return joined;
}

// Shots on the 9ft table (2.54 x 1.27 m, R = 0.028575 m). Corner pocket 3 is at (2.54, 0); the
// line y = 2.54 - x runs into it at -45 degrees, and a ball centre on it drops once it crosses
// the capture line behind the mouth. Each outcome below was checked by running the scenario.

/// The cue ball drawn back after sending the 1 down y = 2.54 - x into pocket 3 (the README's
/// example); ball 9 sits out of the way so the table has both groups.
const char* const straight_in = "ball 0 1.9 0.64\n"
                                "ball 1 2.3 0.24\n"
                                "ball 9 0.6 0.9\n"
                                "strike 2 -45 0 -0.5\n";

/// The cue ball alone down y = 2.54 - x into pocket 3, touching nothing.
const char* const cue_into_pocket = "ball 0 2.2 0.34\n"
                                    "ball 1 0.6 0.9\n"
                                    "strike 2 -45\n";

/// Runs a break and checks the form of its referee's lines and that they agree with the events
/// and balls printed above them.
void check_break_output(const std::string& scenario) {
    INFO(scenario);
    TempDir dir;
    const Run r = run(dir, "simulate " + dir.write("break.txt", scenario));
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());

    const std::vector<std::string> lines = referee_lines(r.out);
    REQUIRE(lines.size() >= 6);
    std::smatch m;
    REQUIRE(std::regex_match(lines[0], m, std::regex("first-contact (none|[0-9]+)")));
    const std::string first_contact = m[1];
    CHECK(std::regex_match(lines[1], std::regex("foul (none|scratch|cue-off-table|off-table|"
                                                "no-contact|wrong-ball-first|no-rail|bad-break)")));
    CHECK(std::regex_match(lines[2], std::regex("pocketed( [0-9]+)*")));
    CHECK(std::regex_match(lines[3], std::regex("groups (open|1=solids|1=stripes)")));
    CHECK(std::regex_match(lines[4], std::regex("next [12]")));
    CHECK(std::regex_match(lines[5], std::regex("ball-in-hand (none|kitchen|anywhere)")));
    std::size_t i = 6;
    if (i < lines.size() && lines[i].starts_with("choice"))
        CHECK(std::regex_match(lines[i++], std::regex("choice( [a-z-]+)+")));
    if (i < lines.size() && lines[i].starts_with("winner"))
        CHECK(std::regex_match(lines[i++], std::regex("winner [12] [a-z-]+")));
    CHECK(i == lines.size());

    // The referee's lines agree with the events and balls printed above them.
    const std::size_t contact = r.out.find("ball-ball 0 ");
    REQUIRE(contact != std::string::npos);
    const std::string hit = r.out.substr(contact + 12, r.out.find('\n', contact) - contact - 12);
    CHECK(first_contact == hit);
    std::multiset<std::string> dropped, listed;
    for (const std::string& line : lines_of(r.out)) {
        if (std::regex_match(line, m, std::regex("ball ([0-9]+) \\S+ \\S+ pocket [1-6]")))
            dropped.insert(m[1]);
    }
    std::istringstream pocketed(lines[2].substr(8));
    for (std::string id; pocketed >> id;)
        listed.insert(id);
    CHECK(listed == dropped);
}

} // namespace

/// A scenario `simulate` must refuse, the line it must name and what it must say.
struct Case {
    const char* text;
    int line;
    const char* says;
};

/// Runs each bad scenario through the binary: exit 2, nothing on stdout, and the message
/// names the file, the line and the problem.
void check_refused(const std::vector<Case>& cases) {
    TempDir dir;
    int n = 0;
    for (const Case& c : cases) {
        const std::string file = dir.write("bad" + std::to_string(n++) + ".txt", c.text);
        const Run r = run(dir, "simulate " + file);
        INFO(c.text << "\nstderr: " << r.err);
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.starts_with(file + ":" + std::to_string(c.line) + ": "));
        CHECK(r.err.find(c.says) != std::string::npos);
    }
}

TEST_CASE("simulate prints well-formed event, ball and rest lines", "[cli]") {
    TempDir dir;
    const Run r = run(dir, "simulate " + dir.write("shot.txt", simple_shot));
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());

    const std::string number = R"(-?[0-9.]+(e[-+][0-9]+)?)";
    const std::regex event("event " + number +
                           " (ball-ball [0-9]+ [0-9]+|pocket [0-9]+ [1-6]|"
                           "(cushion|jaw|sliding|rolling|spinning|stopped) [0-9]+)");
    const std::regex ball("ball ([0-9]+) " + number + " " + number + " (table|pocket [1-6])");
    const std::regex rest("rest " + number);

    const std::vector<std::string> lines = lines_of(r.out);
    REQUIRE(lines.size() >= 5);
    CHECK(lines.front() == "event 0 sliding 0");
    std::size_t i = 0;
    double last_time = 0;
    for (; i < lines.size() && lines[i].starts_with("event "); ++i) {
        INFO(lines[i]);
        CHECK(std::regex_match(lines[i], event));
        const double t = std::stod(lines[i].substr(6));
        CHECK(t >= last_time);
        last_time = t;
    }
    CHECK(i > 2);
    std::vector<std::string> ids;
    for (; i < lines.size() && lines[i].starts_with("ball "); ++i) {
        INFO(lines[i]);
        std::smatch m;
        REQUIRE(std::regex_match(lines[i], m, ball));
        ids.push_back(m[1]);
    }
    CHECK(ids == std::vector<std::string>{"0", "1", "2"});
    REQUIRE(i + 1 == lines.size());
    CHECK(std::regex_match(lines[i], rest));
    CHECK(std::stod(lines[i].substr(5)) == last_time);
    CHECK(r.out.back() == '\n');
}

TEST_CASE("simulate is deterministic", "[cli]") {
    TempDir dir;
    const std::string shot = dir.write("shot.txt", simple_shot);
    const Run first = run(dir, "simulate " + shot);
    const Run second = run(dir, "simulate " + shot);
    REQUIRE(first.status == 0);
    CHECK(first.out == second.out);

    const std::string brk = dir.write("break.txt", "rack 8ball 7\nstrike 12 0\n");
    const Run a = run(dir, "simulate " + brk);
    const Run b = run(dir, "simulate " + brk);
    INFO(a.err);
    REQUIRE(a.status == 0);
    CHECK(a.out == b.out);
    CHECK(a.out.find("ball-ball 0 ") != std::string::npos);
    std::size_t ball_lines = 0;
    for (const std::string& line : lines_of(a.out))
        ball_lines += line.starts_with("ball ");
    CHECK(ball_lines == 16);
}

TEST_CASE("simulate reads standard input without a file or with -", "[cli]") {
    TempDir dir;
    const std::string shot = dir.write("shot.txt", simple_shot);
    const Run from_file = run(dir, "simulate " + shot);
    const Run redirected = run(dir, "simulate <" + shot);
    const Run dash = run(dir, "simulate - <" + shot);
    REQUIRE(from_file.status == 0);
    CHECK(redirected.status == 0);
    CHECK(dash.status == 0);
    CHECK(redirected.out == from_file.out);
    CHECK(dash.out == from_file.out);

    const Run bad = run(dir, "simulate <" + dir.write("bad.txt", "table 9ft\nbogus\n"));
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(bad.err.find("<stdin>:2: ") != std::string::npos);
}

TEST_CASE("simulate without a strike prints the balls as given and rest 0", "[cli]") {
    TempDir dir;
    const Run r =
        run(dir, "simulate " + dir.write("still.txt", "ball 3 1.25 0.5\nball 0 0.5 0.75\n"));
    REQUIRE(r.status == 0);
    CHECK(r.out == "ball 0 0.5 0.75 table\nball 3 1.25 0.5 table\nrest 0\n");
}

TEST_CASE("simulate refuses bad input with FILE:LINE: and nothing on stdout", "[cli]") {
    const std::vector<Case> cases = {
        {"table 9ft\nwobble\n", 2, "unknown directive"},
        {"ball 1 0.5\n", 1, "missing field"},
        {"\ntable 9ft 7ft\n", 2, "extra field"},
        {"ball 1 x 0.5\n", 1, "not a number"},
        {"ball 1 nan 0.5\n", 1, "not finite"},
        {"ball 0 1 1\n# comment\nstrike 21 0\n", 3, "outside 0..20"},
        {"ball 0 1 1\nstrike 1 0 0.7 0\n", 2, "outside -0.5..0.5"},
        {"ball 16 1 1\n", 1, "outside 0..15"},
        {"rack 8ball\nball 4 0.3 0.3\n", 2, "duplicate ball 4"},
        {"ball 1 0.01 0.5\n", 1, "off the table"},
        {"ball 1 1 0.5\nball 2 1.03 0.5\n", 2, "overlaps"},
        {"ball 1 1 1\n\nstrike 1 0\n", 3, "strike without a cue ball"},
        {"ball 0 1 1\nstrike 1 0\nstrike 1 0\n", 3, "more than one"},
        {"param e_b 2\n", 1, "between 0 and 1"},
        {"friction combined 1 0\n", 1, "must be > 0"},
        {"ball 1 1 1 mass=0\n", 1, "mass must be > 0"},
    };
    check_refused(cases);
}

TEST_CASE("simulate turns any finite strike angle by its exact remainder modulo 360", "[cli]") {
    // Issue 28: 1e20 degrees went along +x, but 1e20 = 360 k + 280 exactly.
    TempDir dir;
    const auto output = [&](const std::string& angle) {
        const Run r = run(dir, "simulate " + dir.write("angle.txt", "ball 0 1.27 0.635\n"
                                                                    "ball 1 2.2 0.3\n"
                                                                    "strike 0.3 " +
                                                                        angle + " 0.2 0\n"));
        INFO(angle << ": " << r.err);
        REQUIRE(r.status == 0);
        return r.out;
    };
    CHECK(output("1e20") == output("280"));
    CHECK(output("-1e20") == output("-280"));
    CHECK(output("-280") == output("80"));
    CHECK(output("1e20") != output("0"));
    // 360 k + 37.25 for k = 2^42, a double exactly.
    CHECK(output("1583296743997477.25") == output("37.25"));
    const std::vector<Case> cases = {
        {"ball 0 1 1\nstrike 0.3 inf\n", 2, "angle 'inf' is not finite"},
        {"ball 0 1 1\n\nstrike 0.3 -inf\n", 3, "angle '-inf' is not finite"},
        {"ball 0 1 1\nstrike 0.3 nan\n", 2, "angle 'nan' is not finite"},
        {"ball 0 1 1\nstrike 0.3 1e400\n", 2, "angle '1e400' is not finite"},
    };
    check_refused(cases);
}

TEST_CASE("simulate reports the stop of a ball a cushion leaves at rest", "[cli]") {
    // Issue 28's shot: on a classic cloth the cushion takes the last of the ball's speed, and
    // the ball's stop is its own event at the same instant.
    TempDir dir;
    const Run r = run(dir, "simulate " + dir.write("stop.txt", "friction constant 0.001\n"
                                                               "ball 0 2.5 0.6\n"
                                                               "strike 0.0072 0\n"));
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out == "event 0 rolling 0\n"
                   "event 1.815763749611285 cushion 0\n"
                   "event 1.815763749611285 stopped 0\n"
                   "ball 0 2.511425 0.6 table\n"
                   "rest 1.815763749611285\n");
}

TEST_CASE("simulate refuses unreadable files and extra arguments", "[cli]") {
    TempDir dir;
    const Run missing = run(dir, "simulate " + dir.path() + "/nope.txt");
    CHECK(missing.status == 2);
    CHECK(missing.out.empty());
    CHECK(missing.err.starts_with("termpool: cannot read " + dir.path() + "/nope.txt: "));

    const Run directory = run(dir, "simulate " + dir.path());
    CHECK(directory.status == 2);
    CHECK(directory.err ==
          "termpool: " + dir.path() + ": cannot read: " + std::strerror(EISDIR) + "\n");

    const std::string shot = dir.write("shot.txt", simple_shot);
    const Run extra = run(dir, "simulate " + shot + " " + shot);
    CHECK(extra.status == 2);
    CHECK(extra.out.empty());
    CHECK(extra.err.find("usage:") != std::string::npos);

    const Run option = run(dir, "simulate --fast " + shot);
    CHECK(option.status == 2);
    CHECK(option.out.empty());
}

TEST_CASE("bench runs small workloads and refuses bad options", "[cli]") {
    TempDir dir;
    const Run r = run(dir, "bench --breaks 3 --shots 10 --seed 5 --ball-runs 2");
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(r.out.find("breaks") != std::string::npos);
    CHECK(r.out.find("shots") != std::string::npos);
    CHECK(r.out.find("one core") != std::string::npos);
    // Each row has this thread's CPU time beside the wall time.
    CHECK(r.out.find("CPU med us") != std::string::npos);
    CHECK(std::regex_search(r.out,
                            std::regex(R"(breaks \(12 m/s\) +3 +[0-9.]+ +[0-9.]+ +[0-9.]+ )")));

    for (const char* bad :
         {"--breaks", "--breaks 0", "--shots -1", "--seed x", "--fast", "--balls 1", "--balls 16,x",
          "--balls 16,,32", "--balls 2000", "--balls", "--ball-runs -1", "--ball-runs 100001"}) {
        const Run b = run(dir, std::string("bench ") + bad);
        INFO(bad);
        CHECK(b.status == 2);
        CHECK(b.out.empty());
        CHECK(b.err.find("usage:") != std::string::npos);
    }
}

TEST_CASE("bench times an event against the number of balls on a scaled table", "[cli]") {
    TempDir dir;
    const Run r = run(dir, "bench --breaks 1 --shots 1 --balls 16,40 --ball-runs 3");
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("cost per event against the number of balls") != std::string::npos);
    // A row per count: events a run, ns an event of wall and CPU time, CPU median a run.
    for (const char* balls : {"16", "40"})
        CHECK(std::regex_search(r.out, std::regex(std::string("\n") + balls +
                                                  R"( +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+\n)")));
    CHECK(std::regex_search(r.out,
                            std::regex(R"(40 balls: [0-9.]+ times the CPU cost per event of 16)")));
    // The same runs give the same outcomes, whatever the clock says.
    const Run again = run(dir, "bench --breaks 1 --shots 1 --balls 16,40 --ball-runs 3");
    const auto hash_line = [](const std::string& out) {
        const std::size_t at = out.find("hash of these outcomes:");
        return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
    };
    CHECK(!hash_line(r.out).empty());
    CHECK(hash_line(r.out) == hash_line(again.out));
    // The outcomes are pinned, through every box tested (16, 40 and 100 balls) and through the
    // grid (200): a faster search must not move a bit (as tests/test_determinism.cpp).
    const Run pinned = run(dir, "bench --breaks 1 --shots 1 --balls 16,40,100,200 --ball-runs 3");
    CHECK(hash_line(pinned.out) == "hash of these outcomes: ceba3c74c4983fd3");
    // No rows with --ball-runs 0.
    const Run none = run(dir, "bench --breaks 1 --shots 1 --ball-runs 0");
    CHECK(none.status == 0);
    CHECK(none.out.find("cost per event") == std::string::npos);
}

TEST_CASE("simulate judges a break: well-formed referee lines after rest", "[cli]") {
    // Seed 3 pockets nothing, seed 11 pockets two balls (checked by running them).
    const char* const breaks[] = {
        "game 8ball\nrack 8ball 3\nbreak\nstrike 12 0\n",
        "game 8ball\nrack 8ball 11\nbreak\nstrike 12 0\n",
        "game 9ball\nrack 9ball 3\nbreak\nstrike 12 0\n",
    };
    for (const char* const scenario : breaks)
        check_break_output(scenario);
}

TEST_CASE("simulate: a called ball pocketed on an open table takes its group", "[cli]") {
    TempDir dir;
    CHECK(verdict_of(dir, std::string("game 8ball\ncall 1 3\n") + straight_in) ==
          "first-contact 1\nfoul none\npocketed 1\ngroups 1=solids\nnext 1\n"
          "ball-in-hand none\n");
    // Player 2 taking the solids gives player 1 the stripes.
    CHECK(verdict_of(dir, std::string("shooter 2\ncall 1 3\n") + straight_in) ==
          "first-contact 1\nfoul none\npocketed 1\ngroups 1=stripes\nnext 2\n"
          "ball-in-hand none\n");
    // The same ball called in another pocket: nothing is decided and the turn passes.
    CHECK(verdict_of(dir, std::string("game 8ball\ncall 1 4\n") + straight_in) ==
          "first-contact 1\nfoul none\npocketed 1\ngroups open\nnext 2\n"
          "ball-in-hand none\n");
    // A safety passes the turn whatever drops.
    CHECK(verdict_of(dir, std::string("call safety\n") + straight_in).find("next 2\n") !=
          std::string::npos);
}

TEST_CASE("simulate: a scratch outranks no-contact and gives ball in hand", "[cli]") {
    TempDir dir;
    // The cue ball touches no ball either, but the scratch is the foul that counts.
    CHECK(verdict_of(dir, std::string("game 8ball\n") + cue_into_pocket) ==
          "first-contact none\nfoul scratch\npocketed 0\ngroups open\nnext 2\n"
          "ball-in-hand anywhere\n");
    // Bar rules give the ball in hand in the kitchen only.
    CHECK(verdict_of(dir, std::string("game 8ball-bar\nshooter 2\n") + cue_into_pocket) ==
          "first-contact none\nfoul scratch\npocketed 0\ngroups open\nnext 1\n"
          "ball-in-hand kitchen\n");
}

TEST_CASE("simulate: 9-ball, a higher ball hit first is a foul", "[cli]") {
    TempDir dir;
    // Straight along y = 0.635 into the 2; the 1 is off the line.
    CHECK(verdict_of(dir, "game 9ball\nball 0 1.0 0.635\nball 1 0.5 1.0\nball 2 1.5 0.635\n"
                          "strike 2 0\n") ==
          "first-contact 2\nfoul wrong-ball-first\npocketed\ngroups open\nnext 2\n"
          "ball-in-hand anywhere\n");
}

TEST_CASE("simulate: 10-ball, the called ball in another pocket owes the opponent a choice",
          "[cli][ten]") {
    TempDir dir;
    // Straight along y = 0.635 into the 1 and on into the middle of the foot rail, no pocket:
    // the 1 goes nowhere near pocket 3, so it is called there and missed; nothing down.
    CHECK(verdict_of(dir, "game 10ball\nball 0 1.0 0.635\nball 1 1.5 0.635\nball 10 0.5 1.0\n"
                          "call 1 3\nstrike 2 0\n") ==
          "first-contact 1\nfoul none\npocketed\ngroups open\nnext 2\nball-in-hand none\n");
    // The 1 straight into corner pocket 3: called there, the shooter plays on; called in
    // pocket 4, it stays down and the opponent chooses.
    const std::string into_three =
        "game 10ball\nball 0 2.14 0.4\nball 1 2.34 0.2\nball 10 0.5 1.0\nstrike 2 -45\n";
    CHECK(verdict_of(dir, into_three + "call 1 3\n") ==
          "first-contact 1\nfoul none\npocketed 1\ngroups open\nnext 1\nball-in-hand none\n");
    CHECK(verdict_of(dir, into_three + "call 1 4\n") ==
          "first-contact 1\nfoul none\npocketed 1\ngroups open\nnext 2\nball-in-hand none\n"
          "choice shoot pass-back\n");
}

TEST_CASE("simulate: a 9-ball push-out hitting nothing is no foul and owes a choice", "[cli]") {
    TempDir dir;
    // Straight up the table from the 1, which is off the line: no contact, no foul.
    CHECK(verdict_of(dir, "game 9ball\nball 0 0.5 0.6\nball 1 1.5 0.6\nball 9 2.0 0.3\n"
                          "push-out\nstrike 1 90\n") ==
          "first-contact none\nfoul none\npocketed\ngroups open\nnext 2\n"
          "ball-in-hand none\nchoice shoot pass-back\n");
}

TEST_CASE("simulate: a cue ball meeting two balls at once may take the legal one first", "[cli]") {
    TempDir dir;
    // Straight between the 1 and the 9, which touch the line at the same instant.
    const std::string verdict =
        verdict_of(dir, "game 8ball\ngroups 1=stripes\nball 0 1.0 0.635\n"
                        "ball 9 1.5 0.663576\nball 1 1.5 0.606424\nstrike 2 0\n");
    CHECK(verdict.starts_with("first-contact 9\nfoul none\n"));
}

TEST_CASE("simulate: the 8 pocketed before the group is cleared loses", "[cli]") {
    TempDir dir;
    // A clean combination down y = 2.54 - x: cue ball, 1, 8, pocket 3. Player 1 has the
    // solids and the 2 is still on the table.
    CHECK(verdict_of(dir, "game 8ball\ngroups 1=solids\nball 0 1.5 1.04\nball 1 1.9 0.64\n"
                          "ball 8 2.2 0.34\nball 2 0.5 1.0\nstrike 3 -45\n") ==
          "first-contact 1\nfoul none\npocketed 8\ngroups 1=solids\nnext 1\n"
          "ball-in-hand none\nwinner 2 eight-early\n");
}

TEST_CASE("simulate prints the choices owed and the other ways a game ends", "[cli]") {
    TempDir dir;
    // A soft break drives fewer than four balls to a rail: the opponent chooses.
    CHECK(verdict_of(dir, "game 8ball\nrack 8ball\nbreak\nstrike 1 0\n")
              .ends_with("next 2\nball-in-hand none\nchoice play-on re-rack re-break\n"));
    // The 8 on the break (the straight-in shot with the 8 in place of the 1).
    const std::string eight_on_break =
        "break\nball 0 1.9 0.64\nball 8 2.3 0.24\nball 1 0.5 1.0\nstrike 2 -45 0 -0.5\n";
    CHECK(verdict_of(dir, "game 8ball\n" + eight_on_break)
              .ends_with("pocketed 8\ngroups open\nnext 1\nball-in-hand none\n"
                         "choice spot-eight re-break\n"));
    CHECK(verdict_of(dir, "game 8ball-bar\n" + eight_on_break)
              .ends_with("pocketed 8\ngroups open\nnext 1\nball-in-hand none\n"
                         "winner 1 eight-on-break\n"));
    // The 8 called and made by player 2, whose group (stripes) is cleared.
    const std::string eight_shot =
        "game 8ball\nshooter 2\ngroups 1=solids\nball 0 1.9 0.64\nball 8 2.3 0.24\n"
        "ball 1 0.5 1.0\nstrike 2 -45 0 -0.5\n";
    CHECK(verdict_of(dir, eight_shot + "call 8 3\n").ends_with("winner 2 eight-pocketed\n"));
    CHECK(verdict_of(dir, eight_shot + "call 8 4\n").ends_with("winner 1 eight-wrong-pocket\n"));
    // 9-ball: the 9 on a combination off the 1 wins.
    CHECK(verdict_of(dir, "game 9ball\nball 0 1.5 1.04\nball 1 1.9 0.64\nball 9 2.2 0.34\n"
                          "strike 3 -45\n") ==
          "first-contact 1\nfoul none\npocketed 9\ngroups open\nnext 1\n"
          "ball-in-hand none\nwinner 1 nine-pocketed\n");
}

TEST_CASE("simulate refuses game contexts that cannot happen", "[cli]") {
    const std::vector<Case> cases = {
        {"game pool\n", 1, "unknown game 'pool'"},
        {"ball 0 1 1\nbreak\ngroups open\nstrike 1 0\n", 3, "cannot go with 'break'"},
        {"game 9ball\ngroups 1=solids\nball 0 1 1\nstrike 1 0\n", 2, "9-ball has no groups"},
        {"game 9ball\nball 0 1 1\nball 1 2 1\ncall 1 3\nstrike 1 0\n", 4, "not called"},
        {"ball 0 1 1\ncall 1 3\nstrike 1 0\n", 2, "called ball 1 is not on the table"},
        {"call 0 3\n", 1, "cue ball (0) cannot be called"},
        {"call 8 9\n", 1, "called pocket 9 is outside 1..6"},
        {"game 9ball\nbreak\npush-out\nball 0 1 1\nstrike 1 0\n", 3,
         "the push-out is the shot after the break"},
        {"push-out\nball 0 1 1\nstrike 1 0\n", 1, "push-out needs 'game 9ball' or 'game 10ball'"},
        {"game 8ball\npush-out\nball 0 1 1\nstrike 1 0\n", 2,
         "the push-out is a 9-ball and 10-ball rule"},
        {"shooter 3\n", 1, "not 1 or 2"},
        {"rack 8ball\nbreak\n", 2, "without a strike"},
        {"game 8ball\ngame 9ball\n", 2, "more than one 'game' line"},
        // The rotation games' referees know their own balls only, whichever line comes first.
        {"game 10ball\nball 0 1 1\nball 13 2 1\nstrike 1 0\n", 3,
         "the 10ball referee judges balls 0..10 only"},
        {"ball 0 1 1\nball 13 2 1\ngame 10ball\nstrike 1 0\n", 3,
         "the 10ball referee judges balls 0..10 only"},
        {"game 9ball\nball 0 1 1\nball 10 2 1\nstrike 1 0\n", 3,
         "the 9ball referee judges balls 0..9 only"},
    };
    check_refused(cases);
}

TEST_CASE("selfplay plays short games to their end and sums them up", "[cli][selfplay]") {
    TempDir dir;
    for (const char* game : {"8ball", "8ball-bar", "9ball", "10ball", "ten-ball", "snooker"}) {
        const Run r =
            run(dir, std::string("selfplay --games 3 --p1 easy --p2 easy --game ") + game);
        INFO(game << " stderr: " << r.err);
        REQUIRE(r.status == 0);
        const std::vector<std::string> lines = lines_of(r.out);
        int games = 0;
        for (const std::string& line : lines)
            games += line.starts_with("game ") && line.find(" winner ") != std::string::npos;
        CHECK(games == 3);
        CHECK(r.out.find("p1 easy") != std::string::npos);
        CHECK(r.out.find("fouls per game") != std::string::npos);
        // Snooker's summary has the frame score, the highest break and the pots per visit.
        const bool snooker = std::string(game) == "snooker";
        CHECK((r.out.find("highest break") != std::string::npos) == snooker);
        CHECK((r.out.find("pots per visit") != std::string::npos) == snooker);
        CHECK((r.out.find(" centuries ") != std::string::npos) == snooker);
        CHECK((r.out.find("pots as the statistics count them") != std::string::npos) == snooker);
        CHECK(r.out.find(" CPU ") != std::string::npos);
        // The whole run's wall and CPU time (all jobs' threads), side by side.
        CHECK(std::regex_search(r.out, std::regex(R"(\d\.\d s wall, \d+\.\d s CPU\n)")));
    }
    CHECK(run(dir, "selfplay --games 2 --p1 easy").status == 2);
    CHECK(run(dir, "selfplay --games 2 --p1 easy --p2 grandmaster").status == 2);
    // The scripted safe player takes a seat at snooker only, and plays a frame to its end.
    const Run safe = run(dir, "selfplay --games 1 --p1 medium --p2 safe --game snooker --seed 2");
    INFO("stderr: " << safe.err);
    CHECK(safe.status == 0);
    CHECK(safe.out.find("p2 safe") != std::string::npos);
    CHECK(safe.out.find("game 1 winner ") != std::string::npos);
    CHECK(run(dir, "selfplay --games 1 --p1 safe --p2 easy").status == 2);
    // The same seed plays the same games.
    CHECK(run(dir, "selfplay --games 2 --p1 medium --p2 hard --seed 9").out.substr(0, 120) ==
          run(dir, "selfplay --games 2 --p1 medium --p2 hard --seed 9").out.substr(0, 120));
}

TEST_CASE("experiment friction prints its table, charts and CSV", "[cli][experiment]") {
    TempDir dir;
    const Run table = run(dir, "experiment friction");
    REQUIRE(table.status == 0);
    // The physical model's median time to rest lands in the seed report's 6-9 s of a real break.
    const std::size_t at = table.out.find("\nphysical ");
    REQUIRE(at != std::string::npos);
    const double rest = std::stod(table.out.substr(at + 10));
    CHECK(rest > 6.0);
    CHECK(rest < 9.0);
    for (const char* model : {"decay", "constant", "combined"})
        CHECK(table.out.find(std::string("\n") + model + " ") != std::string::npos);
    CHECK(table.out.find("total speed of all balls") != std::string::npos);

    const Run csv = run(dir, "experiment friction --csv");
    REQUIRE(csv.status == 0);
    const std::vector<std::string> lines = lines_of(csv.out);
    REQUIRE(lines.size() > 10);
    CHECK(lines[0] == "model,time_s,total_speed_m_s");
    for (std::size_t i = 1; i < lines.size(); ++i)
        CHECK(std::count(lines[i].begin(), lines[i].end(), ',') == 2);
    CHECK(run(dir, "experiment friction --table 6ft").status == 2);
    CHECK(run(dir, "experiment").status == 2);
}

TEST_CASE("experiment throw prints throw against cut, stun and rolling, and CSV",
          "[cli][experiment]") {
    TempDir dir;
    const Run table = run(dir, "experiment throw");
    REQUIRE(table.status == 0);
    CHECK(table.out.find("ball-ball friction fit") != std::string::npos);
    CHECK(table.out.find("Stun cue ball") != std::string::npos);
    CHECK(table.out.find("Rolling cue ball") != std::string::npos);
    CHECK(table.out.find("stun: throw against cut angle") != std::string::npos);
    const Run constant = run(dir, "experiment throw --model constant");
    REQUIRE(constant.status == 0);
    CHECK(constant.out.find("ball-ball friction constant") != std::string::npos);
    // The old constant 0.05: a stun cut of 45 degrees throws 2.86 degrees at every speed.
    CHECK(constant.out.find("      45       2.86       2.86       2.86       2.86") !=
          std::string::npos);

    const Run csv = run(dir, "experiment throw --csv");
    REQUIRE(csv.status == 0);
    const std::vector<std::string> lines = lines_of(csv.out);
    REQUIRE(lines.size() == 1 + 2 * 4 * 61);
    CHECK(lines[0] == "cue,speed_m_s,cut_deg,throw_deg");
    CHECK(lines[1] == "stun,0.3,0,0");
    for (std::size_t i = 1; i < lines.size(); ++i)
        CHECK(std::count(lines[i].begin(), lines[i].end(), ',') == 3);
    CHECK(lines.back().starts_with("rolling,5,60,0.5"));
    CHECK(run(dir, "experiment throw --model cubic").status == 2);
    CHECK(run(dir, "experiment friction --model fit").status == 2);
}

TEST_CASE("experiment mass prints both studies, as a table and as CSV", "[cli][experiment]") {
    TempDir dir;
    const Run table = run(dir, "experiment mass");
    REQUIRE(table.status == 0);
    CHECK(table.out.find("Cue ball mass") != std::string::npos);
    CHECK(table.out.find("Object ball mass") != std::string::npos);
    const Run csv = run(dir, "experiment mass --csv");
    REQUIRE(csv.status == 0);
    const std::vector<std::string> lines = lines_of(csv.out);
    REQUIRE(lines.size() == 17);
    for (std::size_t i = 1; i < lines.size(); ++i)
        CHECK(std::count(lines[i].begin(), lines[i].end(), ',') == 7);
    // A heavier object ball leaves slower.
    CHECK(lines[9].starts_with("object,0.8,"));
}

TEST_CASE("a save that cannot be read is named, kept as .bad, and never overwritten",
          "[cli][save]") {
    TempDir dir;
    const std::string save = dir.path() + "/termpool/game.save";
    const std::string env = "XDG_STATE_HOME=" + dir.path() + " ";
    const struct {
        const char* text;
        const char* says;
    } bad[] = {
        {"termpool-record 1\ngame 8ball\nshot 2 0", "game.save:3: truncated"},
        {"<html>not a save</html>\n", "game.save:1: not a termpool record"},
        {"termpool-record 7\nend\n", "game.save:1: record version 7 is newer"},
        {"termpool-record 1\nchoose re-rack\nend\n", "game.save:2: 're-rack' is not a choice"},
    };
    for (const auto& b : bad) {
        std::system(("mkdir -p " + dir.path() + "/termpool").c_str());
        {
            std::ofstream out(save);
            out << b.text;
        }
        std::remove((save + ".bad").c_str());
        const std::string out = dir.path() + "/o", err = dir.path() + "/e";
        const int raw =
            std::system((env + "'" + binary() + "' --resume >" + out + " 2>" + err).c_str());
        INFO(b.text);
        CHECK(WEXITSTATUS(raw) == 2);
        CHECK(slurp(err).find(b.says) != std::string::npos);
        CHECK(slurp(save + ".bad") == b.text);
    }
    // Nothing to resume is not bad input.
    std::remove((save + ".bad").c_str());
    std::remove(save.c_str());
    const int raw = std::system((env + "'" + binary() + "' --resume >/dev/null 2>&1").c_str());
    CHECK(WEXITSTATUS(raw) == 1);
}

TEST_CASE("replay refuses a file that is not a game, naming the line", "[cli][save]") {
    TempDir dir;
    const std::string file = dir.write("bad.save", "termpool-record 1\ngame pool\nend\n");
    const Run r = run(dir, "replay " + file);
    CHECK(r.status == 2);
    CHECK(r.err.starts_with(file + ":2: unknown game 'pool'"));
    CHECK(run(dir, "replay one two").status == 2);
    CHECK(run(dir, "replay " + dir.path() + "/missing.save").status == 2);
}

TEST_CASE("a bad config file stops the game with its line", "[cli][config]") {
    TempDir dir;
    std::system(("mkdir -p " + dir.path() + "/termpool").c_str());
    {
        std::ofstream out(dir.path() + "/termpool/config");
        out << "game = 8ball\ntable = huge\n";
    }
    const std::string err = dir.path() + "/e";
    const int raw =
        std::system(("XDG_CONFIG_HOME=" + dir.path() + " XDG_STATE_HOME=" + dir.path() + " '" +
                     binary() + "' --player1 A --player2 B </dev/null >/dev/null 2>" + err)
                        .c_str());
    CHECK(WEXITSTATUS(raw) == 2);
    CHECK(slurp(err).find("termpool/config:2: unknown table 'huge'") != std::string::npos);
}
