// Game records: a whole game written out, read back and replayed bit for bit; bad records are
// refused at their line.
#include <algorithm>
#include <catch2/catch.hpp>
#include <termpool/computer.hpp>
#include <termpool/match.hpp>
#include <termpool/record.hpp>

#include "record_helpers.hpp"
#include "rules_helpers.hpp"

using namespace termpool;

namespace {

GameRecord two_players(GameType type, std::uint64_t seed) {
    GameRecord record;
    record.setup.game = type;
    record.seed = seed;
    record.names[0] = "Ann Lee";
    record.names[1] = "Bjørn";
    record.computers[1] = Level::medium;
    return record;
}

// Two computers play a game, and every action goes into a record as the game would save it.
std::pair<GameRecord, Game> played_game(GameType type, std::uint64_t seed) {
    GameRecord record = two_players(type, seed);
    Game game(type, make_table(record.setup), record.setup.physics, record.breaker, record.seed);
    ComputerPlayer players[2] = {ComputerPlayer(Level::easy, seed),
                                 ComputerPlayer(Level::medium, seed + 1)};
    for (int turn = 0; turn < 300 && game.winner() == 0; ++turn)
        test::play_one_action(game, players, record);
    return {record, game};
}

// A whole match as the game plays one: each rack after the first starts with a rack action.
struct PlayedMatch {
    GameRecord record;
    Game game;                 // the last rack
    MatchState score;          // as counted while playing
    std::vector<int> breakers; // of each rack
};

PlayedMatch played_match(GameType type, std::uint64_t seed, int race_to, BreakRule rule) {
    GameRecord record = two_players(type, seed);
    record.race_to = race_to;
    record.break_rule = rule;
    Game game(type, make_table(record.setup), record.setup.physics, record.breaker, record.seed);
    MatchState score{race_to, rule, {0, 0}};
    std::vector<int> breakers = {record.breaker};
    ComputerPlayer players[2] = {ComputerPlayer(Level::pro, seed),
                                 ComputerPlayer(Level::pro, seed + 1)};
    for (int turn = 0; turn < 600 && score.match_winner() == 0; ++turn) {
        test::play_one_action(game, players, record);
        if (game.winner() == 0)
            continue;
        score.record_rack(game.winner());
        if (score.match_winner() != 0)
            break;
        const int breaker = score.next_breaker(breakers.back(), game.winner());
        const RecordedAction rack =
            rack_action(record, static_cast<int>(breakers.size()) + 1, breaker);
        record.actions.push_back(rack);
        game = Game(type, make_table(record.setup), record.setup.physics, rack.breaker, rack.seed);
        breakers.push_back(breaker);
    }
    return {record, game, score, breakers};
}

std::string error_of(const std::string& text) {
    const auto parsed = parse_record(text);
    if (const RecordError* e = std::get_if<RecordError>(&parsed))
        return std::to_string(e->line) + ": " + e->message;
    const auto replayed = Match::replay(std::get<GameRecord>(parsed));
    if (const RecordError* e = std::get_if<RecordError>(&replayed))
        return std::to_string(e->line) + ": " + e->message;
    return "";
}

} // namespace

TEST_CASE("a recorded game replays to the same table, bit for bit", "[record]") {
    for (const GameType type : {GameType::eight_ball, GameType::nine_ball, GameType::ten_ball}) {
        const auto [record, game] = played_game(type, 7);
        REQUIRE(record.actions.size() > 5);
        const std::string text = format_record(record);
        const auto parsed = parse_record(text);
        REQUIRE(std::holds_alternative<GameRecord>(parsed));
        const GameRecord& back = std::get<GameRecord>(parsed);
        CHECK(back.names[0] == "Ann Lee");
        CHECK(back.names[1] == "Bjørn");
        CHECK(back.computers[1] == Level::medium);
        CHECK(format_record(back) == text);
        const auto replayed = Match::replay(back);
        REQUIRE(std::holds_alternative<Match>(replayed));
        const Game& again = std::get<Match>(replayed).game();
        CHECK(again.balls() == game.balls());
        CHECK(again.winner() == game.winner());
        CHECK(again.shooter() == game.shooter());
    }
}

TEST_CASE("bad records are refused at their line", "[record]") {
    const auto [record, game] = played_game(GameType::eight_ball, 3);
    const std::string good = format_record(record);
    CHECK(error_of(good).empty());

    SECTION("truncated") {
        const std::string cut = good.substr(0, good.size() / 2);
        CHECK(error_of(cut).find("truncated") != std::string::npos);
    }
    SECTION("foreign") {
        CHECK(error_of("hello world\n") == "1: not a termpool record");
        CHECK(error_of("") == "1: empty: not a termpool record");
    }
    SECTION("from a newer version") {
        std::string newer = good;
        newer.replace(0, std::string("termpool-record 1").size(), "termpool-record 9");
        CHECK(error_of(newer).find("1: record version 9 is newer") == 0);
    }
    SECTION("a bad value names its line") {
        CHECK(error_of("termpool-record 1\ngame croquet\nend\n") == "2: unknown game 'croquet'");
        CHECK(error_of("termpool-record 1\nshot 30 0 0 0\nend\n") == "2: shot out of range");
        CHECK(error_of("termpool-record 1\nshot 1 x 0 0\nend\n") == "2: bad shot numbers");
        CHECK(error_of("termpool-record 1\nend\nshot 1 0 0 0\n") == "3: text after 'end'");
    }
    SECTION("edited into an impossible state") {
        // A choice nobody owes, and a cue ball placed on top of the rack.
        CHECK(error_of("termpool-record 1\nchoose re-rack\nend\n") ==
              "2: 're-rack' is not a choice owed now");
        CHECK(error_of("termpool-record 1\nplace 1.905 0.635\nend\n") ==
              "2: the cue ball cannot be placed there now");
    }
}

TEST_CASE("a version-1 save is read and written back byte for byte", "[record]") {
    // A save as this format's first version writes it: no race lines, version 1.
    const std::string v1 = "termpool-record 1\n"
                           "game 9ball\n"
                           "table 8ft\n"
                           "seed 42\n"
                           "breaker 2\n"
                           "player1 Ann Lee\n"
                           "player2 Bob\n"
                           "computer2 hard\n"
                           "friction combined 0.25 0.125\n"
                           "cue-ball-mass 0.17\n"
                           "place 0.5 0.7\n"
                           "shot 5.5 0.25 0.1 -0.2\n"
                           "end\n";
    const auto parsed = parse_record(v1);
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    const GameRecord& record = std::get<GameRecord>(parsed);
    CHECK(record.setup.game == GameType::nine_ball);
    CHECK(record.breaker == 2);
    CHECK(format_record(record) == v1);
    const auto replayed = Match::replay(record);
    REQUIRE(std::holds_alternative<Match>(replayed));
    CHECK(std::get<Match>(replayed).game().breaker() == 2);
}

TEST_CASE("a recorded race replays rack by rack to the same balls and score", "[record][race]") {
    const struct {
        GameType type;
        BreakRule rule;
        std::uint64_t seed;
    } matches[] = {{GameType::nine_ball, BreakRule::alternate, 11},
                   {GameType::eight_ball, BreakRule::winner, 1}};
    for (const auto& m : matches) {
        const PlayedMatch played = played_match(m.type, m.seed, 2, m.rule);
        INFO(game_type_name(m.type) << ", " << break_rule_name(m.rule));
        REQUIRE(played.score.match_winner() != 0);
        REQUIRE(played.breakers.size() >= 2);
        // The seeds are chosen so that the winner rule lets a player break twice running.
        CHECK((std::adjacent_find(played.breakers.begin(), played.breakers.end()) !=
               played.breakers.end()) == (m.rule == BreakRule::winner));
        const std::string text = format_record(played.record);
        CHECK(text.starts_with("termpool-record 2\n"));
        CHECK(text.find(std::string("\nrace 2\nbreaks ") + break_rule_name(m.rule) + "\n") !=
              std::string::npos);
        const auto parsed = parse_record(text);
        REQUIRE(std::holds_alternative<GameRecord>(parsed));
        const GameRecord& back = std::get<GameRecord>(parsed);
        CHECK(back.race_to == 2);
        CHECK(back.break_rule == m.rule);
        CHECK(format_record(back) == text);

        // The listener hears every shot, each in its rack, and each rack has shots.
        std::vector<int> shots_per_rack;
        const auto replayed = Match::replay(back, back.actions.size(), [&](const PlayedShot& shot) {
            CHECK(shot.rack >= static_cast<int>(shots_per_rack.size()));
            shots_per_rack.resize(static_cast<std::size_t>(shot.rack));
            ++shots_per_rack.back();
        });
        REQUIRE(std::holds_alternative<Match>(replayed));
        const Match& again = std::get<Match>(replayed);
        CHECK(shots_per_rack.size() == played.breakers.size());
        CHECK(std::count(shots_per_rack.begin(), shots_per_rack.end(), 0) == 0);
        CHECK(again.rack() == static_cast<int>(played.breakers.size()));
        CHECK(again.rack_breaker() == played.breakers.back());
        CHECK(again.score() == played.score);
        CHECK(again.score().match_winner() == played.score.match_winner());
        CHECK(again.game().balls() == played.game.balls());
        CHECK(again.game().winner() == played.game.winner());
        // Each rack's breaker, replayed up to the action before it and after it.
        std::vector<int> breakers{std::get<Match>(Match::replay(back, 0)).rack_breaker()};
        for (std::size_t i = 0; i < back.actions.size(); ++i)
            if (back.actions[i].kind == RecordedAction::Kind::rack)
                breakers.push_back(std::get<Match>(Match::replay(back, i + 1)).rack_breaker());
        CHECK(breakers == played.breakers);
    }
}

TEST_CASE("a single game is still written as version 1, without race lines", "[record][race]") {
    const auto [record, game] = played_game(GameType::nine_ball, 4);
    const std::string text = format_record(record);
    CHECK(text.starts_with("termpool-record 1\n"));
    CHECK(text.find("race") == std::string::npos);
    CHECK(text.find("breaks") == std::string::npos);
    const auto replayed = Match::replay(record);
    REQUIRE(std::holds_alternative<Match>(replayed));
    const MatchState& score = std::get<Match>(replayed).score();
    CHECK(score.race_to == 1);
    CHECK(score.match_winner() == game.winner());
}

TEST_CASE("bad race records are refused at their line", "[record][race]") {
    const PlayedMatch played = played_match(GameType::nine_ball, 11, 2, BreakRule::alternate);
    const std::string good = format_record(played.record);
    REQUIRE(error_of(good).empty());
    auto line_of = [&](const std::string& text, std::size_t at) {
        return std::to_string(1 + std::count(text.begin(), text.begin() + at, '\n'));
    };

    SECTION("a rack action in the middle of a rack") {
        CHECK(error_of("termpool-record 2\nrace 2\nbreaks alternate\nrack 2 5\nend\n") ==
              "4: a rack starts only when the one before is won");
    }
    SECTION("a breaker other than the rule's") {
        const std::size_t at = good.find("\nrack ") + 1;
        const char breaker = good[at + 5];
        std::string wrong = good;
        wrong[at + 5] = breaker == '1' ? '2' : '1';
        CHECK(error_of(wrong) == line_of(wrong, at) + ": player " + std::string(1, breaker) +
                                     " breaks this rack (the alternate rule)");
    }
    SECTION("a rack after the match is won") {
        std::string more = good;
        const std::size_t at = more.rfind("end\n");
        more.insert(at, "rack 1 77\n");
        CHECK(error_of(more) == line_of(more, at) + ": the match is over: no rack follows");
        // A single game is a race to 1: won with its only rack.
        const auto [record, game] = played_game(GameType::eight_ball, 3);
        REQUIRE(game.winner() != 0);
        GameRecord single = record;
        single.actions.push_back(rack_action(single, 2, 3 - record.breaker));
        const std::string text = format_record(single);
        CHECK(error_of(text) ==
              line_of(text, text.rfind("rack ")) + ": the match is over: no rack follows");
    }
    SECTION("bad race lines") {
        const struct {
            const char* text;
            const char* says;
        } bad[] = {
            {"termpool-record 2\nrace 0\nend\n", "2: race must be a number of racks from 1 to 99"},
            {"termpool-record 2\nrace 100\nend\n",
             "2: race must be a number of racks from 1 to 99"},
            {"termpool-record 2\nrace two\nend\n",
             "2: race must be a number of racks from 1 to 99"},
            {"termpool-record 2\nrace 3 4\nend\n", "2: unknown or malformed line 'race'"},
            {"termpool-record 2\nbreaks loser\nend\n",
             "2: unknown break rule 'loser' (alternate or winner)"},
            {"termpool-record 2\nrace 3\nrack 3 1\nend\n", "3: rack breaker must be 1 or 2"},
            {"termpool-record 2\nrace 3\nrack 1 -4\nend\n", "3: bad rack seed"},
            {"termpool-record 2\nrace 3\nrack 1\nend\n", "3: unknown or malformed line 'rack'"},
            {"termpool-record 1\nrace 3\nend\n", "2: 'race' lines need record version 2"},
            {"termpool-record 1\nrack 1 4\nend\n", "2: 'rack' lines need record version 2"},
        };
        for (const auto& b : bad)
            CHECK(error_of(b.text) == b.says);
    }
}

TEST_CASE("records keep the cue: a 'cue' line and a shot's elevation, in version 3 only",
          "[record][cue]") {
    GameRecord record = two_players(GameType::eight_ball, 5);
    RecordedAction shot;
    shot.kind = RecordedAction::Kind::shot;
    shot.strike = {1.5, 10, 0.25, -0.1, 30};
    record.actions.push_back(shot);
    SECTION("a level cue and the standard shaft write what version 1 did") {
        record.actions[0].strike.elevation_deg = 0;
        const std::string text = format_record(record);
        CHECK(text.starts_with("termpool-record 1\n"));
        CHECK(text.find("\ncue ") == std::string::npos);
        CHECK(text.find("elevation") == std::string::npos);
    }
    SECTION("an elevation makes it version 3, and reads back") {
        const std::string text = format_record(record);
        CHECK(text.starts_with("termpool-record 3\n"));
        CHECK(text.find("\nshot 1.5 10 0.25 -0.1 elevation 30\n") != std::string::npos);
        const auto back = parse_record(text);
        REQUIRE(std::holds_alternative<GameRecord>(back));
        CHECK(std::get<GameRecord>(back).actions[0].strike.elevation_deg == 30);
        CHECK(format_record(std::get<GameRecord>(back)) == text);
    }
    for (const double end_mass : {low_deflection_end_mass, 0.0, 0.0061}) {
        record.actions[0].strike.elevation_deg = 0;
        record.setup.physics.cue_end_mass = end_mass;
        const std::string text = format_record(record);
        INFO(text);
        CHECK(text.starts_with("termpool-record 3\n"));
        const auto back = parse_record(text);
        REQUIRE(std::holds_alternative<GameRecord>(back));
        CHECK(std::get<GameRecord>(back).setup.physics.cue_end_mass == end_mass);
        CHECK(format_record(std::get<GameRecord>(back)) == text);
    }
    CHECK(format_record(record).find("\ncue 0.0061\n") != std::string::npos);
    record.setup.physics.cue_end_mass = low_deflection_end_mass;
    CHECK(format_record(record).find("\ncue low-deflection\n") != std::string::npos);
}

TEST_CASE("a record's cue lines are checked, and need version 3", "[record][cue]") {
    CHECK(error_of("termpool-record 2\ncue none\nend\n") == "2: 'cue' lines need record version 3");
    CHECK(error_of("termpool-record 1\nshot 1 0 0 0 elevation 20\nend\n") ==
          "2: a shot's elevation needs record version 3");
    CHECK(error_of("termpool-record 3\ncue oak\nend\n") ==
          "2: cue must be standard, low-deflection, none or an end mass in kg");
    CHECK(error_of("termpool-record 3\ncue -1\nend\n").find("2: cue must be") == 0);
    CHECK(error_of("termpool-record 3\nshot 1 0 0 0 elevation 81\nend\n") == "2: bad elevation");
    // In range but a jump shot: the match refuses it when the record is replayed.
    CHECK(error_of("termpool-record 3\nshot 3 0 0 0 elevation 60\nend\n").find("2: ") == 0);
    CHECK(error_of("termpool-record 3\ncue low-deflection\nend\n").empty());
}
