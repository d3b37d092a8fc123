// End-to-end tests of `termpool simulate` and `termpool bench`: they run the real binary.

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

/// A directory under $TMPDIR (or /tmp) that is removed with everything in it.
class TempDir {
public:
    TempDir() {
        const char* base = std::getenv("TMPDIR");
        std::string pattern = std::string(base && *base ? base : "/tmp") + "/termpool-cli-XXXXXX";
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    /// Writes `text` to a file named `name` in the directory and returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::string file = path_ + "/" + name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    const std::string& path() const { return path_; }

private:
    std::string path_;
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

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

const char* const simple_shot = "# a cut shot with some follow\n"
                                "table 9ft\n"
                                "ball 0 0.635 0.635\n"
                                "ball 1 1.5 0.66\n"
                                "ball 2 2.0 0.3 mass=0.16\n"
                                "strike 3 0 0 0.2\n";

} // namespace

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
    struct Case {
        const char* text;
        int line;
        const char* says;
    };
    const Case cases[] = {
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

TEST_CASE("simulate refuses unreadable files and extra arguments", "[cli]") {
    TempDir dir;
    const Run missing = run(dir, "simulate " + dir.path() + "/nope.txt");
    CHECK(missing.status == 2);
    CHECK(missing.out.empty());
    CHECK(missing.err.starts_with("termpool: cannot read " + dir.path() + "/nope.txt: "));

    const Run directory = run(dir, "simulate " + dir.path());
    CHECK(directory.status == 2);
    CHECK(directory.err.starts_with("termpool: cannot read "));

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
    const Run r = run(dir, "bench --breaks 3 --shots 10 --seed 5");
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(r.out.find("breaks") != std::string::npos);
    CHECK(r.out.find("shots") != std::string::npos);
    CHECK(r.out.find("one core") != std::string::npos);

    for (const char* bad : {"--breaks", "--breaks 0", "--shots -1", "--seed x", "--fast"}) {
        const Run b = run(dir, std::string("bench ") + bad);
        INFO(bad);
        CHECK(b.status == 2);
        CHECK(b.out.empty());
        CHECK(b.err.find("usage:") != std::string::npos);
    }
}
