#pragma once
/// \file
/// One client's socket as the server's poll loop sees it: bytes in, cut into lines no longer
/// than the protocol allows; bytes out, queued up to a bound so that a client that stops
/// reading cannot make the server buffer without end.
///
/// The bound counts what the client failed to read, not what the server chose to send at once:
/// a table's record, longer than the bound at the action limit, goes as one bulk with an
/// allowance of its own that shrinks as it is written. One bulk at a time: a second one while
/// the first still waits counts in full, so a client cannot make the server hold many records.

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
    /// Queues `bytes` to send; false when the queue now holds more than `limit` bytes beyond
    /// what is left of a bulk's allowance (see `owed`).
    bool queue(std::string_view bytes, std::size_t limit);
    /// Queues `bytes` as one bulk: its first `allowance` bytes are not counted against `limit`
    /// while they wait to be written. Granted only when no earlier bulk's allowance is left
    /// unwritten; otherwise `bytes` count in full. False as for `queue`.
    bool queue_bulk(std::string_view bytes, std::size_t limit, std::size_t allowance);
    /// Writes what the socket takes now; false when the socket failed.
    bool flush();
    /// True while bytes wait to be sent.
    bool wants_write() const { return sent_ < out_.size(); }
    /// Bytes waiting to be sent.
    std::size_t queued() const { return out_.size() - sent_; }
    /// Bytes waiting to be sent, less what is left of a bulk's allowance: what counts against
    /// the limit, the bytes the client failed to read.
    std::size_t owed() const { return queued() - allowance_left(); }

private:
    UniqueFd fd_;
    std::string in_;                // the line being read, not complete yet
    std::deque<std::string> lines_; // complete lines not handled yet
    std::string out_;
    std::size_t sent_ = 0; // bytes of out_ already written
    // Counted from the connection's first byte queued: bytes written so far, and where the
    // allowance of the last bulk starts and ends.
    std::size_t written_ = 0;
    std::size_t bulk_start_ = 0;
    std::size_t bulk_end_ = 0;
    std::size_t allowance_left() const;
};

} // namespace termpool::hall
