// The layers the project promises, checked on its sources: curses only where the terminal is
// owned (and the byte benchmark that draws frames through curses into a pty); the core
// includes no front end, no command and none of src/ but its own files; the commands and the
// front end do not include each other and use the core through include/termpool/ only; the
// hall (src/hall) is a layer of its own that uses the core the same way, and neither the core
// nor the commands include it (src/main.cpp dispatches to it); what the player keeps between
// games (src/player) draws nothing; the public headers include
// nothing but each other and the standard library. The build enforces
// part of it (the core is compiled with -Iinclude only); these tests name the file and line.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The source files under `dir` (from the repository top, where the tests run).
std::vector<fs::path> sources(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file() &&
            (entry.path().extension() == ".cpp" || entry.path().extension() == ".hpp"))
            files.push_back(entry.path());
    return files;
}

// One #include line of a source file.
struct Include {
    std::string file;    // the including file, e.g. src/cli/bench.cpp
    std::string line;    // the whole line, for the message
    std::string target;  // what it names, between the quotes or the angle brackets
    bool angled = false; // <target> rather than "target"
};

// The #include lines of the sources under `dir`.
std::vector<Include> includes(const fs::path& dir) {
    static const std::regex directive(R"(^\s*#\s*include\s*([<"])([^>"]*)[>"])");
    std::vector<Include> found;
    for (const fs::path& file : sources(dir)) {
        std::ifstream in(file);
        for (std::string line; std::getline(in, line);)
            if (std::smatch m; std::regex_search(line, m, directive))
                found.push_back({file.generic_string(), line, m[2].str(), m[1].str() == "<"});
    }
    return found;
}

bool contains(const std::string& s, const char* part) {
    return s.find(part) != std::string::npos;
}

// A standard library header: <vector>, <string_view>, no directory and no extension.
bool standard_header(const Include& inc) {
    static const std::regex name("[a-z_]+");
    return inc.angled && std::regex_match(inc.target, name);
}

} // namespace

TEST_CASE("curses is included only by the terminal's owner", "[layers]") {
    REQUIRE(fs::exists("src/tui/terminal.cpp")); // run from the repository top
    const std::vector<std::string> allowed = {"src/tui/terminal.cpp", "src/tui/render_figures.cpp"};
    const std::vector<Include> all = includes("src");
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        if (std::find(allowed.begin(), allowed.end(), inc.file) == allowed.end())
            CHECK_FALSE(contains(inc.target, "curses"));
    }
    CHECK(all.size() > 200);
}

TEST_CASE("the core includes the public headers, the standard library and its own files",
          "[layers]") {
    const std::vector<Include> all = includes("src/core");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "tui/"));
        CHECK_FALSE(contains(inc.target, "cli/"));
        CHECK_FALSE(contains(inc.target, "core/")); // its own headers relative to itself
        CHECK_FALSE(contains(inc.target, "hall/"));
        CHECK_FALSE(contains(inc.target, "files/"));
        CHECK_FALSE(contains(inc.target, "curses"));
        if (!inc.angled && !inc.target.starts_with("../support/"))
            CHECK_FALSE(contains(inc.target, "/")); // nothing outside src/core and src/support
    }
}

TEST_CASE("the core's helpers include the public headers, each other and the standard library",
          "[layers]") {
    // src/support is in the library but not in its installed interface: text lines and
    // numbers, the portable sine and cosine, the random stream, the state digest.
    const std::vector<Include> all = includes("src/support");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        const bool own = !inc.angled && !contains(inc.target, "/");
        const bool public_header = inc.angled && inc.target.starts_with("termpool/");
        CHECK((own || public_header || standard_header(inc)));
    }
    for (const char* helper :
         {"text_lines", "text_numbers", "portable_math", "random", "state_digest"}) {
        INFO(helper);
        CHECK(fs::exists(fs::path("src/support") / (std::string(helper) + ".hpp")));
        CHECK_FALSE(fs::exists(fs::path("include/termpool") / (std::string(helper) + ".hpp")));
    }
}

TEST_CASE("the commands include neither the front end, the hall nor the core's private headers",
          "[layers]") {
    const std::vector<Include> all = includes("src/cli");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "tui/"));
        CHECK_FALSE(contains(inc.target, "hall/"));
        CHECK_FALSE(contains(inc.target, "core/"));
    }
}

TEST_CASE("the front end includes neither the commands nor the core's private headers",
          "[layers]") {
    const std::vector<Include> all = includes("src/tui");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "cli/"));
        CHECK_FALSE(contains(inc.target, "core/"));
    }
}

TEST_CASE("the hall includes the public headers, its own files, the standard library and POSIX",
          "[layers]") {
    const std::vector<Include> all = includes("src/hall");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "tui/"));
        CHECK_FALSE(contains(inc.target, "cli/"));
        CHECK_FALSE(contains(inc.target, "core/"));
        CHECK_FALSE(contains(inc.target, "curses"));
        if (!inc.angled) // "hall/x.hpp", as the other layers name their own files, files/, support/
            CHECK((inc.target.starts_with("hall/") || inc.target.starts_with("files/") ||
                   inc.target.starts_with("support/")));
    }
}

TEST_CASE("the Python module uses the installed interface only: what a researcher's own "
          "program can use",
          "[layers]") {
    const std::vector<Include> all = includes("src/python");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "curses"));
        if (!inc.angled)
            CHECK(inc.target.starts_with("python/"));
        else if (contains(inc.target, "/")) // -Isrc would let <core/...> through
            CHECK((inc.target.starts_with("termpool/") || inc.target.starts_with("pybind11/")));
    }
}

TEST_CASE("the file helpers include only the public headers, each other and the system",
          "[layers]") {
    const std::vector<Include> all = includes("src/files");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "curses"));
        if (!inc.angled)
            CHECK(inc.target.starts_with("files/"));
    }
}

TEST_CASE("what the player keeps between games draws nothing and knows no front end", "[layers]") {
    // Saves, save slots, statistics, config, options and names live in src/player so that any
    // front end (the terminal game, the hall's, a future one) can use them: they include the
    // public headers, each other, the file helpers and the system, never a screen. What prints
    // or asks (termpool stats, termpool saves, the --resume question) is a front end's.
    const std::vector<Include> all = includes("src/player");
    REQUIRE(all.size() > 20);
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        CHECK_FALSE(contains(inc.target, "curses"));
        if (!inc.angled)
            CHECK((inc.target.starts_with("player/") || inc.target.starts_with("files/") ||
                   inc.target.starts_with("support/")));
    }
    for (const char* moved : {"save_file", "save_slots", "stats_file", "stats_summary", "config",
                              "options", "player_name"}) {
        INFO(moved);
        CHECK_FALSE(fs::exists(fs::path("src/tui") / (std::string(moved) + ".cpp")));
        CHECK(fs::exists(fs::path("src/player") / (std::string(moved) + ".cpp")));
    }
}

TEST_CASE("the public headers include only each other and the standard library", "[layers]") {
    const std::vector<Include> all = includes("include/termpool");
    REQUIRE(!all.empty());
    for (const Include& inc : all) {
        INFO(inc.file << ": " << inc.line);
        const bool public_header = inc.angled && inc.target.starts_with("termpool/") &&
                                   !contains(inc.target, "..") &&
                                   fs::exists(fs::path("include") / inc.target);
        CHECK((public_header || standard_header(inc)));
    }
}

TEST_CASE("the App's own files stay under 300 lines", "[layers]") {
    // The table's session holds the loop, the overlays and the dispatch; the modes and the
    // drivers of the table live in files of their own.
    for (const char* path : {"src/tui/app.cpp", "src/tui/app.hpp"}) {
        std::ifstream in(path);
        REQUIRE(in);
        int lines = 0;
        for (std::string line; std::getline(in, line);)
            ++lines;
        CAPTURE(path);
        CHECK(lines < 300);
    }
}

TEST_CASE("the App has one action path: hall, practice and replay live in their drivers",
          "[layers]") {
    // Every input becomes an action for the table's driver (table_driver.hpp); what differs
    // between local play, the hall, a replay and practice is the driver's, not the App's.
    static const std::regex branch(
        R"(\bin_hall\s*\(|\bpractice_\b|\breplaying_\b|\blink_\b|\bhall_\b|\bhall\s*\(\))");
    int app_files = 0;
    for (const fs::path& file : sources("src/tui")) {
        const std::string name = file.filename().string();
        if (!name.starts_with("app"))
            continue;
        ++app_files;
        std::ifstream in(file);
        int number = 0;
        for (std::string line; std::getline(in, line);) {
            ++number;
            INFO(file.generic_string() << ":" << number << ": " << line);
            CHECK_FALSE(std::regex_search(line, branch));
        }
    }
    CHECK(app_files >= 4);
    for (const char* driver :
         {"local_driver.cpp", "hall_driver.cpp", "replay_driver.cpp", "practice_driver.cpp"})
        CHECK(fs::exists(fs::path("src/tui") / driver));
}

TEST_CASE("outside the core no code names a game type but through the registry", "[layers]") {
    // What differs between games is the registry's row (game_registry.hpp) or the referee's
    // (referee.hpp): adding a game is its referee's file and a row, and no front end, command,
    // hall or player file has to learn of it. The public headers define the types.
    static const std::regex named(R"(\bGameType::[a-z]|\bis_rotation_game\b)");
    int files = 0;
    for (const char* dir :
         {"src/tui", "src/cli", "src/hall", "src/player", "src/files", "src/python"}) {
        for (const fs::path& file : sources(dir)) {
            ++files;
            std::ifstream in(file);
            int number = 0;
            for (std::string line; std::getline(in, line);) {
                ++number;
                INFO(file.generic_string() << ":" << number << ": " << line);
                CHECK_FALSE(std::regex_search(line, named));
            }
        }
    }
    CHECK(files > 100);
    std::ifstream main_file("src/main.cpp");
    REQUIRE(main_file);
    for (std::string line; std::getline(main_file, line);)
        CHECK_FALSE(std::regex_search(line, named));
}
