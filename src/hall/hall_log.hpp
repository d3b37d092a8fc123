#pragma once
/// \file
/// The hall server's log: every line starts with its time in UTC (ISO 8601, to the
/// millisecond: `2026-12-03T21:04:05.123Z termpool hall: ...`), a line a client can make again
/// and again (a sync, say) is rate-limited per client and kind, and a log file is capped: a
/// line that would take it past the cap first renames it to PATH.1 (over the one before), so
/// the log never takes more than twice the cap on disk.

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>

#include "hall/unique_fd.hpp"

namespace termpool::hall {

/// How a hall's log is kept.
struct HallLogOptions {
    /// The file appended to (made with mode 0600, never through a symbolic link); empty:
    /// `stream`.
    std::string path;
    std::ostream* stream = nullptr; ///< where lines go without a path (nowhere when null too)
    /// Bytes a log file may reach; a line that would take it past this renames it to PATH.1
    /// first (0: never).
    std::uint64_t cap_bytes = 1024 * 1024;
    /// Lines of one kind about one client written at once; after them, one every
    /// `repeat_interval`, and the next one written says how many were left out.
    double burst = 10;
    std::chrono::seconds repeat_interval{60}; ///< see burst
    /// The time of each line and of the rate limit (tests set it; default the system's).
    std::function<std::chrono::system_clock::time_point()> clock;
};

/// A hall's log. Callable from any thread.
class HallLog {
public:
    /// A log as `options` says; a file is opened by `open`.
    explicit HallLog(HallLogOptions options);
    /// A log to `stream`, with the default limits.
    explicit HallLog(std::ostream& stream);
    /// Opens the file (when the options name one): "" or why not.
    std::string open();
    /// Writes `line`.
    void write(std::string_view line);
    /// Writes `line`, a line of `kind` about `client`, unless that client's lines of that kind
    /// have spent their budget (HallLogOptions::burst): then it is counted, and told of later.
    void write_repeated(int client, std::string_view kind, std::string_view line);
    /// Lines left out so far (for tests and the figures).
    std::uint64_t left_out() const;

    /// `time` as ISO 8601 in UTC to the millisecond: 2026-12-03T21:04:05.123Z.
    static std::string timestamp(std::chrono::system_clock::time_point time);

private:
    using Key = std::pair<int, std::string>; // the client and the kind of line
    struct Budget {
        double tokens = 0;
        std::chrono::system_clock::time_point last; // when tokens were counted
        std::uint64_t left_out = 0;                 // lines not written since the last one
    };
    std::chrono::system_clock::time_point now() const;
    bool refill(Budget& budget, std::chrono::system_clock::time_point at) const;
    void sweep(std::chrono::system_clock::time_point at);
    void emit(std::chrono::system_clock::time_point at, std::string_view line);
    void rotate_if_full(std::size_t adding);
    static std::string left_out_line(const Key& key, std::uint64_t count);

    HallLogOptions options_;
    mutable std::mutex mutex_;
    UniqueFd file_;
    std::map<Key, Budget> budgets_;
    std::chrono::system_clock::time_point last_sweep_{};
    std::uint64_t left_out_ = 0;
};

} // namespace termpool::hall
