#pragma once
// A shot rolling on screen. The match (or the practice table) has played it already: the
// game and score as they were show until the balls stop, and then the verdict is told.

#include <chrono>
#include <optional>
#include <termpool/match.hpp>
#include <vector>

namespace termpool::tui {

/// The shot being shown, from the first frame until its balls come to rest.
class ShotShow {
public:
    using Clock = std::chrono::steady_clock;

    /// Starts showing `shot` along `trajectory` at `now`; `before` and `score_before` are the
    /// game and the score as they stood before it (none in practice: no referee).
    void start(PlayedShot shot, Trajectory trajectory, std::optional<Game> before,
               const MatchState& score_before, Clock::time_point now);
    /// Moves the balls shown on to `now`; true once they have come to rest.
    bool advance(Clock::time_point now);
    /// The balls come to rest at once (x, a click, a terminal that fell behind).
    void hurry() { start_ -= std::chrono::hours(1); }
    /// The balls as shown now.
    const std::vector<Ball>& balls() const { return balls_; }
    /// The shot shown (or last shown): who played it, the verdict, the simulation.
    const PlayedShot& shot() const { return shot_; }
    /// The game as it stood before the shot (null when the driver gave none).
    const Game* before() const { return before_ ? &*before_ : nullptr; }
    /// The score as it stood before the shot.
    const MatchState& score_before() const { return score_before_; }

private:
    PlayedShot shot_;
    std::optional<Trajectory> trajectory_;
    std::optional<Game> before_;
    MatchState score_before_;
    Clock::time_point start_;
    std::vector<Ball> balls_;
};

} // namespace termpool::tui
