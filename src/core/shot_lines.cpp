// Lines of play: what lies in a ball's way.
#include "shot_lines.hpp"

#include <algorithm>

namespace termpool {

const Ball* ball_in_play(const std::vector<Ball>& balls, int id) {
    for (const Ball& b : balls)
        if (b.id == id && b.state != MotionState::pocketed)
            return &b;
    return nullptr;
}

bool path_blocked(const std::vector<Ball>& balls, Vec2 a, Vec2 b, std::pair<int, int> ignore,
                  double R) {
    const Vec2 ab = b - a;
    const double len2 = length_squared(ab);
    for (const Ball& ball : balls) {
        if (ball.state == MotionState::pocketed || ball.id == ignore.first ||
            ball.id == ignore.second)
            continue;
        const double u = len2 > 0 ? std::clamp(dot(ball.position - a, ab) / len2, 0.0, 1.0) : 0;
        if (length_squared(a + ab * u - ball.position) < 4 * R * R)
            return true;
    }
    return false;
}

} // namespace termpool
