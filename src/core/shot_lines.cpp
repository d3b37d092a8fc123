// Lines of play: what lies in a ball's way.
#include "shot_lines.hpp"

#include "../support/portable_math.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace termpool {

const Ball* ball_in_play(const std::vector<Ball>& balls, int id) {
    for (const Ball& b : balls)
        if (b.id == id && b.state != MotionState::pocketed)
            return &b;
    return nullptr;
}

bool path_blocked(const std::vector<Ball>& balls, Vec2 a, Vec2 b, std::pair<int, int> ignore,
                  double R) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const Vec2 ab = b - a;
    const double len2 = length_squared(ab);
    // A ball outside the segment's box grown by 2R is clear of it: most are, and skip the
    // division. The margin covers the rounding of the nearest point and of the squares, a few
    // units in the last place of the largest coordinate and of R (a nanometre at least); a
    // radius that is not positive grows no box, and every ball is tested.
    const double largest =
        std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y)});
    const double reach = R > 0 ? 2 * R * (1 + 1e-12) + 1e-9 + 1e-12 * largest : infinity;
    const Vec2 lo{std::min(a.x, b.x) - reach, std::min(a.y, b.y) - reach};
    const Vec2 hi{std::max(a.x, b.x) + reach, std::max(a.y, b.y) + reach};
    for (const Ball& ball : balls) {
        if (ball.state == MotionState::pocketed || ball.id == ignore.first ||
            ball.id == ignore.second)
            continue;
        if (ball.position.x < lo.x || ball.position.x > hi.x || ball.position.y < lo.y ||
            ball.position.y > hi.y)
            continue;
        const double u = len2 > 0 ? std::clamp(dot(ball.position - a, ab) / len2, 0.0, 1.0) : 0;
        if (length_squared(a + ab * u - ball.position) < 4 * R * R)
            return true;
    }
    return false;
}

std::optional<Vec2> open_pot_line(const std::vector<Ball>& balls, Vec2 cue, const Ball& object,
                                  Vec2 aim_point, double min_cut, double R) {
    const Vec2 to_aim = aim_point - object.position;
    const Vec2 ghost = object.position - normalized(to_aim) * (2 * R);
    const Vec2 line = ghost - cue;
    if (dot(normalized(line), normalized(to_aim)) < min_cut ||
        path_blocked(balls, cue, ghost, {0, object.id}, R) ||
        path_blocked(balls, object.position, aim_point, {0, object.id}, R))
        return std::nullopt;
    return line;
}

double aim_degrees(Vec2 v) {
    return portable::atan2(v.y, v.x) * 180 / std::numbers::pi;
}

std::array<Vec2, 4> rail_mirrors(const Table& table, Vec2 point, double R) {
    return {{{point.x, 2 * R - point.y},
             {point.x, 2 * (table.width - R) - point.y},
             {2 * R - point.x, point.y},
             {2 * (table.length - R) - point.x, point.y}}};
}

} // namespace termpool
