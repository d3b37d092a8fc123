// A record names the physics it was made with and the state its actions led to: a replay that
// ends anywhere else is refused, with words that say why.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <termpool/simulator.hpp>
#include <termpool/state_digest.hpp>

#include "match_helpers.hpp"

using namespace termpool;

namespace {

// Two computers play `actions` actions of a 9-ball game through a Match, as the game saves one.
Match played(std::size_t actions) {
    GameRecord header;
    header.setup.game = GameType::nine_ball;
    header.seed = 21;
    header.computers[0] = Level::medium;
    header.computers[1] = Level::hard;
    Match match = test::started(header, 5);
    while (match.record().actions.size() < actions && match.pending().kind != Pending::over)
        REQUIRE(test::play_computer_move(match) == MatchError::none);
    return match;
}

GameRecord read(const std::string& text) {
    auto parsed = parse_record(text);
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    return std::get<GameRecord>(parsed);
}

std::string replay_error(const GameRecord& record) {
    const auto replayed = Match::replay(record);
    if (const RecordError* e = std::get_if<RecordError>(&replayed))
        return std::to_string(e->line) + ": " + e->message;
    return {};
}

std::string parse_error(const std::string& text) {
    const auto parsed = parse_record(text);
    if (const RecordError* e = std::get_if<RecordError>(&parsed))
        return std::to_string(e->line) + ": " + e->message;
    return {};
}

// The text with the first `from` replaced by `to`.
std::string edited(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("a played record names its physics and the state it ends in", "[record][check]") {
    const Match match = played(30);
    const std::string text = format_record(match.record());
    INFO(text);
    CHECK(text.starts_with("termpool-record 4\n"));
    CHECK(text.find("\nphysics " + std::to_string(physics_version) + "\n") != std::string::npos);
    const std::string check = "\ncheck " + digest_hex(match.check_hash()) + "\nend\n";
    CHECK(text.ends_with(check));

    const GameRecord back = read(text);
    REQUIRE(back.check);
    CHECK(back.check->physics_version == physics_version);
    CHECK(back.check->hash == match.check_hash());
    const auto replayed = Match::replay(back);
    REQUIRE(std::holds_alternative<Match>(replayed));
    CHECK(std::get<Match>(replayed).state_hash() == match.state_hash());
    CHECK(format_record(std::get<Match>(replayed).record()) == text);
    // A replay to an earlier action cannot see the end, and is not compared.
    CHECK(std::holds_alternative<Match>(Match::replay(back, 10)));
}

TEST_CASE("a new match has no check until it has an action", "[record][check]") {
    const Match fresh = played(0);
    CHECK_FALSE(fresh.record().check);
    CHECK(format_record(fresh.record()).starts_with("termpool-record 1\n"));
    const Match one = played(1);
    REQUIRE(one.record().check);
    CHECK(one.record().check->hash == one.check_hash());
}

TEST_CASE("a record from another physics version replays when it still matches",
          "[record][check]") {
    const Match match = played(30);
    const std::string text = format_record(match.record());
    const std::string ours = "\nphysics " + std::to_string(physics_version) + "\n";
    const GameRecord older = read(edited(text, ours, "\nphysics 1\n"));
    const auto replayed = Match::replay(older);
    REQUIRE(std::holds_alternative<Match>(replayed));
    // Saved again, it names this build's physics.
    CHECK(format_record(std::get<Match>(replayed).record()) == text);
}

TEST_CASE("a record whose replay ends elsewhere is refused at its check line", "[record][check]") {
    const Match match = played(30);
    const std::string text = format_record(match.record());
    const std::string hash = digest_hex(match.check_hash());
    const int check_line = static_cast<int>(std::count(text.begin(), text.end(), '\n')) - 1;
    // Another hash: what a different simulator, or an edited file, would give.
    std::string other = hash;
    other[15] = other[15] == '0' ? '1' : '0';
    const std::string changed = edited(text, "check " + hash, "check " + other);
    CHECK(replay_error(read(changed)) ==
          std::to_string(check_line) +
              ": the replay does not end in the state the check names: the record was edited or "
              "damaged");
    const std::string ours = "\nphysics " + std::to_string(physics_version) + "\n";
    const std::string foreign = edited(changed, ours, "\nphysics 1\n");
    CHECK(replay_error(read(foreign)) == std::to_string(check_line) +
                                             ": made with physics version 1, which this termpool " +
                                             "(physics version " + std::to_string(physics_version) +
                                             ") replays into a different game");
}

TEST_CASE("a shot that plays differently is caught by the check", "[record][check]") {
    Match match = played(30);
    GameRecord record = match.record();
    // The last shot struck a hair harder: every later state moves.
    for (auto a = record.actions.rbegin(); a != record.actions.rend(); ++a) {
        if (a->kind == RecordedAction::Kind::shot) {
            a->strike.speed = std::nextafter(a->strike.speed, 100.0);
            break;
        }
    }
    const std::string error = replay_error(read(format_record(record)));
    CHECK_FALSE(error.empty());
}

TEST_CASE("physics and check lines are read strictly", "[record][check]") {
    const std::string hash = "0123456789abcdef";
    CHECK(parse_error("termpool-record 3\nphysics 2\nend\n") ==
          "2: 'physics' lines need record version 4");
    CHECK(parse_error("termpool-record 3\ncheck " + hash + "\nend\n") ==
          "2: 'check' lines need record version 4");
    CHECK(parse_error("termpool-record 4\ncheck " + hash + "\nend\n") ==
          "2: a 'check' line needs a 'physics' line");
    CHECK(parse_error("termpool-record 4\nphysics 2\nend\n") ==
          "3: a 'physics' line needs a 'check' line before 'end'");
    CHECK(parse_error("termpool-record 4\nphysics two\ncheck " + hash + "\nend\n") ==
          "2: physics must be a version number");
    CHECK(parse_error("termpool-record 4\nphysics 0\ncheck " + hash + "\nend\n") ==
          "2: physics must be a version number");
    for (const std::string bad :
         {"0123456789ABCDEF", "123", "0123456789abcdefa", "0x23456789abcdef"})
        CHECK(parse_error("termpool-record 4\nphysics 2\ncheck " + bad + "\nend\n") ==
              "3: a check is 16 hexadecimal digits (0-9, a-f)");
    CHECK(parse_error("termpool-record 4\nphysics 2\ncheck " + hash + "\nshot 1 0 0 0\nend\n") ==
          "4: only 'end' may follow the 'check' line");
    CHECK(parse_error("termpool-record 4\nphysics 2\nphysics 2\ncheck " + hash + "\nend\n") ==
          "3: a second 'physics' line");
    CHECK(parse_error("termpool-record 4\nshot 1 0 0 0\nphysics 2\ncheck " + hash + "\nend\n") ==
          "3: the 'physics' line must come before the actions");
    CHECK(parse_error("termpool-record 4\nphysics 2\ncheck " + hash + "\nend\n").empty());
}

TEST_CASE("an edited race does not pass the check", "[record][check]") {
    GameRecord header;
    header.setup.game = GameType::nine_ball;
    header.seed = 4;
    header.race_to = 2;
    header.computers[0] = Level::hard;
    header.computers[1] = Level::hard;
    Match match = test::started(header, 3);
    for (int i = 0; i < 20; ++i)
        REQUIRE(test::play_computer_move(match) == MatchError::none);
    const std::string text = format_record(match.record());
    CHECK(replay_error(read(text)).empty());
    const std::string longer = edited(text, "\nrace 2\n", "\nrace 5\n");
    CHECK(replay_error(read(longer)).find("the record was edited or damaged") != std::string::npos);
    const std::string winner = edited(text, "\nbreaks alternate\n", "\nbreaks winner\n");
    CHECK(replay_error(read(winner)).find("edited or damaged") != std::string::npos);
}
