#pragma once
/// \file
/// The output lines of `termpool simulate` (see README.md, "Simulator input and output").

#include <string>
#include <termpool/ball.hpp>
#include <termpool/event.hpp>
#include <termpool/rules.hpp>
#include <vector>

namespace termpool::cli {

/// One `event T KIND ...` line, newline included.
std::string format_event(const Event& event);

/// One `ball ID X Y table|pocket P` line, newline included.
std::string format_ball(const Ball& ball);

/// The whole output: every event, every ball (in the order given) and `rest T`.
std::string format_shot(const std::vector<Event>& events, const std::vector<Ball>& balls,
                        double rest_time);

/// The referee's lines that follow `rest` in a scenario with a game context: `first-contact`,
/// `foul`, `pocketed`, `groups`, `next` and `ball-in-hand`, then `choice` when a player owes
/// a choice and `winner` when the game is over.
std::string format_verdict(const Verdict& verdict);

} // namespace termpool::cli
