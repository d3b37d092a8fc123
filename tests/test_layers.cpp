// The layers the project promises, checked on its sources: curses only where the terminal is
// owned (and the byte benchmark that writes frames through curses to a file), no curses and
// no front end in the core.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
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

// The #include lines of `file`.
std::vector<std::string> includes(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> found;
    for (std::string line; std::getline(in, line);)
        if (line.starts_with("#include"))
            found.push_back(line);
    return found;
}

} // namespace

TEST_CASE("curses is included only by the terminal's owner", "[layers]") {
    REQUIRE(fs::exists("src/tui/terminal.cpp")); // run from the repository top
    const std::vector<std::string> allowed = {"src/tui/terminal.cpp", "src/tui/render_figures.cpp"};
    int checked = 0;
    for (const fs::path& file : sources("src")) {
        ++checked;
        const std::string name = file.generic_string();
        const bool may = std::find(allowed.begin(), allowed.end(), name) != allowed.end();
        for (const std::string& line : includes(file)) {
            INFO(name << ": " << line);
            if (!may)
                CHECK(line.find("curses") == std::string::npos);
        }
    }
    CHECK(checked > 50);
}

TEST_CASE("the core includes neither the front ends nor the commands", "[layers]") {
    REQUIRE(fs::exists("src/core"));
    for (const fs::path& file : sources("src/core")) {
        for (const std::string& line : includes(file)) {
            INFO(file.generic_string() << ": " << line);
            CHECK(line.find("tui/") == std::string::npos);
            CHECK(line.find("cli/") == std::string::npos);
            CHECK(line.find("curses") == std::string::npos);
        }
    }
}
