// The documents say what the program does: the man page formats cleanly, every transcript in
// the README (a ``` block of `$ ` commands and what they print) is what the program prints
// today, and the version is one (tests/test_install.cpp checks what `make install` installs).
#include <catch2/catch.hpp>
#include <termpool/version.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "tmux_session.hpp"

using tmux_session::run;
using tmux_session::shell_quote;
using tmux_session::termpool_binary;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// One `$ COMMAND` of a README transcript and the lines shown after it.
struct Step {
    int line = 0; // in README.md, 1-based
    std::string command;
    std::vector<std::string> shown;
};

// The transcripts of the README: each fenced block whose first line starts with "$ ".
std::vector<std::vector<Step>> readme_transcripts() {
    const std::vector<std::string> readme = lines_of(tmux_session::file_text("README.md"));
    std::vector<std::vector<Step>> transcripts;
    for (std::size_t i = 0; i < readme.size(); ++i) {
        if (!readme[i].starts_with("```") || i + 1 >= readme.size() ||
            !readme[i + 1].starts_with("$ "))
            continue;
        std::vector<Step> steps;
        for (++i; i < readme.size() && !readme[i].starts_with("```"); ++i) {
            if (readme[i].starts_with("$ "))
                steps.push_back({static_cast<int>(i + 1), readme[i].substr(2), {}});
            else
                steps.back().shown.push_back(readme[i]);
        }
        transcripts.push_back(steps);
    }
    return transcripts;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines)
        text += l + "\n";
    return text;
}

} // namespace

TEST_CASE("the man page formats without a warning", "[docs][e2e]") {
    tmux_session::require_tool("groff", "groff");
    CHECK(run("groff -man -ww -z man/termpool.6 2>&1") == "");
}

// A transcript is played in a fresh folder that is also $HOME: `cat FILE` writes the lines
// shown as FILE (~/ is that home), `termpool ARGS` runs the binary under test and must print
// the lines shown, to the letter.
TEST_CASE("the README's transcripts are what the program prints", "[docs]") {
    const auto transcripts = readme_transcripts();
    REQUIRE(transcripts.size() >= 3);
    for (const std::vector<Step>& steps : transcripts) {
        termpool::test::TempDir home("termpool-readme");
        for (const Step& step : steps) {
            INFO("README.md:" << step.line << ": $ " << step.command);
            if (step.command.starts_with("cat ")) {
                std::string file = step.command.substr(4);
                if (file.starts_with("~/"))
                    file = file.substr(2);
                const std::filesystem::path path = home.path() + "/" + file;
                std::filesystem::create_directories(path.parent_path());
                std::ofstream(path) << joined(step.shown);
            } else if (step.command.starts_with("termpool ")) {
                const std::string printed =
                    run("cd " + shell_quote(home.path()) + " && env -u XDG_STATE_HOME -u " +
                        "XDG_CONFIG_HOME HOME=" + shell_quote(home.path()) + " " +
                        shell_quote(termpool_binary()) + step.command.substr(8) + " 2>&1");
                CHECK(printed == joined(step.shown));
            } else {
                FAIL("a README transcript may only use `cat FILE` and `termpool ...`");
            }
        }
    }
}

TEST_CASE("the man page, --version and the library name one version", "[docs]") {
    std::ifstream in("man/termpool.6");
    std::string line;
    while (std::getline(in, line) && !line.starts_with(".TH "))
        ;
    CHECK(line.find("\"termpool " TERMPOOL_VERSION "\"") != std::string::npos);
    CHECK(run(termpool_binary() + " --version") == "termpool " TERMPOOL_VERSION "\n");
}

TEST_CASE("the umbrella header includes every public header", "[docs]") {
    std::ifstream in("include/termpool/termpool.hpp");
    std::stringstream text;
    text << in.rdbuf();
    for (const auto& entry : std::filesystem::directory_iterator("include/termpool")) {
        const std::string name = entry.path().filename().string();
        if (name != "termpool.hpp")
            CHECK(text.str().find("#include <termpool/" + name + ">") != std::string::npos);
    }
}

TEST_CASE("the API reference is made from the headers without a warning", "[docs][e2e]") {
    tmux_session::require_tool("doxygen", "doxygen");
    termpool::test::TempDir dir("termpool-docs");
    const std::string made =
        run("TERMPOOL_VERSION=" TERMPOOL_VERSION " TERMPOOL_DOCS_DIR=" + shell_quote(dir.path()) +
            " doxygen doc/Doxyfile 2>&1");
    INFO(made);
    std::ifstream warnings(dir.path() + "/warnings.txt");
    std::stringstream text;
    text << warnings.rdbuf();
    CHECK(text.str() == "");
    CHECK(std::filesystem::exists(dir.path() + "/html/index.html"));
    CHECK(std::filesystem::exists(dir.path() + "/html/classtermpool_1_1World.html"));
}
