#pragma once
/// \file
/// A token bucket: at most `burst` events at once, refilled at `rate` a second. The hall keeps
/// one per connection for its requests and one per seat for its actions, so that one client
/// cannot flood the others' tables.

#include <algorithm>
#include <chrono>
#include <optional>

namespace termpool::hall {

/// Events allowed now, refilled with time.
class TokenBucket {
public:
    using Clock = std::chrono::steady_clock;

    /// True (and one token spent) when an event may happen at `now`; a bucket starts full.
    bool take(double rate, double burst, Clock::time_point now) {
        if (!last_)
            tokens_ = burst;
        else
            tokens_ = std::min(
                burst, tokens_ + rate * std::chrono::duration<double>(now - *last_).count());
        last_ = now;
        if (tokens_ < 1)
            return false;
        tokens_ -= 1;
        return true;
    }

private:
    double tokens_ = 0;
    std::optional<Clock::time_point> last_;
};

} // namespace termpool::hall
