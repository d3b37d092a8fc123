#include "tui/computer_pacing.hpp"

#include <algorithm>
#include <cmath>

#include "tui/aim.hpp"

namespace termpool::tui {

void ComputerPacing::start(const RecordedAction& move, double aim_from_deg, Clock::time_point now) {
    move_ = move;
    aim_from_ = aim_from_deg;
    start_ = now;
}

double ComputerPacing::elapsed(Clock::time_point now) const {
    return std::chrono::duration<double>(now - start_).count();
}

bool ComputerPacing::due(Clock::time_point now) const {
    const double t = elapsed(now);
    switch (move_->kind) {
    case RecordedAction::Kind::choose:
        return t >= choose_after;
    case RecordedAction::Kind::place:
        return t >= place_after;
    default:
        return t >= shoot_after;
    }
}

double ComputerPacing::aim_at(double t) const {
    const double delta = std::remainder(move_->strike.angle_deg - aim_from_, 360.0);
    return turn(aim_from_, delta * std::min(1.0, t / turn_time));
}

double ComputerPacing::power_at(double t, bool is_break) const {
    return power_from_speed(move_->strike.speed, is_break) *
           std::clamp((t - turn_time) / fill_time, 0.0, 1.0);
}

} // namespace termpool::tui
