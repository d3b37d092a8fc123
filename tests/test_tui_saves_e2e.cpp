// Saves in the real binary, in tmux: two games at once under one account keep two saves,
// --resume lists and picks them (by number or file), replay without a file shows the save,
// and a config warning is shown in the game.
#include <catch2/catch.hpp>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <termpool/record.hpp>

#include "record_helpers.hpp"
#include "tmux_session.hpp"

using namespace tmux_session;

namespace {} // namespace

TEST_CASE("two games at once keep two saves; --resume lists them and picks one", "[tui][e2e]") {
    const ScratchDir dir("termpool-saves");
    const std::string env = "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path +
                            " TERM=xterm-256color LANG=C.UTF-8 HOME=" + dir.path + " ";
    const std::string first = dir.path + "/termpool/game.save";
    const std::string second = dir.path + "/termpool/game-2.save";
    Tmux t;
    t.start(env + termpool_binary() + " --player1 Ann --player2 Bob; sleep 60");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.start(env + termpool_binary() + " --player1 Cy --player2 Dee; sleep 60", 100, 32, "other");
    // The second game is told where it is saved, then plays there.
    REQUIRE(t.wait_for_text("this one is saved in", 10, "other"));
    CHECK(t.screen("other").find("~/termpool/game-2.save") != std::string::npos);
    t.keys("Enter", "other");
    REQUIRE(t.wait_for_text("[ shoot ]", 10, "other"));
    CHECK(file_text(first).find("player1 Ann") != std::string::npos);
    CHECK(file_text(second).find("player1 Cy") != std::string::npos);

    // While both run, neither save is offered to a third.
    const auto busy = run_termpool(dir, "--resume");
    CHECK(busy.first == 1);
    CHECK(busy.second.find("in use by another termpool game") != std::string::npos);

    // Quitting says where the game is and how to go on with it.
    t.keys("q");
    REQUIRE(t.wait_for_text("Quit"));
    t.keys("y");
    // The binary is not on the PATH here: the way on names it as it was started.
    CHECK(t.wait_for_text("Game saved in ~/termpool/game.save; continue it with: " +
                              termpool_binary() + " --resume 1",
                          10, "e2e", true));
    t.keys("q", "other");
    REQUIRE(t.wait_for_text("Quit", 10, "other"));
    t.keys("y", "other");
    CHECK(t.wait_for_text("continue it with: " + termpool_binary() + " --resume 2", 10, "other",
                          true));

    // Both are listed, with their players; --resume 2 continues Cy's.
    const auto listed = run_termpool(dir, "--resume");
    CHECK(listed.first == 0);
    CHECK(listed.second.find("1  Ann v Bob, 8ball, 9ft, 0 shots, saved ") != std::string::npos);
    CHECK(listed.second.find("2  Cy v Dee, 8ball, 9ft, 0 shots, saved ") != std::string::npos);
    t.kill_session();
    t.start(env + termpool_binary() + " --resume 2; sleep 60");
    CHECK(t.wait_for_text("Game resumed: Cy to play"));
}

TEST_CASE("replay without a file shows the save; --resume FILE; a config warning in the game",
          "[tui][e2e]") {
    const ScratchDir dir("termpool-replay-save");
    std::system(("mkdir -p " + dir.path + "/termpool").c_str());
    std::ofstream(dir.path + "/termpool/game.save")
        << "termpool-record 1\ngame 8ball\ntable 9ft\nseed 3\nbreaker 1\nplayer1 Ann\n"
           "player2 Bob\nshot 12 0 0 0\nshot 2 90 0 0\nend\n";
    std::ofstream(dir.path + "/termpool/config") << "flavour = mint\n";
    const std::string env = "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path +
                            " TERM=xterm-256color LANG=C.UTF-8 ";
    Tmux t;
    t.start(env + termpool_binary() + " replay; sleep 60");
    CHECK(t.wait_for_text("Replay, shot 1 of 2"));
    t.keys("q");
    t.kill_session();

    // --resume FILE continues a save kept anywhere, and saves back to it.
    std::system(("cp " + dir.path + "/termpool/game.save " + dir.path + "/kept.save").c_str());
    t.start(env + termpool_binary() + " --resume " + dir.path + "/kept.save; sleep 60");
    CHECK(t.wait_for_text("Game resumed"));
    t.keys("q");
    REQUIRE(t.wait_for_text("Quit"));
    t.keys("y");
    // The line is longer than the pane: join what tmux wrapped.
    CHECK(t.wait_for_text("continue it with: " + termpool_binary() + " --resume " + dir.path +
                              "/kept.save",
                          10, "e2e", true));
    t.kill_session();

    t.start(env + termpool_binary() + " --player1 Cy --player2 Dee; sleep 60");
    CHECK(t.wait_for_text("unknown key 'flavour'"));
}

namespace {

// A whole 8-ball game between two computers, as the game saves it, under the names Ann and Bob;
// `actions` > 0 stops it after that many actions (unfinished).
std::string saved_game(int actions = 0) {
    termpool::GameRecord record;
    record.seed = 3;
    record.names[0] = "Ann";
    record.names[1] = "Bob";
    termpool::Game game(record.setup.game, termpool::make_table(record.setup), record.setup.physics,
                        1, record.seed);
    termpool::ComputerPlayer players[2] = {termpool::ComputerPlayer(termpool::Level::pro, 1),
                                           termpool::ComputerPlayer(termpool::Level::pro, 2)};
    for (int turn = 0; turn < 300 && game.winner() == 0 && (actions == 0 || turn < actions); ++turn)
        termpool::test::play_one_action(game, players, record);
    return termpool::format_record(record);
}

} // namespace

TEST_CASE("a new game takes a finished save's place, never an unfinished one's", "[tui][e2e]") {
    const ScratchDir dir("termpool-slots");
    const std::string env = "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path +
                            " TERM=xterm-256color LANG=C.UTF-8 HOME=" + dir.path + " ";
    const std::string first = dir.path + "/termpool/game.save";
    std::system(("mkdir -p " + dir.path + "/termpool").c_str());
    const auto play_a_placement = [&](const std::string& expect) {
        Tmux t;
        t.start(env + termpool_binary() + " --player1 Cy --player2 Dee; sleep 60");
        REQUIRE(t.wait_for_text("place the cue ball"));
        CHECK(t.screen().find(expect) != std::string::npos);
        t.keys("Enter");
        REQUIRE(t.wait_for_text("[ shoot ]"));
        t.keys("q");
        t.keys("y");
        REQUIRE(t.wait_for_text("Game saved in"));
    };

    // A finished game: the new one is saved over it, in game.save.
    std::ofstream(first) << saved_game();
    play_a_placement("Cy breaks");
    CHECK(file_text(first).find("player1 Cy") != std::string::npos);

    // An unfinished game: it stays for --resume, and the new game goes to game-2.save.
    const std::string unfinished = saved_game(4);
    std::ofstream(first) << unfinished;
    play_a_placement("An unfinished game is kept for --resume");
    CHECK(file_text(first) == unfinished);
    CHECK(file_text(dir.path + "/termpool/game-2.save").find("player1 Cy") != std::string::npos);

    // A save that is not a game goes aside, never over an older one kept before.
    std::ofstream(first) << "termpool-record 1\ngame snooker\n";
    std::ofstream(first + ".bad") << "kept before\n";
    std::remove((dir.path + "/termpool/game-2.save").c_str());
    play_a_placement("it is kept as");
    CHECK(file_text(first + ".bad") == "kept before\n");
    CHECK(file_text(first + ".bad.1") == "termpool-record 1\ngame snooker\n");
}

TEST_CASE("--resume lists a race with its score", "[tui][e2e][race]") {
    const ScratchDir dir("termpool-race-list");
    std::system(("mkdir -p " + dir.path + "/termpool").c_str());
    // Rack 1 of a race to 2 won (a single game's record with a race line is a race), and an
    // unfinished game beside it.
    termpool::GameRecord race;
    race.seed = 3;
    race.names[0] = "Ann";
    race.names[1] = "Bob";
    race.race_to = 2;
    termpool::Game game(race.setup.game, termpool::make_table(race.setup), race.setup.physics, 1,
                        race.seed);
    termpool::ComputerPlayer players[2] = {termpool::ComputerPlayer(termpool::Level::pro, 1),
                                           termpool::ComputerPlayer(termpool::Level::pro, 2)};
    for (int turn = 0; turn < 300 && game.winner() == 0; ++turn)
        termpool::test::play_one_action(game, players, race);
    REQUIRE(game.winner() != 0);
    std::ofstream(dir.path + "/termpool/game.save") << termpool::format_record(race);
    std::ofstream(dir.path + "/termpool/game-2.save") << saved_game(2);
    const auto listed = run_termpool(dir, "--resume");
    CHECK(listed.first == 0);
    const std::string score = game.winner() == 1 ? "race to 2 at 1-0" : "race to 2 at 0-1";
    CHECK(listed.second.find(score) != std::string::npos);
    CHECK(listed.second.find("won by") == std::string::npos);
}

TEST_CASE("a save that fails stays on the message line until one works", "[tui][e2e]") {
    // The state directory's termpool is a file: no save can be written there (even by root).
    const ScratchDir dir("termpool-nosave");
    std::ofstream(dir.path + "/termpool") << "not a directory\n";
    Tmux t;
    t.start("env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path +
            " TERM=xterm-256color LANG=C.UTF-8 " + termpool_binary() +
            " --player1 Ann --player2 Bob; sleep 60");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    // The placement was saved (or not) before the next message: the failure still shows.
    CHECK(t.wait_for_text("Could not save"));
    CHECK(t.screen().find("Ann: aim") != std::string::npos);
}

TEST_CASE("a game saved after a ball-in-hand placement resumes at the aim with the ball put",
          "[tui][e2e]") {
    const ScratchDir dir("termpool-placed");
    const std::string env = "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path +
                            " TERM=xterm-256color LANG=C.UTF-8 HOME=" + dir.path + " ";
    const std::string save = dir.path + "/termpool/game.save";
    {
        Tmux t;
        t.start(env + termpool_binary() + " --player1 Cy --player2 Dee --seed 4; sleep 60");
        REQUIRE(t.wait_for_text("place the cue ball"));
        t.keys("Up"); // a row up from the head spot: not where a new turn would put it
        t.keys("Enter");
        REQUIRE(t.wait_for_text("[ shoot ]"));
        t.keys("q");
        t.keys("y");
        REQUIRE(t.wait_for_text("Game saved in"));
    }
    const std::string saved = file_text(save);
    REQUIRE(saved.find("\nplace ") != std::string::npos);
    Tmux t;
    t.start(env + termpool_binary() + " --resume; sleep 60");
    REQUIRE(t.wait_for_text("Game resumed: Cy to play"));
    REQUIRE(t.wait_for_text("[ shoot ]")); // the aim, not a second placement
    CHECK(t.screen().find("place the cue ball") == std::string::npos);
    t.keys("q");
    t.keys("y");
    REQUIRE(t.wait_for_text("Game saved in"));
    CHECK(file_text(save) == saved); // nothing placed twice
}
