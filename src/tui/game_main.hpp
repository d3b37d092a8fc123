#pragma once
// Entry point of the terminal game; the header stays free of curses so main.cpp can call it.

#include <string>
#include <vector>

namespace termpool::tui {

/// The game's options, one or two lines each, as `termpool --help` (main.cpp) and the game's
/// own usage message show them.
const char* game_options_usage();

/// `termpool [OPTIONS]`: plays the game in the terminal (see game_options_usage). Returns the
/// exit status (0 after -h/--help, 2 for bad options).
int run_game(const std::vector<std::string>& args);

/// `termpool practice [--game G] [--table T] [--player1 NAME] [--seed S] [--ascii]`: one
/// player at the table with no referee. Returns the exit status (2 for bad options).
int run_practice(const std::vector<std::string>& args);

/// `termpool replay [FILE]`: plays a saved game back in the terminal, by default the save
/// written last. Returns the exit status (1 when there is no save, 2 for a file that cannot
/// be read as a game).
int run_replay(const std::vector<std::string>& args);

} // namespace termpool::tui
