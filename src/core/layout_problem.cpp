#include <termpool/simulator.hpp>

namespace termpool {

std::optional<LayoutProblem> layout_problem(const Table& table, const std::vector<Ball>& balls,
                                            double radius) {
    // Rack balls are packed with a gap that their jitter may close, so touching is allowed.
    constexpr double tolerance = 1e-9;
    using Kind = LayoutProblem::Kind;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Ball& b = balls[i];
        for (std::size_t j = 0; j < i; ++j)
            if (balls[j].id == b.id)
                return LayoutProblem{Kind::same_id, i, j};
        if (b.state == MotionState::pocketed)
            continue;
        if (!on_playing_surface(table, b.position, radius))
            return LayoutProblem{Kind::off_table, i, i};
        for (std::size_t j = 0; j < i; ++j)
            if (balls[j].state != MotionState::pocketed &&
                length(b.position - balls[j].position) < 2 * radius - tolerance)
                return LayoutProblem{Kind::overlap, i, j};
    }
    return std::nullopt;
}

} // namespace termpool
