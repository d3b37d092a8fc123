// The message line: the referee's verdicts in the players' words.
#include <catch2/catch.hpp>

#include <termpool/record.hpp>
#include <variant>

#include "tui/help_text.hpp"
#include "tui/messages.hpp"
#include "tui/rack_log.hpp"

using namespace termpool;
using namespace termpool::tui;

namespace {
const std::string names[2] = {"Ann", "Bob"};
}

TEST_CASE("verdicts read as a player would say them", "[tui][messages]") {
    Verdict v;
    v.next_shooter = 2;
    CHECK(verdict_message(v, 1, names) == "Switch player: Bob to shoot");

    v.foul = Foul::scratch;
    v.ball_in_hand = BallInHand::anywhere;
    CHECK(verdict_message(v, 1, names) == "Foul: scratch \u2014 Bob has ball in hand");
    v.ball_in_hand = BallInHand::kitchen;
    CHECK(verdict_message(v, 1, names) == "Foul: scratch \u2014 Bob has ball in hand (kitchen)");

    Verdict again;
    again.next_shooter = 1;
    CHECK(verdict_message(again, 1, names) == "Ann shoots again");
    again.groups_assigned = true;
    again.player1_group = Group::stripes;
    CHECK(verdict_message(again, 1, names) == "Ann has stripes \u2014 shoot again");

    Verdict choice;
    choice.next_shooter = 2;
    choice.chooser = 2;
    choice.choices = {Choice::play_on, Choice::re_rack};
    CHECK(verdict_message(choice, 1, names) == "Bob chooses");
}

TEST_CASE("the end of a game names the winner and why", "[tui][messages]") {
    Verdict v;
    v.winner = 2;
    v.reason = WinReason::eight_early;
    CHECK(verdict_message(v, 1, names) == "Ann pocketed the 8 early \u2014 Bob wins");
    v.winner = 1;
    v.reason = WinReason::eight_pocketed;
    CHECK(win_message(v, 1, names) == "Ann pocketed the 8 \u2014 Ann wins");
    v.winner = 1;
    v.reason = WinReason::three_fouls;
    CHECK(win_message(v, 2, names) == "Bob fouled three times in a row \u2014 Ann wins");
}

TEST_CASE("an illegal 8-ball break says why a choice is owed", "[tui][messages]") {
    Verdict v;
    v.next_shooter = 2;
    v.chooser = 2;
    v.choices = {Choice::play_on, Choice::re_rack, Choice::re_break};
    v.legal_break = false;
    CHECK(verdict_message(v, 1, names) ==
          "Illegal break (fewer than four balls to a rail): Bob chooses");
    v.legal_break = true; // a choice owed for another reason (a push-out) says only who
    CHECK(verdict_message(v, 1, names) == "Bob chooses");
}

TEST_CASE("the re-break choice reads right for whoever is offered it", "[tui]") {
    // The opponent of an illegal break and the breaker who potted the 8 are both offered it:
    // either way it is the breaker who breaks again.
    CHECK(termpool::tui::choice_words(termpool::Choice::re_break) == "the breaker breaks again");
}

TEST_CASE("a snooker foul names the points and says in-off, not scratch",
          "[tui][messages][snooker]") {
    Verdict v;
    v.foul = Foul::scratch;
    v.penalty = 4;
    v.next_shooter = 2;
    v.chooser = 2;
    CHECK(verdict_message(v, 1, names) == "Foul: in-off \u2014 4 points to Bob; Bob chooses");
    v.foul = Foul::wrong_ball_first;
    v.penalty = 7;
    v.miss = true;
    CHECK(verdict_message(v, 1, names) ==
          "Foul and a miss: wrong ball first \u2014 7 points to Bob; Bob chooses");
}

TEST_CASE("the rack's log tells each shot: shooter, call, pots and verdict", "[tui][messages]") {
    const auto parsed =
        parse_record("termpool-record 1\ngame 8ball\ntable 9ft\nseed 3\nbreaker 1\n"
                     "player1 Ann\nplayer2 Bob\nshot 12 0 0 0\nshot 2 90 0 0\nend\n");
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    const GameRecord& record = std::get<GameRecord>(parsed);
    const std::vector<std::string> log = rack_log(record, 1);
    REQUIRE(log.size() == 2);
    CHECK(log[0] == "1. Ann, break: pocketed 3 \u2014 Ann shoots again");
    CHECK(log[1] == "2. Ann: nothing pocketed \u2014 Switch player: Bob to shoot");
    // Another rack has no shots yet; a record that does not replay has no log.
    CHECK(rack_log(record, 2).empty());
    GameRecord broken = record;
    broken.actions.insert(broken.actions.begin(), RecordedAction{});
    broken.actions.front().kind = RecordedAction::Kind::rack;
    CHECK(rack_log(broken, 1).empty());
}

TEST_CASE("the rack's log grows shot by shot as the rebuilt one would read", "[tui][messages]") {
    // Each shot adds its line as it is told; the log of the record rebuilt afterwards agrees,
    // and the first shot of the next rack starts the log afresh.
    const auto parsed =
        parse_record("termpool-record 1\ngame 8ball\ntable 9ft\nseed 3\nbreaker 1\n"
                     "player1 Ann\nplayer2 Bob\nshot 12 0 0 0\nshot 2 90 0 0\nend\n");
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    const GameRecord& record = std::get<GameRecord>(parsed);
    GameRecord empty = record;
    empty.actions.clear();
    RackLog log;
    log.rebuild(empty, 1);
    CHECK(log.lines(1).empty());
    const auto heard = [&](const PlayedShot& shot) { log.add(shot, record); };
    REQUIRE(std::holds_alternative<Match>(Match::replay(record, record.actions.size(), heard)));
    CHECK(log.lines(1) == rack_log(record, 1));
    CHECK(log.lines(2).empty());
    PlayedShot next_rack;
    next_rack.rack = 2;
    log.add(next_rack, record);
    CHECK(log.lines(2).size() == 1);
    CHECK(log.lines(1).empty());
}

TEST_CASE("the rack's log pages by the rows its lines take once wrapped", "[tui][messages]") {
    // Thirty shots whose lines are wider than a 100-column screen's box: each takes two rows,
    // so a page of a 32-row screen holds half as many as it has rows, and every line is on one
    // page, in order.
    std::vector<std::string> lines;
    for (int i = 1; i <= 30; ++i)
        lines.push_back(std::to_string(i) + ". " + std::string(90, 'x') + " " +
                        std::string(20, 'y'));
    const int width = 100, height = 32;
    const std::vector<std::size_t> starts = log_page_starts(lines, width, height);
    REQUIRE(starts.size() >= 2);
    CHECK(starts.front() == 0);
    for (std::size_t page = 0; page < starts.size(); ++page) {
        const std::size_t end = page + 1 < starts.size() ? starts[page + 1] : lines.size();
        REQUIRE(end > starts[page]);
        std::size_t rows = 0;
        for (std::size_t i = starts[page]; i < end; ++i) {
            const std::size_t wrapped = box_lines(lines[i], width - 4).size();
            CHECK(wrapped == 2);
            rows += wrapped;
        }
        // With its border, title, blank lines and footer, the box fits the screen.
        CHECK(static_cast<int>(rows) + 6 <= height - 3);
    }
    CHECK(starts.size() == 3); // 11 shots a page (22 of 23 rows), 11, then 8
    // Short lines take a row each; no lines still make one page.
    CHECK(log_page_starts(std::vector<std::string>(23, "1. Ann: nothing pocketed"), 100, 32) ==
          std::vector<std::size_t>{0});
    CHECK(log_page_starts(std::vector<std::string>(24, "1. Ann: nothing pocketed"), 100, 32) ==
          std::vector<std::size_t>{0, 23});
    CHECK(log_page_starts({}, 100, 32) == std::vector<std::size_t>{0});
}
