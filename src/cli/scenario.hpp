#pragma once
/// \file
/// The input of `termpool simulate`: text in, a validated scenario or the first error out.
/// No I/O happens here, so that the format can be tested without running the binary.

#include <optional>
#include <string>
#include <string_view>
#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/rules.hpp>
#include <termpool/setup.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <variant>
#include <vector>

namespace termpool::cli {

/// The game around the shot, for the referee: given by the directives `game`, `shooter`,
/// `groups`, `break`, `call` and `push-out`. Every field has passed the checks against the rest of
/// the scenario (a called ball is on the table, 9-ball has neither groups nor calls, ...).
struct GameContext {
    int shooter = 1;                   ///< the player at the table, 1 or 2
    Group player1_group = Group::open; ///< player 1's group (player 2 has the other)
    bool is_break = false;             ///< the shot is the break
    Call call;                         ///< the 8-ball call; ball 0 when nothing was called
    bool push_out = false;             ///< `push-out`: 9-ball, the shot right after the break
};

/// A scenario that passed every check and can be handed to the simulator as it is.
struct Scenario {
    /// `game` (8-ball when not given), `table`, and the physics: the defaults with every
    /// directive applied, on the balls of the table (snooker's on `table snooker`, unless
    /// `param R` or `param m` says otherwise). Unlike a game's setup, `physics` is already the
    /// physics of the shot: hand it to the simulator as it is.
    GameSetup setup;
    Table table = make_table(TableSize::nine_foot); ///< `setup`'s table, built for its ball radius
    std::vector<Ball> balls;                        ///< at rest, in ascending id order
    std::optional<Strike> strike;                   ///< the shot; none means "just print"
    /// Present when any game directive was given; then `strike` is present too.
    std::optional<GameContext> game;
};

/// Why a scenario was refused.
struct ScenarioError {
    int line = 0;        ///< 1-based line of the offending directive
    std::string message; ///< what is wrong, without file name and line number
};

/// Either the scenario or the error that refused it.
using ScenarioResult = std::variant<Scenario, ScenarioError>;

/// Parses and validates the text of a scenario (see README.md, "Simulator input and output").
/// Errors that a line shows on its own (syntax, ranges, repeated directives) are reported
/// first, in line order; then those that need the whole file (positions, overlaps, the cue
/// ball), at the later of the lines involved.
ScenarioResult parse_scenario(std::string_view text);

} // namespace termpool::cli
