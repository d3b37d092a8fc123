#pragma once
// One action taken on a Match, as every driver takes it (the player's, the computer's, the
// server's, a record's), with what it means in the players' words.

#include <string>
#include <termpool/match.hpp>

#include "tui/table_driver.hpp"

namespace termpool::tui {

/// Applies `action` to `match` for the player to act: a shot is simulated (for rolling out),
/// judged and told in words. Nothing, with `error` set, when the match refuses it.
std::optional<TableNews> take_action(Match& match, const RecordedAction& action, MatchError& error);

/// "Ann breaks: place the cue ball in the kitchen".
std::string breaks_words(const Match& match, int breaker);

/// "Rack 2: Ann breaks: ..." ("Frame 2" at snooker): the next rack of a race has begun.
std::string rack_words(const Match& match, int breaker);

/// Where the match stands: "Ann won rack 2", "Bob to choose", "Ann to play".
std::string standing_words(const Match& match);

} // namespace termpool::tui
