// The score of a race-to-N match and who breaks next.
#include <termpool/race.hpp>

namespace termpool {

const char* break_rule_name(BreakRule rule) {
    return name_of(break_rule_names, rule);
}

std::optional<BreakRule> parse_break_rule(std::string_view name) {
    return parse_name(break_rule_names, name);
}

int MatchState::match_winner() const {
    // A race to 0 is a single game too: one rack decides it.
    const int needed = race_to > 1 ? race_to : 1;
    for (int p = 0; p < 2; ++p)
        if (racks_won[p] >= needed)
            return p + 1;
    return 0;
}

int MatchState::next_breaker(int rack_breaker, int rack_winner) const {
    if (break_rule == BreakRule::winner)
        return rack_winner == 2 ? 2 : 1;
    return rack_breaker == 1 ? 2 : 1;
}

bool MatchState::record_rack(int winner) {
    if ((winner != 1 && winner != 2) || match_winner() != 0)
        return false;
    ++racks_won[winner - 1];
    return true;
}

} // namespace termpool
