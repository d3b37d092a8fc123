// The game's setup and the one text form of the cloth model.
#include <cmath>
#include <termpool/game_registry.hpp>
#include <termpool/setup.hpp>
#include <termpool/text_numbers.hpp>

namespace termpool {
namespace {

struct ModelName {
    std::string_view name;
    FrictionKind kind;
    std::size_t constants;
};

constexpr ModelName model_names[] = {
    {"physical", FrictionKind::physical, 0},
    {"decay", FrictionKind::decay, 1},
    {"constant", FrictionKind::constant, 1},
    {"combined", FrictionKind::combined, 2},
};

const ModelName* find_model(std::string_view name) {
    for (const ModelName& m : model_names)
        if (m.name == name)
            return &m;
    return nullptr;
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
    const ModelName* m = find_model(name);
    return m ? std::optional<FrictionKind>(m->kind) : std::nullopt;
}

std::size_t friction_constant_count(FrictionKind kind) {
    for (const ModelName& m : model_names)
        if (m.kind == kind)
            return m.constants;
    return 0;
}

const char* friction_constant_symbol(FrictionKind kind, std::size_t index) {
    return kind == FrictionKind::constant || index > 0 ? "A" : "K";
}

std::variant<FrictionModel, FrictionProblem>
parse_friction(std::span<const std::string_view> words) {
    const ModelName* m = words.empty() ? nullptr : find_model(words[0]);
    if (!m)
        return FrictionProblem{FrictionProblem::Kind::unknown_model, 0};
    if (words.size() < m->constants + 1)
        return FrictionProblem{FrictionProblem::Kind::missing_constant, words.size()};
    if (words.size() > m->constants + 1)
        return FrictionProblem{FrictionProblem::Kind::extra_word, m->constants + 1};
    FrictionModel model;
    model.kind = m->kind;
    for (std::size_t i = 0; i < m->constants; ++i) {
        const auto value = read_constant(words[i + 1]);
        if (const auto* kind = std::get_if<FrictionProblem::Kind>(&value))
            return FrictionProblem{*kind, i + 1};
        const double v = std::get<double>(value);
        if (friction_constant_symbol(m->kind, i)[0] == 'K')
            model.decay_rate = v;
        else
            model.deceleration = v;
    }
    return model;
}

std::string format_friction(const FrictionModel& model) {
    switch (model.kind) {
    case FrictionKind::physical:
        break;
    case FrictionKind::decay:
        return "decay " + shortest(model.decay_rate);
    case FrictionKind::constant:
        return "constant " + shortest(model.deceleration);
    case FrictionKind::combined:
        return "combined " + shortest(model.decay_rate) + " " + shortest(model.deceleration);
    }
    return "physical";
}

} // namespace termpool
