// A record names the physics it was made with and the state its actions led to: a replay that
// ends anywhere else is refused, with words that say why.
#include "support/state_digest.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <termpool/simulator.hpp>

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
    CHECK(text.starts_with("termpool-record 6\n"));
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
    // Twenty moves of the first rack at most, so that nothing the actions hold depends on who
    // breaks the next: only the check can tell that the rule was edited.
    Match match = test::started(header, 3);
    for (int i = 0; i < 20 && match.rack() == 1 && match.game().winner() == 0; ++i)
        REQUIRE(test::play_computer_move(match) == MatchError::none);
    REQUIRE(match.rack() == 1);
    REQUIRE(match.record().actions.size() >= 4);
    const std::string text = format_record(match.record());
    CHECK(replay_error(read(text)).empty());
    const std::string longer = edited(text, "\nrace 2\n", "\nrace 5\n");
    CHECK(replay_error(read(longer)).find("the record was edited or damaged") != std::string::npos);
    const std::string winner = edited(text, "\nbreaks alternate\n", "\nbreaks winner\n");
    CHECK(replay_error(read(winner)).find("edited or damaged") != std::string::npos);
}

namespace {

// `text` as a record of version 4 or 5 wrote it: that header, and a check of the last state.
std::string as_version(const std::string& text, int version, const Match& match) {
    const std::string header = "termpool-record " + std::to_string(version) + "\n";
    std::string old = edited(text, "termpool-record 6\n", header);
    return edited(old, "\ncheck " + digest_hex(match.check_hash()) + "\n",
                  "\ncheck " + digest_hex(match.final_check_hash()) + "\n");
}

// The byte ranges of the action lines of `text` (each with its newline).
std::vector<std::pair<std::size_t, std::size_t>> action_lines(const std::string& text) {
    std::vector<std::pair<std::size_t, std::size_t>> lines;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = text.find('\n', start) + 1;
        const std::string_view line(text.data() + start, end - start);
        for (const char* key : {"shot ", "place ", "choose ", "rack "})
            if (line.starts_with(key))
                lines.emplace_back(start, end);
        start = end;
    }
    return lines;
}

} // namespace

TEST_CASE("records of versions 4 and 5 are read with their check of the last state",
          "[record][check]") {
    const Match match = played(30);
    const std::string text = format_record(match.record());
    for (const int version : {4, 5}) {
        INFO("version " << version);
        const std::string old = as_version(text, version, match);
        const GameRecord back = read(old);
        REQUIRE(back.check);
        CHECK_FALSE(back.check->running);
        CHECK(back.check->hash == match.final_check_hash());
        CHECK(replay_error(back).empty());
        // Written back as it was read, it keeps its version and its meaning.
        const std::string as_written =
            version == 4 ? old : edited(old, "termpool-record 5\n", "termpool-record 4\n");
        CHECK(format_record(back) == as_written);
        // Replayed and saved again, it is written with the running check.
        const auto replayed = Match::replay(back);
        REQUIRE(std::holds_alternative<Match>(replayed));
        CHECK(format_record(std::get<Match>(replayed).record()) == text);
        // The old check still catches what it caught.
        const std::string hash = digest_hex(match.final_check_hash());
        std::string other = hash;
        other[0] = other[0] == '0' ? '1' : '0';
        CHECK(replay_error(read(edited(old, "check " + hash, "check " + other)))
                  .find("edited or damaged") != std::string::npos);
        // And a version 6 check in an old record is no longer the state's.
        const std::string running =
            edited(old, "check " + hash, "check " + digest_hex(match.check_hash()));
        CHECK(replay_error(read(running)).find("edited or damaged") != std::string::npos);
    }
}

TEST_CASE("the running check differs from the check of the last state", "[record][check]") {
    const Match match = played(10);
    CHECK(match.check_hash() != match.final_check_hash());
    // A cue ball placed again replaces the record's last place, and the check with it: it is
    // the check of a record that placed it there at once.
    GameRecord header = match.record();
    header.actions.clear();
    header.check.reset();
    header.setup.game = GameType::eight_ball;
    header.computers[0] = header.computers[1] = std::nullopt;
    Match twice = test::started(header, 5);
    Match once = test::started(header, 5);
    // A scratch on the break gives ball in hand; a break that pots nothing and fouls is not
    // needed: the breaker of 8-ball places the cue ball in the kitchen first.
    REQUIRE(twice.pending().kind == Pending::place);
    REQUIRE(twice.place(1, {0.5, 0.5}) == MatchError::none);
    REQUIRE(twice.place(1, {0.55, 0.6}) == MatchError::none);
    REQUIRE(once.place(1, {0.55, 0.6}) == MatchError::none);
    CHECK(twice.record().actions.size() == 1);
    CHECK(twice.check_hash() == once.check_hash());
    CHECK(format_record(twice.record()) == format_record(once.record()));
}

TEST_CASE("a version 6 record holds each action and number to its one text", "[record][check]") {
    const Match match = played(30);
    const std::string text = format_record(match.record());
    REQUIRE(text.find("\nseed 21\n") != std::string::npos);
    const auto shot_at = text.find("\nshot ");
    REQUIRE(shot_at != std::string::npos);
    const std::size_t line_start = shot_at + 1;
    const std::string shot_line = text.substr(line_start, text.find('\n', line_start) - line_start);
    const int shot_line_number =
        1 + static_cast<int>(std::count(text.begin(), text.begin() + line_start, '\n'));
    const std::string word = shot_line.substr(5, shot_line.find(' ', 5) - 5); // the speed
    // Other texts of the same values: the same action, but a second spelling of it.
    for (const std::string& other :
         {edited(shot_line, "shot " + word, "shot 0" + word),
          edited(shot_line, "shot " + word, "shot  " + word), shot_line + " ",
          edited(shot_line, "shot " + word, "shot\t" + word)}) {
        INFO(other);
        const std::string changed = edited(text, shot_line, other);
        CHECK(parse_error(changed) == std::to_string(shot_line_number) +
                                          ": a version 6 record writes this action as '" +
                                          shot_line + "'");
        // A record of version 5 is read as it always was.
        CHECK(parse_error(as_version(changed, 5, match)).empty());
    }
    CHECK(parse_error(edited(text, "\nseed 21\n", "\nseed 021\n")) == "4: bad seed");
    CHECK(parse_error(as_version(edited(text, "\nseed 21\n", "\nseed 021\n"), 5, match)).empty());
}

TEST_CASE("every single-bit flip of a record's actions that still reads is caught",
          "[record][check]") {
    // A 9-ball game: its calls are the computer's words only (9-ball calls no pocket), so a
    // flipped pocket leaves the game as it was, and the check of the last state cannot see it.
    const Match match = played(12);
    const std::string text = format_record(match.record());
    const std::uint64_t final_state = match.final_check_hash();
    const auto lines = action_lines(text);
    REQUIRE(lines.size() == 12);
    int flips = 0, read_back = 0, caught = 0, caught_by_old_check = 0;
    const auto began = std::chrono::steady_clock::now();
    for (const auto& [start, end] : lines) {
        for (std::size_t at = start; at < end; ++at) {
            for (int bit = 0; bit < 8; ++bit) {
                std::string flipped = text;
                flipped[at] = static_cast<char>(flipped[at] ^ (1 << bit));
                ++flips;
                auto parsed = parse_record(flipped);
                if (!std::holds_alternative<GameRecord>(parsed))
                    continue;
                ++read_back;
                // The real reader refuses it...
                const GameRecord& record = std::get<GameRecord>(parsed);
                INFO("byte " << at << " bit " << bit << ":\n" << flipped);
                // ...which is to say: its replay, played without the comparison, ends in
                // another running check (or is refused on its own).
                GameRecord unchecked = record;
                unchecked.check.reset();
                const auto replayed = Match::replay(unchecked);
                const Match* m = std::get_if<Match>(&replayed);
                if (!m || m->check_hash() != record.check->hash)
                    ++caught;
                else
                    FAIL_CHECK("a flip read back and replayed to the same check");
                if (!m || m->final_check_hash() != final_state)
                    ++caught_by_old_check;
                else
                    CHECK_FALSE(replay_error(record).empty()); // what a player's reader says
            }
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    WARN(flips << " flips of " << lines.size() << " action lines, " << read_back
               << " read back; the running check caught " << caught
               << ", a check of the last state alone " << caught_by_old_check << " (" << seconds
               << " s)");
    CHECK(read_back > 0);
    CHECK(caught == read_back);
    // The check of versions 4 and 5 misses some: what the running check is for.
    CHECK(caught_by_old_check < read_back);
}
