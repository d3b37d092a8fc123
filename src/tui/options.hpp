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
    bool timed_power = false;               ///< config power-mode: start in timed power mode
    bool aim_aid = true;                    ///< config aim-aid: show the aiming aid
    Level default_level = Level::medium;    ///< config level: for --vs-computer without one
    bool resume = false;                    ///< --resume [N|FILE]: continue a saved game
    std::string resume_from;                ///< --resume N or FILE; empty: the only one
    std::string save_path;                  ///< where App saves (run_game picks the slot)
    bool help = false;                      ///< -h, --help: print the usage and exit
    bool ascii = false;                     ///< --ascii: plain ASCII and no colour
    FrictionModel friction;                 ///< --friction MODEL [K] [A]
    double cue_ball_mass = 0;               ///< --cue-ball-mass KG (0: like the others)
    std::optional<Level> watch;             ///< --watch [LEVEL]: the computer is player 1 too
    std::optional<Level> computer;          ///< --vs-computer [LEVEL]: the computer is player 2
};

/// Parses the game's options; on error returns nothing and sets `error`.
/// `defaults` (from the config file) are what the command line starts from.
std::optional<GameOptions> parse_game_options(const std::vector<std::string>& args,
                                              std::string& error, GameOptions defaults = {});

} // namespace termpool::tui
