#pragma once
// The referee's verdicts in the players' words.

#include <string>
#include <termpool/rules.hpp>

namespace termpool::tui {

/// A foul in words ("scratch", "wrong ball first", ...).
std::string foul_words(Foul foul);
/// A choice in words ("play on", ...).
std::string choice_words(Choice choice);
/// A choice in the words of `game` (snooker's "put the offender back in"); `free_ball` when
/// playing on takes a free ball, `in_hand` where the cue ball is to be placed first (snooker,
/// after an in-off: the D).
std::string choice_words(Choice choice, GameType game, bool free_ball,
                         BallInHand in_hand = BallInHand::none);
/// A snooker ball's name: "red", "yellow", ..., "black" (empty for another id).
std::string snooker_ball_name(int id);
/// "in the D", "in the kitchen" or "anywhere": where a ball in hand goes.
std::string ball_in_hand_words(BallInHand where);
/// The end of the game: "Ann pocketed the 8 early — Bob wins". `names` are players 1 and 2.
std::string win_message(const Verdict& verdict, int shooter, const std::string names[2]);
/// Why the cue ball may not go to `spot` now ("behind the head string only", "it would touch
/// the 5", ...); empty when it may.
std::string placement_problem(const Game& game, Vec2 spot);
/// The message line after a shot by `shooter`.
std::string verdict_message(const Verdict& verdict, int shooter, const std::string names[2]);

} // namespace termpool::tui
