#pragma once
// Entry point of the terminal game; the header stays free of curses so main.cpp can call it.

#include <string>
#include <vector>

namespace termpool::tui {

/// `termpool [--player1 NAME] [--player2 NAME] [--game G] [--table T] [--ascii]`: plays the
/// game in the terminal. Returns the exit status (2 for bad options).
int run_game(const std::vector<std::string>& args);

/// `termpool practice [--game G] [--table T] [--player1 NAME] [--seed S] [--ascii]`: one
/// player at the table with no referee. Returns the exit status (2 for bad options).
int run_practice(const std::vector<std::string>& args);

/// `termpool replay FILE`: plays a saved game back in the terminal. Returns the exit status
/// (2 for a file that cannot be read as a game).
int run_replay(const std::vector<std::string>& args);

} // namespace termpool::tui
