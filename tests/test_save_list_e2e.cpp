// The saves a player can continue, in the real binary: `--resume` never offers a finished game
// (it stays for replay), the unfinished ones are listed newest first with the same numbers by
// `termpool saves` and `--resume`, `d` in --resume's list and `termpool saves --remove N`
// remove one (never one being played, nothing on a bad N), and the next new game takes the
// freed slot.
#include <catch2/catch.hpp>
#include <cctype>
#include <ctime>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <termpool/match.hpp>
#include <termpool/record.hpp>

#include "tmux_session.hpp"

using namespace tmux_session;

namespace {

// `termpool ARGS` with its state, config and home in `dir`, no terminal: its exit status and
// both streams.
std::pair<int, std::string> run_at_home(const ScratchDir& dir, const std::string& args) {
    return tmux_session::run_termpool(dir, args, "HOME=" + dir.path);
}

// The game in tmux with its state, config and home in `dir`.
std::string game(const ScratchDir& dir, const std::string& args) {
    return "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path + " HOME=" + dir.path +
           " TERM=xterm-256color LANG=C.UTF-8 " + termpool_binary() + " " + args + "; sleep 60";
}

// The path of save `slot` under `dir` as the state folder.
std::string slot_file(const ScratchDir& dir, int slot) {
    return dir.path + "/termpool/" +
           (slot == 1 ? std::string("game.save") : "game-" + std::to_string(slot) + ".save");
}

// Writes a save of `first` v `second` before the break as save `slot`, written `age` seconds
// ago.
void write_unfinished(const ScratchDir& dir, int slot, const std::string& first,
                      const std::string& second, std::time_t age) {
    termpool::GameRecord record;
    record.seed = 3;
    record.names[0] = first;
    record.names[1] = second;
    std::system(("mkdir -p " + dir.path + "/termpool").c_str());
    std::ofstream(slot_file(dir, slot)) << termpool::format_record(record);
    const std::time_t when = std::time(nullptr) - age;
    const timespec times[2] = {{when, 0}, {when, 0}};
    REQUIRE(::utimensat(AT_FDCWD, slot_file(dir, slot).c_str(), times, 0) == 0);
}

// Writes, as save `slot`, a snooker frame that Ann conceded at once to Bob: a game that is over.
void write_finished(const ScratchDir& dir, int slot) {
    termpool::GameRecord header;
    header.setup.game = termpool::GameType::snooker;
    header.setup.table = termpool::TableSize::snooker;
    header.seed = 11;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    auto started = termpool::Match::start(header);
    REQUIRE(std::holds_alternative<termpool::Match>(started));
    auto& match = std::get<termpool::Match>(started);
    REQUIRE(match.concede(1) == termpool::MatchError::none);
    std::system(("mkdir -p " + dir.path + "/termpool").c_str());
    std::ofstream(slot_file(dir, slot)) << termpool::format_record(match.record());
}

bool exists(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0;
}

// The lines of `text` that list a save ("  N  ..."), in order.
std::vector<std::string> listed(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.size() > 5 && line.starts_with("  ") &&
            std::isdigit(static_cast<unsigned char>(line[2])))
            lines.push_back(line);
    return lines;
}

} // namespace

TEST_CASE("--resume never offers a finished game: it stays for termpool replay",
          "[tui][e2e][save]") {
    const ScratchDir dir("termpool-finished");
    write_finished(dir, 1); // the newest, and the lower number
    write_unfinished(dir, 2, "Cy", "Dee", 3600);
    const std::string over = file_text(slot_file(dir, 1));

    // The one game to continue is continued at once: the finished one is not in the way.
    {
        Tmux t;
        t.start(game(dir, "--resume"));
        REQUIRE(t.wait_for_text("Game resumed: Cy to play"));
        t.keys("q");
        REQUIRE(t.wait_for_text("Quit"));
        t.keys("y");
        REQUIRE(t.wait_for_text("Game saved in ~/termpool/game-2.save"));
    }
    const auto saves = run_at_home(dir, "saves");
    CHECK(saves.first == 0);
    CHECK(listed(saves.second).size() == 1);
    CHECK(saves.second.find("  2  Cy v Dee") != std::string::npos);
    CHECK(saves.second.find("Ann") == std::string::npos);

    // With only the finished game left there is nothing to continue, and it is said why.
    std::remove(slot_file(dir, 2).c_str());
    const auto none = run_at_home(dir, "--resume");
    CHECK(none.first == 1);
    CHECK(none.second.find("no saved game to resume") != std::string::npos);
    CHECK(none.second.find("finished games are kept for ") != std::string::npos);
    CHECK(none.second.find(" replay") != std::string::npos);
    const auto by_number = run_at_home(dir, "--resume 1");
    CHECK(by_number.first == 2);
    CHECK(by_number.second.find("save 1 is a finished game, not one to continue; watch it again "
                                "with: ") != std::string::npos);
    CHECK(run_at_home(dir, "saves").second.find("No saved game to continue") != std::string::npos);
    // The finished game is still there, untouched, for replay.
    CHECK(file_text(slot_file(dir, 1)) == over);
}

TEST_CASE("termpool saves and --resume list the unfinished saves newest first, same numbers",
          "[cli][save]") {
    const ScratchDir dir("termpool-newest");
    write_unfinished(dir, 1, "Ann", "Bob", 2 * 86400 + 60);
    write_unfinished(dir, 2, "Cy", "Dee", 5 * 60 + 10);
    write_unfinished(dir, 3, "Eve", "Fay", 3 * 3600 + 60);
    const std::vector<std::string> newest_first = {
        "  2  Cy v Dee, 8ball, 9ft, 0 shots, saved 5 minutes ago",
        "  3  Eve v Fay, 8ball, 9ft, 0 shots, saved 3 hours ago",
        "  1  Ann v Bob, 8ball, 9ft, 0 shots, saved 2 days ago",
    };
    const auto saves = run_at_home(dir, "saves");
    CHECK(saves.first == 0);
    CHECK(saves.second.starts_with("Saved games you can continue, newest first ("));
    CHECK(listed(saves.second) == newest_first);
    // --resume without a terminal prints the same list and leaves the choice to --resume N.
    const auto resume = run_at_home(dir, "--resume");
    CHECK(resume.first == 0);
    CHECK(listed(resume.second) == newest_first);
}

TEST_CASE("d in the --resume list removes the chosen save once the player says yes",
          "[tui][e2e][save]") {
    const ScratchDir dir("termpool-resume-d");
    write_unfinished(dir, 1, "Ann", "Bob", 3000);
    write_unfinished(dir, 2, "Cy", "Dee", 1000);
    write_unfinished(dir, 3, "Eve", "Fay", 2000);
    Tmux t;
    t.start(game(dir, "--resume"));
    REQUIRE(t.wait_for_text("Continue which?"));
    CHECK(t.screen().find("  2  Cy v Dee") < t.screen().find("  3  Eve v Fay"));
    // A no keeps it.
    t.keys("d Enter");
    REQUIRE(t.wait_for_text("Remove which save?"));
    t.keys("3 Enter");
    REQUIRE(t.wait_for_text("Remove save 3 (Eve v Fay, 8ball, 9ft, 0 shots, saved "));
    CHECK(t.screen().find("? y/n") != std::string::npos);
    t.keys("n Enter");
    REQUIRE(t.wait_for_text("Save 3 is kept."));
    CHECK(exists(slot_file(dir, 3)));
    // A yes removes that save, and only that one.
    t.keys("'d 3' Enter");
    REQUIRE(t.wait_for([](const std::string& s) {
        return s.find("Remove save 3") != s.rfind("Remove save 3"); // asked a second time
    }));
    t.keys("y Enter");
    REQUIRE(t.wait_for_text("Removed save 3."));
    CHECK_FALSE(exists(slot_file(dir, 3)));
    CHECK(exists(slot_file(dir, 3) + ".lock")); // the lock stays: another game may hold it
    CHECK(exists(slot_file(dir, 1)));
    CHECK(exists(slot_file(dir, 2)));
    // The list shown again has the other two; one of them is continued.
    const std::string after = t.screen().substr(t.screen().find("Removed save 3."));
    CHECK(after.find("Eve v Fay") == std::string::npos);
    CHECK(after.find("  1  Ann v Bob") != std::string::npos);
    t.keys("1 Enter");
    CHECK(t.wait_for_text("Game resumed: Ann to play"));
    CHECK(listed(run_at_home(dir, "saves").second).size() == 2);
}

TEST_CASE("termpool saves --remove N: never a save being played, nothing on a bad N",
          "[tui][e2e][save]") {
    const ScratchDir dir("termpool-remove");
    write_finished(dir, 1);
    write_unfinished(dir, 2, "Cy", "Dee", 100);
    write_unfinished(dir, 3, "Eve", "Fay", 200);
    std::ofstream(slot_file(dir, 4)) << "not a save\n";
    // The saves in the folder (a listing may add a save's lock file: harmless, and a game
    // makes it anyway).
    const auto folder = [&] { return run("ls -a " + dir.path + "/termpool | grep -v '\\.lock$'"); };
    const std::string before = folder();

    // Not a number of the list: a message, status 2, nothing removed (nor moved aside).
    for (const char* bad : {"0", "9", "x", "-1", "1000", "1", "4"}) {
        INFO("--remove " << bad);
        const auto r = run_at_home(dir, std::string("saves --remove ") + bad);
        CHECK(r.first == 2);
        CHECK(r.second.starts_with("termpool saves: "));
        CHECK(folder() == before);
    }
    CHECK(run_at_home(dir, "saves --remove 1").second.find("save 1 is a finished game") !=
          std::string::npos);
    CHECK(run_at_home(dir, "saves --remove 9").second.find("there is no save 9") !=
          std::string::npos);
    CHECK(run_at_home(dir, "saves --remove").first == 2);
    CHECK(run_at_home(dir, "saves --remove 2 --remove 3").first == 2);
    CHECK(folder() == before);

    // Save 2 being played in another terminal is listed as such and kept.
    Tmux t;
    t.start(game(dir, "--resume 2"));
    REQUIRE(t.wait_for_text("Game resumed: Cy to play"));
    CHECK(run_at_home(dir, "saves").second.find("  2  Cy v Dee, 8ball, 9ft, 0 shots, saved ") !=
          std::string::npos);
    CHECK(run_at_home(dir, "saves").second.find(", being played in another terminal") !=
          std::string::npos);
    const auto busy = run_at_home(dir, "saves --remove 2");
    CHECK(busy.first == 1);
    CHECK(busy.second ==
          "termpool saves: save 2 is being played in another terminal: it is not removed\n");
    CHECK(exists(slot_file(dir, 2)));

    // Save 3 goes.
    const auto removed = run_at_home(dir, "saves --remove 3");
    CHECK(removed.first == 0);
    CHECK(removed.second == "Removed save 3.\n");
    CHECK_FALSE(exists(slot_file(dir, 3)));
    CHECK(exists(slot_file(dir, 1)));
    CHECK(exists(slot_file(dir, 4)));
}

TEST_CASE("a new game after a removal takes the freed slot", "[tui][e2e][save]") {
    const ScratchDir dir("termpool-freed");
    for (const int slot : {1, 2, 3})
        write_unfinished(dir, slot, "Ann", "Bob", 100 * slot);
    REQUIRE(run_at_home(dir, "saves --remove 2").first == 0);
    Tmux t;
    t.start(game(dir, "--player1 Gil --player2 Hal"));
    REQUIRE(t.wait_for_text("place the cue ball"));
    CHECK(t.screen().find("~/termpool/game-2.save") != std::string::npos); // the panel wraps it
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    CHECK(wait_until(
        [&] { return file_text(slot_file(dir, 2)).find("player1 Gil") != std::string::npos; }));
    CHECK_FALSE(exists(slot_file(dir, 4)));
}
