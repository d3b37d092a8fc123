#pragma once
// The computer's turn shown like a player's: it thinks a moment before a choice or a
// placement, turns the cue to its aim over a second, fills the power bar, then shoots.

#include <chrono>
#include <optional>
#include <termpool/record.hpp>

namespace termpool::tui {

/// The move the computer is showing and how far along it is.
class ComputerPacing {
public:
    using Clock = std::chrono::steady_clock;

    /// Seconds before a choice is made.
    static constexpr double choose_after = 1.0;
    /// Seconds before the cue ball is put down.
    static constexpr double place_after = 0.7;
    /// Seconds the cue takes to turn to the aim, then the bar to fill, then until the shot.
    static constexpr double turn_time = 1.0, fill_time = 0.5, shoot_after = 1.7;

    /// True while a move is being shown.
    bool showing() const { return move_.has_value(); }
    /// Starts showing `move`, with the cue at `aim_from_deg` now.
    void start(const RecordedAction& move, double aim_from_deg, Clock::time_point now);
    /// Ends the show (the move is made, or the game moved on).
    void stop() { move_.reset(); }
    /// Seconds since the show started.
    double elapsed(Clock::time_point now) const;
    /// True once the move is due.
    bool due(Clock::time_point now) const;
    /// The cue's direction at `t` seconds: it turns the shorter way round to the aim.
    double aim_at(double t) const;
    /// The power bar at `t` seconds, for a strike speed of the shot (the bar's top is 12 m/s
    /// for a break, 7 m/s otherwise).
    double power_at(double t, bool is_break) const;

private:
    std::optional<RecordedAction> move_;
    Clock::time_point start_;
    double aim_from_ = 0;
};

} // namespace termpool::tui
