#pragma once
// The one way a test waits: for a condition, bounded in time, never for a fixed sleep.

#include <chrono>
#include <functional>
#include <thread>

namespace termpool::test {

/// Polls `ok` every `poll` until it holds; false after `seconds`. It returns as soon as the
/// condition holds: the bound is only a deadline for a program that never gets there.
inline bool wait_until(const std::function<bool()>& ok, double seconds,
                       std::chrono::microseconds poll = std::chrono::milliseconds(20)) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        if (ok())
            return true;
        if (std::chrono::steady_clock::now() >= end)
            return false;
        std::this_thread::sleep_for(poll);
    }
}

} // namespace termpool::test
