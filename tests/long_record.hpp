#pragma once
// A valid 8-ball record as long as the hall keeps one: every shot a tap with spin, a raised
// cue and a call, every number written to its last digit, so that each action line is as long
// as a player's can be. Taps miss: each is a foul, and the other player, with the cue ball in
// hand, shoots it from where it lies (back and forth, so it never travels far).

#include <catch2/catch.hpp>
#include <cstddef>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <variant>

namespace termpool::test {

/// A record of `actions` actions of 8-ball on the 7 ft table, as Match made it (with its check).
inline GameRecord long_eight_ball_record(std::size_t actions) {
    GameRecord header;
    header.setup.game = GameType::eight_ball;
    header.setup.table = TableSize::seven_foot;
    header.seed = 12345678901234567ull;
    header.names[0] = "Annabel Longname-Fortescue";
    header.names[1] = "Bartholomew Q. Threepwood";
    auto started = Match::start(header);
    REQUIRE(std::holds_alternative<Match>(started));
    Match match = std::move(std::get<Match>(started));
    for (std::size_t i = 0; i < actions; ++i) {
        const PendingAction pending = match.pending();
        RecordedAction action;
        if (pending.kind == Pending::choose) {
            action.kind = RecordedAction::Kind::choose;
            action.choice = pending.choices.front();
        } else if (pending.kind == Pending::place && i == 0) {
            // Behind the head string, far from the rack, to the last digit.
            action.kind = RecordedAction::Kind::place;
            action.place = {0.21234567890123456 + 1e-17 * static_cast<double>(i % 7),
                            0.31234567890123456};
        } else {
            action.kind = RecordedAction::Kind::shot;
            action.strike.speed = 0.012345678901234567; // rolls a few millimetres
            action.strike.angle_deg = i % 2 ? -179.12345678901234 : 0.87654321098765432;
            action.strike.side = -0.12345678901234567;
            action.strike.follow = -0.23456789012345678;
            action.strike.elevation_deg = 12.345678901234567;
            action.call.call.ball = 15;
            action.call.call.pocket = 6;
        }
        const MatchError error = match.apply(action);
        INFO("action " << i + 1 << ": " << format_action(action));
        REQUIRE(error == MatchError::none);
    }
    return match.record();
}

} // namespace termpool::test
