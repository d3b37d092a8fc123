#pragma once
/// \file
/// One client's socket as the server's poll loop sees it: bytes in, cut into lines no longer
/// than the protocol allows; bytes out, queued up to a bound so that a client that stops
/// reading cannot make the server buffer without end.

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>

#include "hall/unique_fd.hpp"

namespace termpool::hall {

/// A non-blocking stream socket with an input line buffer and a bounded output queue.
class Connection {
public:
    /// What a read found.
    enum class ReadResult {
        ok,       ///< zero or more lines
        closed,   ///< the peer closed, or the socket failed
        too_long, ///< a line longer than max_line_bytes: the connection must end
    };

    /// Takes `fd` (already non-blocking).
    explicit Connection(UniqueFd fd) : fd_(std::move(fd)) {}

    /// The socket.
    int fd() const { return fd_.get(); }
    /// Reads once (what the socket holds, up to 64 KiB) and keeps each complete line, without
    /// its '\n', for `take_line`.
    ReadResult read();
    /// True while a complete line read waits to be handled.
    bool has_line() const { return !lines_.empty(); }
    /// The oldest complete line read (there must be one).
    std::string take_line();
    /// Queues `bytes` to send; false when the queue now holds more than `limit` bytes.
    bool queue(std::string_view bytes, std::size_t limit);
    /// Writes what the socket takes now; false when the socket failed.
    bool flush();
    /// True while bytes wait to be sent.
    bool wants_write() const { return sent_ < out_.size(); }
    /// Bytes waiting to be sent.
    std::size_t queued() const { return out_.size() - sent_; }

private:
    UniqueFd fd_;
    std::string in_;                // the line being read, not complete yet
    std::deque<std::string> lines_; // complete lines not handled yet
    std::string out_;
    std::size_t sent_ = 0; // bytes of out_ already written
};

} // namespace termpool::hall
