#include <termpool/params.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "../support/text_numbers.hpp"

namespace termpool {

namespace {

/// What values of a parameter make physical sense.
enum class Range {
    non_negative,
    unit_interval,
    positive,
    one_to_two, ///< between 1 and 2, both excluded (the stronge cushion's w_c)
};

struct ParameterSpec {
    std::string_view name;
    double PhysicsParams::*field; ///< null for u_b, which lives in PhysicsParams::ball_friction
    Range range;
};

// In the order of physics_parameter_names, which the static_assert below keeps.
constexpr ParameterSpec parameter_specs[] = {
    {"u_s", &PhysicsParams::sliding_friction, Range::non_negative},
    {"u_r", &PhysicsParams::rolling_friction, Range::non_negative},
    {"u_sp", &PhysicsParams::spin_friction, Range::non_negative},
    {"e_b", &PhysicsParams::ball_restitution, Range::unit_interval},
    {"u_b", nullptr, Range::non_negative},
    {"e_c", &PhysicsParams::cushion_restitution, Range::unit_interval},
    {"f_c", &PhysicsParams::cushion_friction, Range::non_negative},
    {"w_c", &PhysicsParams::cushion_frequency_ratio, Range::one_to_two},
    {"g", &PhysicsParams::gravity, Range::positive},
    {"R", &PhysicsParams::ball_radius, Range::positive},
    {"m", &PhysicsParams::ball_mass, Range::positive},
};

constexpr bool specs_match_names() {
    if (std::size(parameter_specs) != std::size(physics_parameter_names))
        return false;
    for (std::size_t i = 0; i < std::size(parameter_specs); ++i)
        if (parameter_specs[i].name != physics_parameter_names[i])
            return false;
    return true;
}
static_assert(specs_match_names());

const ParameterSpec* find_spec(std::string_view name) {
    const auto it = std::find_if(std::begin(parameter_specs), std::end(parameter_specs),
                                 [&](const ParameterSpec& s) { return s.name == name; });
    return it == std::end(parameter_specs) ? nullptr : &*it;
}

} // namespace

std::optional<std::string> set_physics_parameter(PhysicsParams& params, std::string_view name,
                                                 double value) {
    const ParameterSpec* spec = find_spec(name);
    if (!spec) {
        return "unknown parameter '" + std::string(name) + "' (expected " +
               or_list(physics_parameter_names) + ")";
    }
    const std::string got = " (got " + format_double(value) + ")";
    if (!std::isfinite(value))
        return std::string(name) + " must be finite" + got;
    switch (spec->range) {
    case Range::non_negative:
        if (value < 0)
            return std::string(name) + " must be >= 0" + got;
        break;
    case Range::unit_interval:
        if (value < 0 || value > 1)
            return std::string(name) + " must be between 0 and 1" + got;
        break;
    case Range::positive:
        if (value <= 0)
            return std::string(name) + " must be > 0" + got;
        break;
    case Range::one_to_two:
        if (!(value > 1 && value < 2))
            return std::string(name) + " must be between 1 and 2, both excluded" + got;
        break;
    }
    if (spec->field) {
        params.*spec->field = value;
    } else {
        params.ball_friction.model = BallFrictionModel::constant;
        params.ball_friction.constant = value;
    }
    return std::nullopt;
}

std::optional<double> physics_parameter(const PhysicsParams& params, std::string_view name) {
    const ParameterSpec* spec = find_spec(name);
    if (!spec)
        return std::nullopt;
    if (spec->field)
        return params.*spec->field;
    return params.ball_friction.model == BallFrictionModel::constant
               ? params.ball_friction.constant
               : ball_friction_at(params.ball_friction, 0);
}

} // namespace termpool
