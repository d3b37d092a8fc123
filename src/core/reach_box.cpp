#include "reach_box.hpp"

namespace termpool::core {
namespace {

// Range of x0 + v t + a t^2 / 2 over [0, T].
void extend_range(double x0, double v, double a, double T, double& lo, double& hi) {
    auto at = [&](double t) { return x0 + v * t + 0.5 * a * t * t; };
    lo = hi = x0;
    const double end = at(T);
    lo = std::min(lo, end);
    hi = std::max(hi, end);
    if (a != 0) {
        const double t_turn = -v / a;
        if (t_turn > 0 && t_turn < T) {
            lo = std::min(lo, at(t_turn));
            hi = std::max(hi, at(t_turn));
        }
    }
}

} // namespace

Box path_box(const Path& path, double duration) {
    Box box;
    extend_range(path.position.x, path.velocity.x, path.acceleration.x, duration, box.min.x,
                 box.max.x);
    extend_range(path.position.y, path.velocity.y, path.acceleration.y, duration, box.min.y,
                 box.max.y);
    return box;
}

Box physical_reach(const MotionPiece& piece, double duration, const PhysicsParams&) {
    const Ball& b = piece.ball;
    return path_box({b.position, b.velocity, piece.acceleration, duration}, duration);
}

Box classic_reach(const MotionPiece& piece, double duration, const PhysicsParams& params,
                  AdvanceFn advance) {
    const Ball& b = piece.ball;
    return box_of(b.position, advance(b, duration, params).position);
}

} // namespace termpool::core
