#include <termpool/spots.hpp>

namespace termpool {

int ball_touching(const std::vector<Ball>& balls, Vec2 p, double R, int except_id) {
    for (const Ball& b : balls)
        if (b.id != except_id && b.state != MotionState::pocketed &&
            length_squared(b.position - p) < 4 * R * R)
            return b.id;
    return -1;
}

std::optional<Vec2> free_spot_on_string(const Table& table, const std::vector<Ball>& balls,
                                        Vec2 from, double R, int id) {
    constexpr double step = 0.0005;
    for (double x = from.x; x <= table.length - R; x += step)
        if (ball_touching(balls, {x, from.y}, R, id) < 0)
            return Vec2{x, from.y};
    for (double x = from.x - step; x >= R; x -= step)
        if (ball_touching(balls, {x, from.y}, R, id) < 0)
            return Vec2{x, from.y};
    return std::nullopt;
}

void set_at_rest(Ball& ball, Vec2 p) {
    const int id = ball.id;
    const double mass = ball.mass;
    ball = Ball{};
    ball.id = id;
    ball.mass = mass;
    ball.position = p;
}

} // namespace termpool
