#pragma once
/// \file
/// A headless hall client: connects to the server's socket, says hello, sends messages, reads
/// and parses the server's lines, and follows tables. A followed table is a local Match built
/// from the record the server sends on join; each broadcast action is applied to it with Match
/// and its state hash checked; on a mismatch the client asks `sync` and rebuilds from the
/// record. Used by the tests and by `termpool hall bench`; the terminal client builds on it.

#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <termpool/match.hpp>

#include "hall/protocol.hpp"
#include "hall/server_bounds.hpp"
#include "hall/unique_fd.hpp"

namespace termpool::hall {

/// One connection to a hall.
class HallClient {
public:
    /// Connects to the server at `socket_path`; "" or why not.
    std::string connect(const std::string& socket_path);
    /// Sends `message`; false once the connection is gone.
    bool send(const ClientMessage& message);
    /// Sends raw bytes (tests send garbage with it); false once the connection is gone.
    bool send_raw(std::string_view bytes);
    /// The next message, waiting at most `timeout`; nothing on timeout, on a line that does not
    /// read (counted in `bad_lines`), or once the server closed. Followed tables take it first.
    std::optional<ServerMessage> receive(std::chrono::milliseconds timeout);
    /// Receives until `done` says yes to a message, for at most `timeout` in all; that message,
    /// or nothing.
    std::optional<ServerMessage> wait_for(const std::function<bool(const ServerMessage&)>& done,
                                          std::chrono::milliseconds timeout);
    /// Sends hello and waits (at most `timeout`) for welcome; the error's text, or "".
    std::string hello(const std::string& name, const std::string& token,
                      std::chrono::milliseconds timeout);
    /// Closes the connection.
    void disconnect() { fd_.reset(); }
    /// The process id of the server at the other end (SO_PEERCRED: the process that made its
    /// socket listen), 0 when not connected.
    pid_t server_pid() const;

    /// True once the server closed the connection (or it was never open).
    bool closed() const { return !fd_; }
    /// The socket, to wait on beside other input (-1 when closed).
    int fd() const { return fd_ ? fd_.get() : -1; }
    /// True when a whole line is read already: `receive(0)` gives it without the socket.
    bool line_waiting() const { return in_.find('\n') != std::string::npos; }
    /// Whether `receive` follows tables: keeps their copies, `table()` and `seat()` (default:
    /// yes). A front end that plays each action itself turns it off rather than simulate every
    /// shot twice.
    void keep_copies(bool keep) { keep_copies_ = keep; }
    /// The token from welcome.
    const std::string& token() const { return token_; }
    /// The table this client sits at or watches (0: none) and its seat (0: watching).
    int table() const { return table_; }
    /// The seat at `table()`: 1 or 2, 0 watching.
    int seat() const { return seat_; }
    /// The local copy of table `number`'s match, once its record came; nullptr before.
    const Match* match(int number) const;
    /// Hash or sequence mismatches seen (each one asked a sync).
    int mismatches() const { return mismatches_; }
    /// Lines from the server that did not read.
    int bad_lines() const { return bad_lines_; }
    /// Why the connection was ended for the server's sending more than a hall sends (a record,
    /// a lobby: ServerBounds), as "the hall is broken: ..."; "" when it was not.
    const std::string& broken() const { return broken_; }
    /// The bounds on what the server may send, for a new connection (tests set them low).
    void set_bounds(ServerBoundLimits limits) { bounds_ = ServerBounds(limits); }

private:
    struct Followed {
        std::string record_text;    // the record's lines so far
        std::optional<Match> match; // nothing until a record ends, or while resyncing
    };
    void follow(const ServerMessage& message);
    void resync(int number, Followed& followed);

    UniqueFd fd_;
    std::string in_;
    std::string token_;
    int table_ = 0;
    int seat_ = 0;
    std::map<int, Followed> followed_;
    int mismatches_ = 0;
    int bad_lines_ = 0;
    bool keep_copies_ = true;
    ServerBounds bounds_;
    std::string broken_;
};

} // namespace termpool::hall
