#pragma once
// Command-line options of the game.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <termpool/assist.hpp>
#include <termpool/level.hpp>
#include <termpool/race.hpp>
#include <termpool/rules.hpp>
#include <termpool/setup.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// What the command line presets.
struct GameOptions {
    std::optional<std::string> names[2]; ///< --player1, --player2 (cleaned)
    /// --game, --table, --friction MODEL [K] [A], --cue-ball-mass KG (0: like the others),
    /// --cue standard|low-deflection|none (the shaft's end mass, hence the squirt)
    GameSetup setup;
    bool timed_power = false;            ///< config power-mode: start in timed power mode
    bool aim_aid = true;                 ///< config aim-aid: show the aiming aid
    Assist assist = Assist::standard;    ///< --assist, config assist: how much the aid helps
    Level default_level = Level::medium; ///< config level: for --vs-computer without one
    bool resume = false;                 ///< --resume [N|FILE]: continue a saved game
    std::string resume_from;             ///< --resume N or FILE; empty: the only one
    std::string save_path;               ///< where App saves (run_game picks the slot)
    bool help = false;                   ///< -h, --help: print the usage and exit
    bool ascii = false;                  ///< --ascii: plain ASCII and no colour
    std::optional<Level> watch;          ///< --watch [LEVEL]: the computer is player 1 too
    std::optional<Level> computer;       ///< --vs-computer [LEVEL]: the computer is player 2
    std::optional<std::uint64_t> seed;   ///< --seed S: the first rack's seed (else the clock)
    bool practice = false;               ///< `termpool practice`: one player, no referee
    /// News for the first message line: config warnings, where this game is saved.
    std::vector<std::string> notices;

    // The match: a single game unless a race is set.
    int race_to = 1;                             ///< --race N: racks to win (1: one game)
    BreakRule break_rule = BreakRule::alternate; ///< --breaks: who breaks each next rack
};

/// Parses a race length for --race and the config's `race`: a whole number from 1 to
/// max_race_to; nothing otherwise.
std::optional<int> parse_race_to(std::string_view text);

/// Parses a match's length in frames for --best-of: an odd whole number from 1 to
/// 2 * max_race_to - 1; nothing otherwise.
std::optional<int> parse_best_of(std::string_view text);

/// Parses the game's options; on error returns nothing and sets `error`.
/// `defaults` (from the config file) are what the command line starts from.
std::optional<GameOptions> parse_game_options(const std::vector<std::string>& args,
                                              std::string& error, GameOptions defaults = {});

} // namespace termpool
