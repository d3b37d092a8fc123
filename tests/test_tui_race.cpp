// Race to N in the real binary: the race asked at the end of the name prompt, the score after
// a rack, the next rack (the break alternating), and the match winner; the save holds the
// whole match.
#include <catch2/catch.hpp>
#include <fstream>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <variant>

#include "record_helpers.hpp"
#include "tmux_session.hpp"

using namespace termpool;
using tmux_session::file_text;
using tmux_session::ScratchDir;
using tmux_session::Tmux;

namespace {

// Two pro computers play 9-ball racks of a race to `race_to` until `racks` racks are won; the
// record names two people, as a hot-seat match would save it.
GameRecord race_record(int race_to, int racks, std::uint64_t seed) {
    GameRecord record;
    record.setup.game = GameType::nine_ball;
    record.seed = seed;
    record.names[0] = "Ann";
    record.names[1] = "Bob";
    record.race_to = race_to;
    MatchState score{race_to, BreakRule::alternate, {0, 0}};
    Game game(record.setup.game, make_table(record.setup), record.setup.physics, 1, seed);
    ComputerPlayer players[2] = {ComputerPlayer(Level::pro, seed),
                                 ComputerPlayer(Level::pro, seed + 1)};
    int breaker = 1;
    for (int turn = 0; turn < 600; ++turn) {
        test::play_one_action(game, players, record);
        if (game.winner() == 0)
            continue;
        score.record_rack(game.winner());
        if (score.racks_played() == racks || score.match_winner() != 0)
            break;
        breaker = score.next_breaker(breaker, game.winner());
        const RecordedAction rack = rack_action(record, score.racks_played() + 1, breaker);
        record.actions.push_back(rack);
        game = Game(record.setup.game, make_table(record.setup), record.setup.physics, rack.breaker,
                    rack.seed);
    }
    return record;
}

void write_save(const std::string& dir, const GameRecord& record) {
    std::system(("mkdir -p " + dir + "/termpool").c_str());
    std::ofstream(dir + "/termpool/game.save") << format_record(record);
}

std::string game(const std::string& dir, const std::string& args) {
    return "env XDG_STATE_HOME=" + dir + " TERM=xterm-256color LANG=C.UTF-8 " +
           tmux_session::termpool_binary() + " " + args + "; sleep 60";
}

} // namespace

TEST_CASE("the name prompt ends with the race length", "[tui][e2e][race]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    t.start(game(dir.path, "--seed 4"));
    REQUIRE(t.wait_for_text("Name of player 1"));
    t.keys("-l Ann");
    t.keys("Enter");
    REQUIRE(t.wait_for_text("Name of player 2"));
    t.keys("-l Bob");
    t.keys("Enter");
    REQUIRE(t.wait_for_text("Race to how many racks?"));
    t.keys("-l 123");
    CHECK(t.wait_for_text("Race to how many racks? 12_"));
    t.keys("BSpace BSpace 0 Enter");
    CHECK(t.wait_for_text("a race is 1 to 99 racks"));
    t.keys("BSpace 3 Enter");
    REQUIRE(t.wait_for_text("Ann breaks: place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.keys("q");
    t.keys("y");
    // The save holds the race.
    const std::string save = dir.path + "/termpool/game.save";
    REQUIRE(t.wait_for(
        [&](const std::string&) { return file_text(save).find("\nplace ") != std::string::npos; }));
    CHECK(file_text(save).find("\nrace 3\nbreaks alternate\n") != std::string::npos);
}

TEST_CASE("a race: the score after a rack, the next rack, the match winner", "[tui][e2e][race]") {
    ScratchDir dir("termpool-test");
    const std::string save = dir.path + "/termpool/game.save";
    // Rack 1 won, the race to 2 goes on.
    const GameRecord one_rack = race_record(2, 1, 11);
    write_save(dir.path, one_rack);
    auto replayed = Match::replay(one_rack);
    REQUIRE(std::holds_alternative<Match>(replayed));
    const int first_winner = std::get<Match>(replayed).game().winner();
    REQUIRE(first_winner != 0);
    {
        Tmux t;
        t.start(game(dir.path, "--resume"));
        const std::string score =
            first_winner == 1 ? "Race to 2: Ann 1, Bob 0" : "Race to 2: Ann 0, Bob 1";
        REQUIRE(t.wait_for_text(score));
        // Alternate breaks: Ann broke rack 1, so Bob breaks rack 2.
        CHECK(t.screen().find("next rack (Bob breaks)") != std::string::npos);
        t.keys("Enter");
        REQUIRE(t.wait_for_text("Rack 2: Bob breaks"));
        t.keys("q");
        t.keys("y");
        REQUIRE(t.wait_for([&](const std::string&) {
            return file_text(save).find("\nrack 2 ") != std::string::npos;
        }));
    }
    // The saved match replays to rack 2 with the score of rack 1.
    auto parsed = parse_record(file_text(save));
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    auto again = Match::replay(std::get<GameRecord>(parsed));
    REQUIRE(std::holds_alternative<Match>(again));
    CHECK(std::get<Match>(again).rack() == 2);
    CHECK(std::get<Match>(again).rack_breaker() == 2);
    CHECK(std::get<Match>(again).score().racks_played() == 1);

    // A match decided: the winner is announced and a rematch offered.
    ScratchDir done("termpool-test");
    const GameRecord whole = race_record(2, 3, 11);
    auto decided = Match::replay(whole);
    REQUIRE(std::holds_alternative<Match>(decided));
    const MatchState& final_score = std::get<Match>(decided).score();
    REQUIRE(final_score.match_winner() != 0);
    write_save(done.path, whole);
    Tmux t;
    // A finished match is never offered to continue: it is opened by its file.
    t.start(game(done.path, "--resume " + done.path + "/termpool/game.save"));
    REQUIRE(t.wait_for_text("wins the match"));
    const std::string winner = final_score.match_winner() == 1 ? "Ann" : "Bob";
    CHECK(t.screen().find(winner + " wins the match") != std::string::npos);
    CHECK(t.screen().find("r  rematch") != std::string::npos);
}

TEST_CASE("two computers in a race go on to the next rack by themselves", "[tui][e2e][race]") {
    ScratchDir dir("termpool-test");
    GameRecord record = race_record(3, 1, 11);
    record.computers[0] = Level::easy;
    record.computers[1] = Level::easy;
    write_save(dir.path, record);
    Tmux t;
    t.start(game(dir.path, "--resume"));
    REQUIRE(t.wait_for_text("Race to 3"));
    CHECK(t.wait_for_text("Rack 2: ", 10));
}

TEST_CASE("termpool replay plays a whole match back, rack by rack", "[tui][e2e][race]") {
    ScratchDir dir("termpool-test");
    const GameRecord match = race_record(2, 3, 11);
    auto replayed = Match::replay(match);
    REQUIRE(std::holds_alternative<Match>(replayed));
    REQUIRE(std::get<Match>(replayed).rack() >= 2);
    const std::string file = dir.path + "/match.save";
    std::ofstream(file) << format_record(match);
    Tmux t;
    t.start(game(dir.path, "replay " + file));
    REQUIRE(t.wait_for_text("Replay, shot 1 of"));
    CHECK(t.screen().find("race to 2") != std::string::npos);
    // The help the panel offers opens in a replay too, and closes again.
    t.keys("?");
    CHECK(t.wait_for_text("Esc closes"));
    t.keys("Escape");
    CHECK(t.wait_gone("Esc closes"));
    // Skip through every shot; the replay goes on into the next racks and ends. Each x waits
    // for the screen it changes (a shot skipped moves the balls).
    const auto over = [](const std::string& s) {
        return s.find("Replay ended") != std::string::npos;
    };
    CHECK(tmux_session::wait_until(
        [&] {
            const std::string before = t.screen();
            if (over(before))
                return true;
            t.keys("x");
            t.wait_changed(before, 2);
            return over(t.screen());
        },
        60));
    // At the end the panel has the final score.
    const MatchState& score = std::get<Match>(replayed).score();
    const std::string s = t.screen();
    CAPTURE(s);
    CHECK(s.find("Ann " + std::to_string(score.racks_won[0])) != std::string::npos);
    CHECK(s.find("Bob " + std::to_string(score.racks_won[1])) != std::string::npos);
}
