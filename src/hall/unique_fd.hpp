#pragma once
/// \file
/// A file descriptor that closes itself: sockets and pipes of the hall never leak, whatever
/// path a function leaves by.

#include <unistd.h>
#include <utility>

namespace termpool::hall {

/// Owns one file descriptor (or none: -1) and closes it when destroyed.
class UniqueFd {
public:
    UniqueFd() = default;
    /// Takes ownership of `fd` (-1 for none).
    explicit UniqueFd(int fd) : fd_(fd) {}
    ~UniqueFd() { reset(); }
    UniqueFd(UniqueFd&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    UniqueFd& operator=(UniqueFd&& other) noexcept {
        if (this != &other) {
            reset();
            fd_ = std::exchange(other.fd_, -1);
        }
        return *this;
    }
    UniqueFd(const UniqueFd&) = delete;
    UniqueFd& operator=(const UniqueFd&) = delete;

    /// The descriptor, -1 for none.
    int get() const { return fd_; }
    /// True when it holds a descriptor.
    explicit operator bool() const { return fd_ >= 0; }
    /// Closes the descriptor held, if any.
    void reset() {
        if (fd_ >= 0)
            ::close(fd_);
        fd_ = -1;
    }

private:
    int fd_ = -1;
};

/// Sets O_NONBLOCK and FD_CLOEXEC on `fd`; false if fcntl failed.
bool make_nonblocking(int fd);

/// A pipe whose ends are non-blocking and close-on-exec: how other threads and signal handlers
/// wake a poll loop (POSIX has no eventfd).
struct WakePipe {
    UniqueFd read_end;  ///< polled for input
    UniqueFd write_end; ///< one byte written wakes the poller
    /// Opens the pipe; false if pipe(2) failed.
    bool open();
    /// Wakes the poller; async-signal-safe.
    void wake() const;
    /// Reads away every pending byte.
    void drain() const;
};

} // namespace termpool::hall
