// tools/run-tests, which `make test` and `make check` end with: its closing line counts the
// test cases of both runs, the skipped end-to-end ones, and a run that died without a summary
// as a failure; its exit status is the runs'. Driven with a stand-in for the test binary.
#include <catch2/catch.hpp>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>

#include "temp_dir.hpp"
#include "tmux_session.hpp"

using tmux_session::run;
using tmux_session::shell_quote;

namespace {

// A stand-in for the Catch2 binary: it lists 3 end-to-end cases, and for a run prints `unit`
// or `e2e` (by whether its spec, the last argument, starts with ~) and exits with that run's
// status.
std::string stand_in(const termpool::test::TempDir& dir, const std::string& unit, int unit_status,
                     const std::string& e2e, int e2e_status) {
    const std::string path = dir.path() + "/tests";
    run("printf '%s' " +
        shell_quote("#!/bin/sh\n"
                    "for a; do [ \"$a\" = --list-tests ] && "
                    "{ echo '3 matching test cases'; exit 3; }; done\n"
                    "for a; do spec=$a; done\n"
                    "case \"$spec\" in\n"
                    "'~'*) printf '%s\\n' " +
                    shell_quote(unit) + "; exit " + std::to_string(unit_status) +
                    ";;\n"
                    "*) printf '%s\\n' " +
                    shell_quote(e2e) + "; exit " + std::to_string(e2e_status) + ";;\nesac\n") +
        " > " + path + " && chmod +x " + path);
    return path;
}

struct Result {
    int status = -1;
    std::string last_line;
};

Result run_tests(const std::string& binary, const std::string& env = "") {
    const std::string out =
        run(env + " sh tools/run-tests " + binary + " 2>&1; echo \"status $?\"");
    Result r;
    const std::size_t status_at = out.rfind("status ");
    r.status = std::stoi(out.substr(status_at + 7));
    const std::string before = out.substr(0, status_at - 1);
    r.last_line = before.substr(before.rfind('\n') + 1);
    return r;
}

} // namespace

TEST_CASE("run-tests: one closing line for both runs, skipped cases, a run that died",
          "[cli][tests]") {
    termpool::test::TempDir dir("termpool-run-tests");
    const std::string passing = stand_in(dir, "All tests passed (9 assertions in 7 test cases)", 0,
                                         "All tests passed (4 assertions in 3 test cases)", 0);
    Result r = run_tests(passing);
    CHECK(r.last_line == "tests: 10 passed, 0 failed");
    CHECK(r.status == 0);

    r = run_tests(passing, "TERMPOOL_SKIP_E2E=1");
    CHECK(r.last_line == "tests: 7 passed, 0 failed, 3 skipped");
    CHECK(r.status == 0);

    const std::string failing = stand_in(dir, "test cases: 7 | 6 passed | 1 failed", 1,
                                         "All tests passed (4 assertions in 3 test cases)", 0);
    r = run_tests(failing);
    CHECK(r.last_line == "tests: 9 passed, 1 failed");
    CHECK(r.status == 1);

    // The end-to-end run killed before its summary (a sanitizer's abort): one failure.
    const std::string died =
        stand_in(dir, "All tests passed (9 assertions in 7 test cases)", 0, "==1==ERROR", 134);
    r = run_tests(died);
    CHECK(r.last_line == "tests: 7 passed, 1 failed");
    CHECK(r.status == 1);

    // Every test passed, then a leak report at exit changed the status: the run's line says so,
    // and the exit status is a failure.
    const std::string leaked =
        stand_in(dir, "All tests passed (9 assertions in 7 test cases)\n==1==ERROR: leaks", 23,
                 "All tests passed (4 assertions in 3 test cases)", 0);
    const std::string out = run("sh tools/run-tests " + leaked + " 2>&1; echo \"status $?\"");
    CHECK(out.find("run unit: 7 passed, 0 failed") != std::string::npos);
    CHECK(out.find("exit status 23 after its tests") != std::string::npos);
    CHECK(out.find("status 1") != std::string::npos);
}
