// Race to N: the score of a match, who breaks each next rack, and the break rules' names.
#include <catch2/catch.hpp>
#include <termpool/race.hpp>

using namespace termpool;

TEST_CASE("break rules have names that parse back", "[race]") {
    for (const BreakRule rule : {BreakRule::alternate, BreakRule::winner})
        CHECK(parse_break_rule(break_rule_name(rule)) == rule);
    CHECK(std::string(break_rule_name(BreakRule::alternate)) == "alternate");
    CHECK(std::string(break_rule_name(BreakRule::winner)) == "winner");
    CHECK_FALSE(parse_break_rule("loser"));
    CHECK_FALSE(parse_break_rule(""));
    CHECK_FALSE(parse_break_rule("Winner"));
}

TEST_CASE("alternate breaks: the players take turns whoever wins", "[race]") {
    const MatchState match{3, BreakRule::alternate, {0, 0}};
    CHECK(match.next_breaker(1, 1) == 2);
    CHECK(match.next_breaker(1, 2) == 2);
    CHECK(match.next_breaker(2, 1) == 1);
    CHECK(match.next_breaker(2, 2) == 1);
    CHECK(MatchState{}.break_rule == BreakRule::alternate);
}

TEST_CASE("winner breaks: the rack's winner breaks the next", "[race]") {
    const MatchState match{3, BreakRule::winner, {0, 0}};
    CHECK(match.next_breaker(1, 1) == 1);
    CHECK(match.next_breaker(1, 2) == 2);
    CHECK(match.next_breaker(2, 1) == 1);
    CHECK(match.next_breaker(2, 2) == 2);
}

TEST_CASE("a race is won by the first to win N racks, and then counts no more", "[race]") {
    MatchState match{3, BreakRule::alternate, {0, 0}};
    CHECK(match.is_race());
    CHECK(match.match_winner() == 0);
    CHECK(match.record_rack(2));
    CHECK(match.record_rack(1));
    CHECK(match.record_rack(2));
    CHECK(match.match_winner() == 0);
    CHECK(match.record_rack(1));
    CHECK(match.match_winner() == 0);
    CHECK(match.racks_played() == 4);
    CHECK(match.record_rack(2));
    CHECK(match.match_winner() == 2);
    CHECK(match.racks_won[0] == 2);
    CHECK(match.racks_won[1] == 3);
    // Decided: a further rack is not counted, nor is a player who does not exist.
    CHECK_FALSE(match.record_rack(1));
    CHECK(match.racks_won[0] == 2);
    MatchState fresh{3, BreakRule::winner, {0, 0}};
    CHECK_FALSE(fresh.record_rack(0));
    CHECK_FALSE(fresh.record_rack(3));
    CHECK(fresh.racks_played() == 0);
}

TEST_CASE("a race to 0 or 1 is a single game", "[race]") {
    for (const int n : {0, 1}) {
        MatchState match{n, BreakRule::alternate, {0, 0}};
        CHECK_FALSE(match.is_race());
        CHECK(match.match_winner() == 0);
        CHECK(match.record_rack(1));
        CHECK(match.match_winner() == 1);
        CHECK_FALSE(match.record_rack(2));
    }
}

TEST_CASE("a race to N is best of 2N - 1 frames, and back", "[race]") {
    CHECK(best_of_for_race(1) == 1);
    CHECK(best_of_for_race(3) == 5);
    CHECK(best_of_for_race(max_race_to) == 197);
    for (int race = 1; race <= max_race_to; ++race)
        CHECK(race_for_best_of(best_of_for_race(race)) == race);
    static_assert(best_of_for_race(4) == 7);
}
