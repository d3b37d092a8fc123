// The documents say what the program does: the man page formats cleanly, every transcript in
// the README (a ``` block of `$ ` commands and what they print) is what the program prints
// today, and `make install` and `make uninstall` put the files where they say.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "temp_dir.hpp"
#include "tmux_session.hpp"

using tmux_session::run;
using tmux_session::shell_quote;
using tmux_session::termpool_binary;

namespace {

bool exists(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0;
}

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

// The commands `make -n` lists for the targets, run without make: nothing is built (the
// binary under test is installed as it is) and no make runs inside the tests.
TEST_CASE("make install and make uninstall honour DESTDIR and PREFIX", "[docs]") {
    termpool::test::TempDir dir("termpool-install");
    const auto commands = [&](const std::string& target, const std::string& tool) {
        const std::string planned =
            run("make --no-print-directory -n -s " + target + " DESTDIR=" + dir.path() +
                " PREFIX=/usr BIN=" + shell_quote(termpool_binary()) + " 2>&1");
        std::string script;
        for (const std::string& line : lines_of(planned))
            if (line.starts_with(tool + " "))
                script += line + "\n";
        INFO(planned);
        REQUIRE(!script.empty());
        return script;
    };
    const std::string install = commands("install", "install");
    CHECK(std::system(install.c_str()) == 0);
    CHECK(exists(dir.path() + "/usr/bin/termpool"));
    CHECK(exists(dir.path() + "/usr/share/man/man6/termpool.6"));
    CHECK(run(dir.path() + "/usr/bin/termpool --version").starts_with("termpool "));
    const std::string uninstall = commands("uninstall", "rm");
    CHECK(std::system(uninstall.c_str()) == 0);
    CHECK_FALSE(exists(dir.path() + "/usr/bin/termpool"));
    CHECK_FALSE(exists(dir.path() + "/usr/share/man/man6/termpool.6"));
}
