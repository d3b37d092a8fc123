#include <termpool/simulator.hpp>

#include <cmath>

#include "../support/text_numbers.hpp"

namespace termpool {

namespace {

bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

bool finite(Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// What is wrong with `b` alone, whatever the table: numbers a World cannot step.
std::optional<LayoutProblem::Kind> motion_problem(const Ball& b) {
    using Kind = LayoutProblem::Kind;
    if (!finite(b.position) || !finite(b.velocity) || !finite(b.angular_velocity))
        return Kind::not_finite;
    if (!(b.mass > 0) || !std::isfinite(b.mass))
        return Kind::bad_mass;
    const Vec3 w = b.angular_velocity;
    if (length(b.velocity) > max_strike_speed ||
        std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z) > max_ball_spin)
        return Kind::too_fast;
    // A ball at rest has no velocity; one spinning on the spot turns about the vertical only.
    const bool still = b.velocity.x == 0 && b.velocity.y == 0;
    if ((b.state == MotionState::stationary && !(still && w.x == 0 && w.y == 0 && w.z == 0)) ||
        (b.state == MotionState::spinning && !(still && w.x == 0 && w.y == 0)))
        return Kind::at_rest_but_moving;
    return std::nullopt;
}

std::string position_text(Vec2 p) {
    return "(" + format_double(p.x) + ", " + format_double(p.y) + ")";
}

} // namespace

std::optional<LayoutProblem> layout_problem(const Table& table, const std::vector<Ball>& balls,
                                            double radius) {
    // Rack balls are packed with a gap that their jitter may close, so touching is allowed.
    constexpr double tolerance = 1e-9;
    using Kind = LayoutProblem::Kind;
    if (balls.size() > max_world_balls)
        return LayoutProblem{Kind::too_many, max_world_balls, max_world_balls};
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Ball& b = balls[i];
        for (std::size_t j = 0; j < i; ++j)
            if (balls[j].id == b.id)
                return LayoutProblem{Kind::same_id, i, j};
        if (b.state == MotionState::pocketed)
            continue;
        if (const auto kind = motion_problem(b))
            return LayoutProblem{*kind, i, i};
        if (!on_playing_surface(table, b.position, radius))
            return LayoutProblem{Kind::off_table, i, i};
        for (std::size_t j = 0; j < i; ++j)
            if (balls[j].state != MotionState::pocketed &&
                length(b.position - balls[j].position) < 2 * radius - tolerance)
                return LayoutProblem{Kind::overlap, i, j};
    }
    return std::nullopt;
}

std::string layout_problem_text(const LayoutProblem& problem, const std::vector<Ball>& balls,
                                const std::function<std::string(std::size_t, bool)>& name) {
    using Kind = LayoutProblem::Kind;
    if (problem.kind == Kind::too_many)
        return std::to_string(balls.size()) + " balls, more than the " +
               std::to_string(max_world_balls) + " a table holds";
    const Ball& b = balls[problem.ball];
    const std::string at = name(problem.ball, false) + " at " + position_text(b.position);
    switch (problem.kind) {
    case Kind::off_table:
        return at + " is off the table";
    case Kind::overlap:
        return at + " overlaps " + name(problem.other, true);
    case Kind::same_id:
        return "duplicate " + name(problem.ball, false);
    case Kind::not_finite:
        return name(problem.ball, false) +
               ": its position, velocity and spin must be finite numbers";
    case Kind::bad_mass:
        return name(problem.ball, false) + ": mass must be > 0 (got " + format_double(b.mass) + ")";
    case Kind::too_fast:
        return name(problem.ball, false) + " moves faster than " + format_double(max_strike_speed) +
               " m/s or spins faster than " + format_double(max_ball_spin) + " rad/s";
    case Kind::at_rest_but_moving:
        return name(problem.ball, false) + " is " + motion_state_name(b.state) +
               " but has a velocity or spin that state does not allow";
    case Kind::too_many:
        break;
    }
    return "";
}

} // namespace termpool
