#pragma once
/// \file
/// How long a client whose hall went away waits before each try to reconnect: soon at first
/// (a restarted server is back within a second), then less and less often, never more than
/// 5 s apart, so that a hall that is down for long is not hammered and one that comes back is
/// found quickly. Pure: the caller sleeps, connects, and resets on success.

#include <algorithm>
#include <chrono>

namespace termpool::hall {

/// The waits before reconnect tries: 0.25, 0.5, 1, 2, 4, then 5 s each.
class ReconnectBackoff {
public:
    /// The first wait.
    static constexpr std::chrono::milliseconds first{250};
    /// The longest wait.
    static constexpr std::chrono::milliseconds longest{5000};

    /// The wait before the next try; each call moves one step along the schedule.
    std::chrono::milliseconds next() {
        const std::chrono::milliseconds wait = current_;
        current_ = std::min(longest, current_ * 2);
        ++tries_;
        return wait;
    }
    /// Back to the start of the schedule (after a connection succeeded).
    void reset() {
        current_ = first;
        tries_ = 0;
    }
    /// The waits handed out since the last reset: the tries that failed so far.
    int tries() const { return tries_; }

private:
    std::chrono::milliseconds current_ = first;
    int tries_ = 0;
};

} // namespace termpool::hall
