// Every command's --help and -h print its usage on stdout and exit 0; the main usage names
// every option and command; without a terminal the game prints its message and nothing else.
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
#include <sys/wait.h>

#include "tmux_session.hpp"

using namespace tmux_session;

namespace {

struct Output {
    int status = -1;
    std::string out; // stdout, or both streams when asked
};

// Runs `sh -c command` with the saves and the config in `dir`, so that no file of the user's
// is read or written.
Output run_in(const ScratchDir& dir, const std::string& command) {
    const std::string full =
        "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path + " " + command;
    Output o;
    FILE* pipe = popen(full.c_str(), "r");
    if (!pipe)
        return o;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe))
        o.out.append(buffer, n);
    const int raw = pclose(pipe);
    o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return o;
}

} // namespace

TEST_CASE("every command's --help and -h print its usage on stdout and exit 0", "[cli][usage]") {
    const ScratchDir dir("termpool-usage");
    const std::string bin = "'" + termpool_binary() + "'";
    for (const std::string command : {"", "simulate", "bench", "replay", "experiment", "selfplay",
                                      "practice", "stats", "saves", "--ascii", "--player1 Ann"}) {
        for (const std::string help : {"--help", "-h"}) {
            const std::string args = command.empty() ? help : command + " " + help;
            INFO("termpool " << args);
            // stderr goes to a file of its own: it must stay empty.
            const std::string err = dir.path + "/err";
            const Output o = run_in(dir, bin + " " + args + " </dev/null 2>" + err);
            CHECK(o.status == 0);
            CHECK(o.out.starts_with("usage: termpool"));
            CHECK(file_text(err).empty());
        }
    }
}

TEST_CASE("the usage names every option of the game and every command", "[cli][usage]") {
    const ScratchDir dir("termpool-usage");
    const Output o = run_in(dir, "'" + termpool_binary() + "' --help");
    REQUIRE(o.status == 0);
    for (const char* item : {"--player1 NAME",
                             "--player2 NAME",
                             "--game 8ball|8ball-bar|9ball|10ball",
                             "--table 7ft|8ft|9ft",
                             "--race N",
                             "--breaks alternate|winner",
                             "--seed S",
                             "--vs-computer [LEVEL]",
                             "--watch [LEVEL]",
                             "--friction physical | decay K | constant A | combined K A",
                             "--cue-ball-mass KG",
                             "--cue standard|low-deflection|none",
                             "--ascii",
                             "--resume [N | FILE]",
                             "--version",
                             "practice [--game G]",
                             "stats",
                             "saves [--remove N]",
                             "replay [FILE]",
                             "simulate [FILE]",
                             "bench [--breaks N] [--shots N] [--seed S]",
                             "bench --render",
                             "experiment friction",
                             "experiment throw [--model fit|constant]",
                             "selfplay --games N"}) {
        INFO(item);
        CHECK(o.out.find(item) != std::string::npos);
    }
    // The game's own usage (after a bad option) lists the same options.
    const Output bad = run_in(dir, "'" + termpool_binary() + "' --colour 2>&1");
    CHECK(bad.status == 2);
    CHECK(bad.out.find("unknown option '--colour'") != std::string::npos);
    for (const char* item : {"--vs-computer [LEVEL]", "--friction", "--resume [N | FILE]"}) {
        INFO(item);
        CHECK(bad.out.find(item) != std::string::npos);
    }
}

TEST_CASE("without a terminal the game says so and prints nothing else", "[cli][usage]") {
    const ScratchDir dir("termpool-usage");
    const Output o = run_in(dir, "sh -c \"echo | '" + termpool_binary() + "' 2>&1\"");
    CHECK(o.status == 1);
    CHECK(o.out == "termpool: the game needs a terminal (try termpool --help)\n");
    CHECK(o.out.find('\033') == std::string::npos);
}

TEST_CASE("a bad hall --name says why on one line, without the usage", "[cli][usage]") {
    const ScratchDir dir("termpool-usage");
    const Output o = run_in(dir, "sh -c \"'" + termpool_binary() +
                                     "' hall --name \"$(printf 'Eve\\342\\200\\256')\" 2>&1\"");
    CHECK(o.status == 2);
    CHECK(o.out == "termpool hall: --name: a name may not hold U+202E (it changes the direction "
                   "of the text) (termpool hall --help: usage)\n");
}

TEST_CASE("a command the program suggests names it so that it runs where the player is",
          "[cli][usage]") {
    const ScratchDir dir("termpool-self");
    const std::string bin = termpool_binary();
    // Not on the PATH (a build run from its tree): the program's own absolute path.
    const Output away = run_in(dir, "PATH=/usr/bin:/bin '" + bin + "' --resume 0 2>&1");
    CHECK(away.status == 2);
    const std::string real = run("readlink -f '" + bin + "'");
    REQUIRE(!real.empty());
    CHECK(away.out == "termpool: there is no save 0 (" + real.substr(0, real.size() - 1) +
                          " --resume lists them)\n");
    // Found on the PATH as termpool (here through a link to this very file): its name.
    REQUIRE(std::system(("mkdir -p " + dir.path + "/bin && ln -s '" +
                         real.substr(0, real.size() - 1) + "' " + dir.path + "/bin/termpool")
                            .c_str()) == 0);
    const Output home =
        run_in(dir, "PATH=" + dir.path + "/bin:/usr/bin:/bin termpool --resume 0 2>&1");
    CHECK(home.out == "termpool: there is no save 0 (termpool --resume lists them)\n");
    // Another termpool first on the PATH is not this one: the path again.
    REQUIRE(std::system(("mkdir -p " + dir.path + "/other && printf '#!/bin/sh\\n' > " + dir.path +
                         "/other/termpool && chmod +x " + dir.path + "/other/termpool")
                            .c_str()) == 0);
    const Output other =
        run_in(dir, "PATH=" + dir.path + "/other:/usr/bin:/bin '" + bin + "' --resume 0 2>&1");
    CHECK(other.out.find("(" + real.substr(0, real.size() - 1) + " --resume") != std::string::npos);
}
