// Game records: a whole game written out, read back and replayed bit for bit; bad records are
// refused at their line.
#include <catch2/catch.hpp>
#include <termpool/computer.hpp>
#include <termpool/record.hpp>

#include "rules_helpers.hpp"

using namespace termpool;

namespace {

// Two computers play a game, and every action goes into a record as the game would save it.
std::pair<GameRecord, Game> played_game(GameType type, std::uint64_t seed) {
    GameRecord record;
    record.game = type;
    record.seed = seed;
    record.names[0] = "Ann Lee";
    record.names[1] = "Bjørn";
    record.computers[1] = Level::medium;
    const PhysicsParams params = record_params(record);
    Game game(type, make_table(record.table), params, record.breaker, record.seed);
    ComputerPlayer players[2] = {ComputerPlayer(Level::easy, seed),
                                 ComputerPlayer(Level::medium, seed + 1)};
    for (int turn = 0; turn < 300 && game.winner() == 0; ++turn) {
        const int actor = game.chooser() != 0 ? game.chooser() : game.shooter();
        ComputerPlayer& player = players[actor - 1];
        RecordedAction action;
        if (game.chooser() != 0) {
            action.kind = RecordedAction::Kind::choose;
            action.choice = player.choose(game);
            game.choose(action.choice);
        } else if (game.ball_in_hand() != BallInHand::none && !game.ready_to_shoot()) {
            action.kind = RecordedAction::Kind::place;
            action.place = player.place_cue_ball(game);
            game.place_cue_ball(action.place);
        } else {
            const ComputerShot shot = player.shot(game);
            action.strike = shot.strike;
            action.call = shot.call;
            game.play(shot.strike, shot.call);
        }
        record.actions.push_back(action);
    }
    return {record, game};
}

std::string error_of(const std::string& text) {
    const auto parsed = parse_record(text);
    if (const RecordError* e = std::get_if<RecordError>(&parsed))
        return std::to_string(e->line) + ": " + e->message;
    const auto replayed = replay_record(std::get<GameRecord>(parsed));
    if (const RecordError* e = std::get_if<RecordError>(&replayed))
        return std::to_string(e->line) + ": " + e->message;
    return "";
}

} // namespace

TEST_CASE("a recorded game replays to the same table, bit for bit", "[record]") {
    for (const GameType type : {GameType::eight_ball, GameType::nine_ball}) {
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
        const auto replayed = replay_record(back);
        REQUIRE(std::holds_alternative<Game>(replayed));
        const Game& again = std::get<Game>(replayed);
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
        CHECK(error_of("termpool-record 1\ngame snooker\nend\n") == "2: unknown game 'snooker'");
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
