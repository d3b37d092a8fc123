// What `make install` installs works where it was installed: `make test` first installs into
// $TERMPOOL_STAGE (DESTDIR, PREFIX /usr), and these tests build doc/examples/random_shots.cpp
// against that copy with pkg-config (shared and static), run it, run the Python example with
// the installed module, and check that the two print the same shots to the last digit. Then
// `make uninstall` removes every file again.
#include <catch2/catch.hpp>

#include <termpool/version.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "temp_dir.hpp"
#include "tmux_session.hpp"

using tmux_session::require_tool;
using tmux_session::run;
using tmux_session::run_with_status;
using tmux_session::shell_quote;

namespace {

namespace fs = std::filesystem;

/// The staged install (`make test` sets it); the test fails when it is missing.
std::string stage() {
    const char* dir = std::getenv("TERMPOOL_STAGE");
    INFO("TERMPOOL_STAGE names the tree `make test` installs into; run these tests with make "
         "test");
    REQUIRE(dir != nullptr);
    REQUIRE(fs::is_directory(dir));
    return dir;
}

std::string env(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

/// pkg-config asked about the staged termpool.pc, with the stage as its sysroot: the paths it
/// gives are the installed ones under the stage.
std::string pkg_config(const std::string& args) {
    const std::string root = stage();
    return "PKG_CONFIG_SYSROOT_DIR=" + shell_quote(root) +
           " PKG_CONFIG_LIBDIR=" + shell_quote(root + "/usr/lib/pkgconfig") + " pkg-config " + args;
}

/// The first line of `text`.
std::string first_line(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

} // namespace

TEST_CASE("make install puts the program, the library, its headers, termpool.pc and the Python "
          "module under DESTDIR/PREFIX",
          "[e2e][install]") {
    const fs::path usr = fs::path(stage()) / "usr";
    CHECK(fs::is_regular_file(usr / "bin/termpool"));
    CHECK(fs::is_regular_file(usr / "share/man/man6/termpool.6"));
    CHECK(fs::is_regular_file(usr / "lib/libtermpool.a"));
    CHECK(fs::is_regular_file(usr / ("lib/libtermpool.so." TERMPOOL_VERSION)));
    CHECK(fs::read_symlink(usr / "lib/libtermpool.so") ==
          "libtermpool.so." + std::to_string(TERMPOOL_VERSION_MAJOR) + "." +
              std::to_string(TERMPOOL_VERSION_MINOR));
    CHECK(fs::is_regular_file(usr / "lib/pkgconfig/termpool.pc"));
    // Every public header, and none of the core's own helpers.
    for (const auto& entry : fs::directory_iterator("include/termpool"))
        CHECK(fs::is_regular_file(usr / "include/termpool" / entry.path().filename()));
    CHECK_FALSE(fs::exists(usr / "include/termpool/random.hpp"));
    CHECK_FALSE(fs::exists(usr / "include/termpool/text_lines.hpp"));
    const fs::path site = usr / env("TERMPOOL_PYTHON_SITE");
    bool module = false;
    if (fs::is_directory(site))
        for (const auto& entry : fs::directory_iterator(site))
            module = module || entry.path().filename().string().starts_with("termpool.");
    CHECK(module);

    require_tool("pkg-config", "pkg-config");
    CHECK(run(pkg_config("--modversion termpool")) == TERMPOOL_VERSION "\n");
    // The shared library names its soname, the versioned name a program records.
    require_tool("readelf", "binutils");
    CHECK(run("readelf -d " + shell_quote((usr / "lib/libtermpool.so").string()))
              .find("[libtermpool.so." + std::to_string(TERMPOOL_VERSION_MAJOR) + "." +
                    std::to_string(TERMPOOL_VERSION_MINOR) + "]") != std::string::npos);
}

TEST_CASE("a C++ program and a Python script use the installed library and module, and agree "
          "to the last digit",
          "[e2e][install]") {
    require_tool("pkg-config", "pkg-config");
    require_tool("g++", "g++");
    termpool::test::TempDir dir("termpool-program");
    const std::string root = stage();
    const std::string lib = root + "/usr/lib";
    // A sanitized build's library needs the sanitizers' runtime in the program too.
    const std::string compile =
        "g++ -std=c++20 -O1 " + env("TERMPOOL_SANITIZE_FLAGS") + " doc/examples/random_shots.cpp ";
    const std::string shared = dir.path() + "/shared";
    auto built = run_with_status(compile + "$(" + pkg_config("--cflags --libs termpool") + ") -o " +
                                 shared + " 2>&1");
    INFO(built.second);
    REQUIRE(built.first == 0);
    const auto from_shared =
        run_with_status("LD_LIBRARY_PATH=" + shell_quote(lib) + " " + shared + " 300 2>&1");
    INFO(from_shared.second);
    REQUIRE(from_shared.first == 0);
    CHECK(from_shared.second.starts_with("termpool " TERMPOOL_VERSION ": 300 shots, "));
    // It runs on the installed copy.
    CHECK(run("LD_LIBRARY_PATH=" + shell_quote(lib) + " ldd " + shared)
              .find(lib + "/libtermpool.so") != std::string::npos);

    const std::string fixed = dir.path() + "/static";
    built = run_with_status(compile + "$(" + pkg_config("--cflags termpool") + ") " +
                            shell_quote(lib + "/libtermpool.a") + " -o " + fixed + " 2>&1");
    INFO(built.second);
    REQUIRE(built.first == 0);
    const auto from_static = run_with_status(fixed + " 300 2>&1");
    REQUIRE(from_static.first == 0);
    CHECK(first_line(from_static.second) == first_line(from_shared.second));

    const std::string python = env("TERMPOOL_PYTHON").empty() ? "python3" : env("TERMPOOL_PYTHON");
    require_tool(python, "python3");
    const std::string preload = env("TERMPOOL_PRELOAD").empty()
                                    ? ""
                                    : "LD_PRELOAD=" + shell_quote(env("TERMPOOL_PRELOAD")) +
                                          " ASAN_OPTIONS=detect_leaks=0 ";
    const auto from_python = run_with_status(
        preload + "PYTHONPATH=" + shell_quote(root + "/usr/" + env("TERMPOOL_PYTHON_SITE")) + " " +
        python + " doc/examples/random_shots.py 300 2>&1");
    INFO(from_python.second);
    REQUIRE(from_python.first == 0);
    CHECK(first_line(from_python.second) == first_line(from_shared.second));
    // The batch call across threads gives the same sum.
    const std::string sum =
        first_line(from_shared.second).substr(first_line(from_shared.second).rfind(' ') + 1);
    CHECK(from_python.second.find("simulate_many: ") != std::string::npos);
    CHECK(from_python.second.find("cue ball sum " + sum + "\n",
                                  from_python.second.find("simulate_many")) != std::string::npos);
}

TEST_CASE("make uninstall removes every file make install put there", "[e2e][install]") {
    termpool::test::TempDir dir("termpool-uninstall");
    const std::string copy = dir.path() + "/root";
    REQUIRE(std::system(("cp -a " + shell_quote(stage()) + " " + shell_quote(copy)).c_str()) == 0);
    // make -n lists uninstall's commands for that root; they are run without make, so no make
    // runs inside the tests.
    // (The make running the tests tells its own flags to children; this one starts afresh.)
    const std::string commands =
        run("env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make --no-print-directory -n -s -j1 "
            "uninstall DESTDIR=" +
            shell_quote(copy) + " PREFIX=/usr 2>&1");
    INFO(commands);
    REQUIRE(commands.find("rm ") != std::string::npos);
    REQUIRE(std::system(("set -e\n" + commands).c_str()) == 0);
    std::string left;
    for (const auto& entry : fs::recursive_directory_iterator(copy))
        if (!entry.is_directory())
            left += entry.path().string() + "\n";
    CHECK(left == "");
}
