#pragma once
/// \file
/// Race to N: a match of racks, won by the first player to win N of them. Only the score and
/// who breaks next; the racks themselves are Games.

#include <optional>
#include <string_view>
#include <termpool/enum_names.hpp>

namespace termpool {

/// Who breaks the next rack of a match.
enum class BreakRule {
    alternate, ///< the players take turns (WPA's default for match play)
    winner,    ///< the winner of a rack breaks the next one
};

/// The break rules' names, as the command line and a record give them.
inline constexpr NameRow<BreakRule> break_rule_names[] = {
    {BreakRule::alternate, "alternate"},
    {BreakRule::winner, "winner"},
};
static_assert(names_in_order(break_rule_names));

/// "alternate" or "winner".
const char* break_rule_name(BreakRule rule);
/// Parses a break rule's name; nothing for an unknown one.
std::optional<BreakRule> parse_break_rule(std::string_view name);

/// The longest race the game offers.
inline constexpr int max_race_to = 99;

/// The race of a match of best of `frames` (snooker's way of saying it): the first to win
/// more than half, (frames + 1) / 2.
constexpr int race_for_best_of(int frames) {
    return (frames + 1) / 2;
}

/// The frames of a match of race to `race_to` said snooker's way, best of 2 * race_to - 1
/// (best of 5 for a race to 3); the inverse of `race_for_best_of` for odd counts.
constexpr int best_of_for_race(int race_to) {
    return 2 * race_to - 1;
}

/// The score of a match.
struct MatchState {
    int race_to = 1;                             ///< racks to win; 0 or 1: a single game
    BreakRule break_rule = BreakRule::alternate; ///< who breaks each next rack
    int racks_won[2] = {0, 0};                   ///< by player 1 and player 2

    /// True for a race of more than one rack.
    bool is_race() const { return race_to > 1; }
    /// The racks won so far by both players.
    int racks_played() const { return racks_won[0] + racks_won[1]; }
    /// 1 or 2 once a player has won the race, else 0.
    int match_winner() const;
    /// Who breaks the rack after one that `rack_breaker` was given to break and `rack_winner`
    /// won: 1 or 2.
    int next_breaker(int rack_breaker, int rack_winner) const;
    /// Counts a rack won by `winner` (1 or 2). Returns false, and counts nothing, for another
    /// value or once the match is decided.
    bool record_rack(int winner);

    /// Equal scores of equal races.
    bool operator==(const MatchState&) const = default;
};

} // namespace termpool
