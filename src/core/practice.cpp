#include <termpool/practice.hpp>

#include <algorithm>

namespace termpool {

PracticeTable::PracticeTable(const Table& table, const PhysicsParams& params, RackType rack,
                             std::uint64_t seed)
    : table_(table), params_(params), rack_(rack) {
    rerack(seed);
}

void PracticeTable::rerack(std::uint64_t seed) {
    balls_ = make_rack(table_, params_, rack_, game_rack_seed(seed, 0));
    before_shot_.reset();
    is_break_ = was_break_ = true;
}

bool PracticeTable::can_put(int id, Vec2 spot) const {
    const double R = params_.ball_radius;
    if (!on_playing_surface(table_, spot, R))
        return false;
    return std::none_of(balls_.begin(), balls_.end(), [&](const Ball& b) {
        return b.id != id && b.state != MotionState::pocketed &&
               length_squared(b.position - spot) < 4 * R * R;
    });
}

bool PracticeTable::put(int id, Vec2 spot) {
    if (!can_put(id, spot))
        return false;
    for (Ball& b : balls_) {
        if (b.id != id)
            continue;
        const double mass = b.mass;
        b = Ball{};
        b.id = id;
        b.mass = mass;
        b.position = spot;
        return true;
    }
    return false;
}

Vec2 PracticeTable::free_spot_near(int id, Vec2 wanted) const {
    // Along the long string towards the foot, as a spotted ball is placed; then back towards
    // the head. A full table always leaves some spot on that line in practice.
    const double step = params_.ball_radius / 4;
    for (double d = 0; d < table_.length; d += step)
        for (const double x : {wanted.x + d, wanted.x - d})
            if (can_put(id, {x, wanted.y}))
                return {x, wanted.y};
    return wanted;
}

ShotResult PracticeTable::shoot(const Strike& strike, Trajectory* trajectory) {
    before_shot_ = balls_;
    was_break_ = is_break_;
    ShotResult result = simulate_shot(table_, params_, balls_, strike, trajectory);
    balls_ = result.balls;
    is_break_ = false;
    for (const Ball& b : balls_)
        if (b.id == 0 && b.state == MotionState::pocketed)
            put(0, free_spot_near(0, table_.head_spot()));
    return result;
}

bool PracticeTable::retake() {
    if (!before_shot_)
        return false;
    balls_ = *before_shot_;
    is_break_ = was_break_;
    before_shot_.reset();
    return true;
}

} // namespace termpool
