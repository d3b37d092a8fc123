#pragma once
// One action taken on a Match, as every driver takes it (the player's, the computer's, the
// server's, a record's), with what it means in the players' words.

#include <string>
#include <termpool/match.hpp>

#include "tui/table_driver.hpp"

namespace termpool::tui {

/// Applies `action` to `match` for the player to act: a shot is simulated (for rolling out),
/// judged and told in words. Nothing, with `error` set, when the match refuses it. `seat` is
/// the seat played at this terminal (0: none, a replay or a spectator): a new rack tells its
/// breaker there what to do, and says to anyone else who breaks.
std::optional<TableNews> take_action(Match& match, const RecordedAction& action, MatchError& error,
                                     int seat = 0);

/// Who breaks and from where: to the player who breaks at this terminal (`here`), what to do
/// ("Ann breaks: place the cue ball in the kitchen", in snooker "Ann breaks off: place the
/// cue ball in the D"); of another seat, what it does ("CPU (hard) breaks off from the D").
std::string breaks_words(const Match& match, int breaker, bool here);

/// "Rack 2: Ann breaks: ..." ("Frame 2" at snooker): the next rack of a race has begun.
std::string rack_words(const Match& match, int breaker, bool here);

/// Who plays next after a choice, and how: "Ann breaks", "Ann has ball in hand in the D",
/// "Ann to shoot".
std::string next_words(const Match& match);

/// Where the match stands: "Ann won rack 2", "Bob to choose", "Ann to play".
std::string standing_words(const Match& match);

} // namespace termpool::tui
