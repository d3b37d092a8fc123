#pragma once
// A save in words, for a list a player picks from: who plays what, how far they are, and how
// long ago it was saved.

#include <ctime>
#include <string>
#include <termpool/match.hpp>

#include "player/save_list.hpp"

namespace termpool {

/// How long before `now` a save written at `written` was saved: "just now" (under a minute,
/// or a time ahead of the clock), "1 minute ago", "5 minutes ago", "3 hours ago", "2 days ago";
/// from 30 days on, "on 2024-05-01" (the local date).
std::string age_words(std::time_t written, std::time_t now);

/// A game as a list shows it: the players, the game, the table (unless the game has its own:
/// snooker), the shots played, snooker's frame score, a race's racks ("Ann v Bob, 8ball, 9ft,
/// 12 shots, race to 3 at 1-0"), or who won a game that is over.
std::string game_summary(const Match& game);

/// A save in words: "Ann v Bob, 8ball, 9ft, 12 shots, saved 5 minutes ago", with ", being
/// played in another terminal" after one in use. A save that holds no game says so.
std::string save_words(const SlotSave& save, std::time_t now);

/// One line of a list of saves: the slot's number (right-aligned in 3 columns), 2 spaces and
/// `save_words`.
std::string save_line(const SlotSave& save, std::time_t now);

/// Why save `slot` was not removed, in words ("save 2 is being played in another terminal:
/// it is not removed"); `error` is what a failed removal reported. Empty for one removed.
std::string removal_words(Removal removal, int slot, const std::string& error);

} // namespace termpool
