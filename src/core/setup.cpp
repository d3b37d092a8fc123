// The game's setup and the one text form of the cloth model.
#include "../support/text_numbers.hpp"
#include <cmath>
#include <termpool/game_registry.hpp>
#include <termpool/setup.hpp>

namespace termpool {
namespace {

// Where constant `index` of `model`'s kind is kept: K is the decay rate, A the deceleration.
template <class Model> auto& constant_slot(Model& model, std::size_t index) {
    return friction_constant_symbol(model.kind, index)[0] == 'K' ? model.decay_rate
                                                                 : model.deceleration;
}

std::variant<double, FrictionProblem::Kind> read_constant(std::string_view text) {
    const std::optional<double> value = parse_double(text);
    if (!value)
        return FrictionProblem::Kind::not_a_number;
    if (!std::isfinite(*value))
        return FrictionProblem::Kind::not_finite;
    if (!(*value > 0))
        return FrictionProblem::Kind::not_positive;
    return *value;
}

std::string shortest(double v) {
    return format_double(v); // the one text of state that reads back exactly
}

} // namespace

TableSize table_played(const GameSetup& setup) {
    return game_row(setup.game).table.value_or(setup.table);
}

PhysicsParams game_physics(const GameSetup& setup) {
    return physics_for_table(table_played(setup), setup.physics);
}

Table make_table(const GameSetup& setup) {
    return make_table(table_played(setup), game_physics(setup).ball_radius);
}

Game make_game(const GameSetup& setup, int breaker, std::uint64_t seed) {
    return Game(setup.game, make_table(setup), game_physics(setup), breaker, seed);
}

std::optional<FrictionKind> parse_friction_kind(std::string_view name) {
    return parse_name(friction_kind_names, name);
}

std::size_t friction_constant_count(FrictionKind kind) {
    switch (kind) {
    case FrictionKind::physical:
        break;
    case FrictionKind::decay:
    case FrictionKind::constant:
        return 1;
    case FrictionKind::combined:
        return 2;
    }
    return 0;
}

const char* friction_constant_symbol(FrictionKind kind, std::size_t index) {
    return kind == FrictionKind::constant || index > 0 ? "A" : "K";
}

std::variant<FrictionModel, FrictionProblem>
parse_friction(std::span<const std::string_view> words) {
    const std::optional<FrictionKind> kind =
        words.empty() ? std::nullopt : parse_friction_kind(words[0]);
    if (!kind)
        return FrictionProblem{FrictionProblem::Kind::unknown_model, 0};
    const std::size_t constants = friction_constant_count(*kind);
    if (words.size() < constants + 1)
        return FrictionProblem{FrictionProblem::Kind::missing_constant, words.size()};
    if (words.size() > constants + 1)
        return FrictionProblem{FrictionProblem::Kind::extra_word, constants + 1};
    FrictionModel model;
    model.kind = *kind;
    for (std::size_t i = 0; i < constants; ++i) {
        const auto value = read_constant(words[i + 1]);
        if (const auto* problem = std::get_if<FrictionProblem::Kind>(&value))
            return FrictionProblem{*problem, i + 1};
        constant_slot(model, i) = std::get<double>(value);
    }
    return model;
}

std::string friction_problem_text(const FrictionProblem& problem,
                                  std::span<const std::string_view> words, std::string_view usage) {
    using Kind = FrictionProblem::Kind;
    const auto word = [&](std::size_t i) {
        return i < words.size() ? std::string(words[i]) : std::string();
    };
    if (problem.kind == Kind::unknown_model)
        return "unknown friction model '" + word(0) +
               "' (expected physical, decay, constant or combined)";
    if (problem.kind == Kind::missing_constant)
        return "missing field (usage: " + std::string(usage) + ")";
    const std::string text = word(problem.word);
    if (problem.kind == Kind::extra_word)
        return "extra field '" + text + "' (usage: " + std::string(usage) + ")";
    const std::optional<FrictionKind> kind =
        words.empty() ? std::nullopt : parse_friction_kind(words[0]);
    const bool rate =
        kind && problem.word >= 1 && friction_constant_symbol(*kind, problem.word - 1)[0] == 'K';
    const std::string what = rate ? "decay rate K" : "deceleration A";
    if (problem.kind == Kind::not_a_number)
        return what + " '" + text + "' is not a number";
    if (problem.kind == Kind::not_finite)
        return what + " '" + text + "' is not finite";
    return what + " must be > 0 (got " + text + ")";
}

std::string format_friction(const FrictionModel& model) {
    std::string text = name_of(friction_kind_names, model.kind);
    for (std::size_t i = 0; i < friction_constant_count(model.kind); ++i)
        text += " " + shortest(constant_slot(model, i));
    return text;
}

} // namespace termpool
