#pragma once
// Command-line options of the game.

#include <optional>
#include <string>
#include <termpool/computer.hpp>
#include <termpool/rules.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool::tui {

/// What the command line presets.
struct GameOptions {
    std::optional<std::string> names[2];    ///< --player1, --player2 (cleaned)
    GameType game = GameType::eight_ball;   ///< --game
    TableSize table = TableSize::nine_foot; ///< --table
    bool resume = false;                    ///< --resume: continue the last unfinished game
    bool ascii = false;                     ///< --ascii: plain ASCII and no colour
    FrictionModel friction;                 ///< --friction MODEL [K] [A]
    double cue_ball_mass = 0;               ///< --cue-ball-mass KG (0: like the others)
    std::optional<Level> watch;             ///< --watch [LEVEL]: the computer is player 1 too
    std::optional<Level> computer;          ///< --vs-computer [LEVEL]: the computer is player 2
};

/// Parses the game's options; on error returns nothing and sets `error`.
std::optional<GameOptions> parse_game_options(const std::vector<std::string>& args,
                                              std::string& error);

} // namespace termpool::tui
