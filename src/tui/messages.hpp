#pragma once
// The referee's verdicts in the players' words.

#include <string>
#include <termpool/rules.hpp>

namespace termpool::tui {

/// A foul in words ("scratch", "wrong ball first", ...).
std::string foul_words(Foul foul);
/// A choice in words ("play on", ...).
std::string choice_words(Choice choice);
/// The end of the game: "Ann pocketed the 8 early — Bob wins". `names` are players 1 and 2.
std::string win_message(const Verdict& verdict, int shooter, const std::string names[2]);
/// The message line after a shot by `shooter`.
std::string verdict_message(const Verdict& verdict, int shooter, const std::string names[2]);

} // namespace termpool::tui
