#include <termpool/practice.hpp>
#include <termpool/spots.hpp>

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
    return on_playing_surface(table_, spot, R) && ball_touching(balls_, spot, R, id) < 0;
}

bool PracticeTable::put(int id, Vec2 spot) {
    if (!can_put(id, spot))
        return false;
    for (Ball& b : balls_) {
        if (b.id != id)
            continue;
        set_at_rest(b, spot);
        return true;
    }
    return false;
}

Vec2 PracticeTable::free_spot_near(int id, Vec2 wanted) const {
    return free_spot_on_string(table_, balls_, wanted, params_.ball_radius, id).value_or(wanted);
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
