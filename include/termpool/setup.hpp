#pragma once
/// \file
/// What a game is played with: the rules, the table and the physics. One type carried by the
/// game's options, the config, a record and a scenario, and one text form of the cloth model
/// ("physical", "decay K", "constant A", "combined K A") read and written in one place.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <termpool/params.hpp>
#include <termpool/rules.hpp>
#include <termpool/table.hpp>
#include <termpool/table_physics.hpp>
#include <variant>

namespace termpool {

/// The rules, the table and the physics of a game.
struct GameSetup {
    GameType game = GameType::eight_ball;   ///< the rules
    TableSize table = TableSize::nine_foot; ///< the table's size
    /// The simulator's constants and models as chosen (the defaults but for what the player
    /// changed); the balls' size and mass follow the table (`game_physics`).
    PhysicsParams physics;
};

/// The table a game of `setup` is played on: its table, but a game whose row names a table
/// (snooker's) is always played on that one.
TableSize table_played(const GameSetup& setup);

/// The physics a game of `setup` is played with: its physics with the balls of its table
/// (`physics_for_table`), so snooker balls on the snooker table.
PhysicsParams game_physics(const GameSetup& setup);

/// The table of `setup`, built for the radius of its balls (`game_physics`).
Table make_table(const GameSetup& setup);

/// A new rack of `setup`'s game with `breaker` (1 or 2) to break, racked from `seed`, played
/// with `game_physics(setup)`.
Game make_game(const GameSetup& setup, int breaker, std::uint64_t seed);

/// Why the words of a cloth model were refused; each reader words it its own way.
struct FrictionProblem {
    /// The kinds of problem.
    enum class Kind {
        unknown_model,    ///< the first word names no model
        missing_constant, ///< fewer constants than the model takes
        extra_word,       ///< more words than the model takes
        not_a_number,     ///< a constant is not a number
        not_finite,       ///< a constant is infinite or not a number
        not_positive,     ///< a constant is zero or negative
    };
    Kind kind = Kind::unknown_model; ///< what is wrong
    std::size_t word = 0;            ///< the word it is about (0: the model's name)
};

/// The model named `name` ("physical", "decay", "constant", "combined"); nothing for another.
std::optional<FrictionKind> parse_friction_kind(std::string_view name);

/// The number of constants `kind` takes: 0 (physical), 1 (decay, constant) or 2 (combined).
std::size_t friction_constant_count(FrictionKind kind);

/// The symbol of constant `index` (from 0) of `kind`: "K" (the decay rate, 1/s) or "A" (the
/// deceleration, m/s^2).
const char* friction_constant_symbol(FrictionKind kind, std::size_t index);

/// Reads a cloth model from its words: the model's name, then its constants, each a positive
/// finite number.
std::variant<FrictionModel, FrictionProblem>
parse_friction(std::span<const std::string_view> words);

/// `problem` in the words `termpool simulate` uses ("unknown friction model 'x' (expected
/// ...)", "decay rate K must be > 0 (got 0)"), `words` being what was read and `usage` the form
/// the reader shows for a missing or extra word.
std::string friction_problem_text(const FrictionProblem& problem,
                                  std::span<const std::string_view> words, std::string_view usage);

/// The words `parse_friction` reads back to `model` (numbers as the shortest text that reads back
/// bit for bit), separated by spaces.
std::string format_friction(const FrictionModel& model);

} // namespace termpool
