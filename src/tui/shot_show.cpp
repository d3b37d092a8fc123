// A shot rolling on screen: the balls sampled from the trajectory until the shot's rest time.

#include "tui/shot_show.hpp"

namespace termpool::tui {

void ShotShow::start(PlayedShot shot, Trajectory trajectory, std::optional<Game> before,
                     const MatchState& score_before, Clock::time_point now) {
    shot_ = std::move(shot);
    trajectory_ = std::move(trajectory);
    before_ = std::move(before);
    score_before_ = score_before;
    start_ = now;
    balls_ = trajectory_->sample(0);
}

bool ShotShow::advance(Clock::time_point now) {
    if (!trajectory_)
        return true;
    const double t = std::chrono::duration<double>(now - start_).count();
    if (t >= shot_.result.rest_time)
        return true;
    balls_ = trajectory_->sample(t);
    return false;
}

} // namespace termpool::tui
