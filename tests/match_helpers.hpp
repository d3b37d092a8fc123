#pragma once
// Matches played in tests: one started from a header, and the seated computer's move made
// through the match's own actions.

#include <catch2/catch.hpp>
#include <termpool/match.hpp>
#include <utility>
#include <variant>

namespace termpool::test {

// The match `header` gives; the test stops when the match refuses it.
inline Match started(const GameRecord& header, std::uint64_t computer_seed = 0) {
    auto match = Match::start(header, computer_seed);
    REQUIRE(std::holds_alternative<Match>(match));
    return std::move(std::get<Match>(match));
}

// The computer seated at the player to act makes its move (or, at a rack's end, racks the next
// one), through the match's own actions: what the match said of it.
inline MatchError play_computer_move(Match& match) {
    const int player = match.to_act();
    if (match.pending().kind == Pending::next_rack)
        return match.next_rack(player);
    const std::optional<ComputerMove> move = match.computer_move();
    REQUIRE(move);
    switch (move->kind) {
    case Pending::place:
        return match.place(player, move->spot);
    case Pending::choose:
        return match.choose(player, move->choice);
    default: {
        const auto played = match.shoot(player, move->shot.strike, move->shot.call);
        return std::holds_alternative<MatchError>(played) ? std::get<MatchError>(played)
                                                          : MatchError::none;
    }
    }
}

} // namespace termpool::test
