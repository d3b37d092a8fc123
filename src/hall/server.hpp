#pragma once
/// \file
/// The hall's server: tables of Matches, the people at them, one Unix stream socket. It is
/// authoritative: every action is validated and applied by the table's Match, saved, then sent
/// to everyone at the table with the state hash after it.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "hall/hall_log.hpp"

namespace termpool::hall {

/// How a server runs.
struct ServerOptions {
    std::string socket_path; ///< where to listen (the folder must exist)
    std::string state_dir;   ///< where tables are saved and restored from; empty: nowhere
    /// People (connections that said hello) at most. One more is let in by closing the
    /// connection idle longest in the lobby (at no table, nothing said for lobby_idle_limit),
    /// which is told why; with none such, the newcomer is told "full" and closed.
    int max_clients = 256;
    /// A person in the lobby who has said nothing (pings aside) for this long may give way to
    /// a newcomer when the hall is full (max_clients).
    std::chrono::milliseconds lobby_idle_limit = std::chrono::minutes(5);
    /// Connections not yet past hello at most: one more closes the one that has waited
    /// longest, which is told "full".
    int max_unwelcomed = 32;
    /// A connection that has not said hello within this is closed.
    std::chrono::milliseconds hello_timeout{10000};
    int max_tables = 100; ///< tables beyond this are refused
    /// Tables one person may hold in any state (waiting, under way, with an away seat, not
    /// over): those they created or hold a seat of. A person is a name (compared by name_key:
    /// NFKC, case folded) or a token, so a new token per hello holds no more; beyond, create and
    /// sit are refused ("full").
    int max_tables_per_person = 3;
    /// The last free tables, this many at most and a tenth of max_tables (rounded up) at
    /// most, are kept for people who hold none: someone holding a table cannot create one of
    /// them ("full").
    int reserved_tables = 10;
    /// A table nobody is at (its seats away, empty or the computer's) with no action for this
    /// long is archived: its file moves to archive/ in the state folder (table-N.save, then
    /// .1, .2, ... never over another) and it leaves the lobby (hall serve --archive-after).
    std::chrono::milliseconds archive_after = std::chrono::hours(24);
    /// Tables not started yet that one token may have created; more are refused ("full"). A
    /// table nobody sits at or watches goes when its creator disconnects, and any table not
    /// started goes when the last person leaves it.
    int max_waiting_tables = 3;
    /// How long a seat in a game under way waits for its owner, away, before it is freed (and
    /// a table left with nobody goes). A restored seat counts from its table file's last
    /// change (its mtime: the file is rewritten on every change of the table), so a restart
    /// does not give it more time; a seat of a restored game not started is freed at once.
    std::chrono::milliseconds away_limit = std::chrono::hours(7 * 24);
    /// Bytes queued for one client beyond which it is disconnected (it stopped reading), not
    /// counting what is left of a record's allowance (record_allowance).
    std::size_t output_limit = 256 * 1024;
    /// A table's record goes to a joining client as one bulk whose first this many bytes count
    /// against output_limit only once written late: the client that reads gets it whole. The
    /// largest record at max_actions 5000 takes at most 850 KB on the wire (5000 lines of at
    /// most 170 bytes); a realistic one of 8-ball shots with spin and calls, 613 KB of text.
    std::size_t record_allowance = 1024 * 1024;
    int max_errors = 10;          ///< error replies in a row before a client is cut
    double error_rate = 1.0 / 30; ///< errors forgiven a second (one every 30 s)
    int computer_threads = 2;     ///< the computer seats' worker pool
    /// Threads (the loop's own among them) that save the tables a round's actions changed,
    /// side by side: a save waits for the disk.
    int save_threads = 8;
    std::chrono::milliseconds aim_interval{50};    ///< at most one aim per seat this often
    std::chrono::milliseconds chat_interval{1000}; ///< at most one chat per person this often
    /// The lobby's changes go out as one snapshot at most this often.
    std::chrono::milliseconds lobby_interval{250};
    /// A client whose output queue holds more than this gets the next snapshot only once it has
    /// read it down: a slow reader is not buried in lobbies.
    std::size_t lobby_queue_limit = 16 * 1024;
    /// create, sit, watch, leave and sync: at most `request_burst` at once, `request_rate` a
    /// second after that; beyond, "rate" (which counts as an error).
    double request_rate = 5;
    double request_burst = 20; ///< see request_rate
    /// Actions (act, next-rack) from one seat: at most `action_burst` at once, `action_rate`
    /// a second after that; beyond, "rate" (which counts as an error).
    double action_rate = 20;
    double action_burst = 40; ///< see action_rate
    /// Lines of one client handled in one round of the poll loop; the rest wait for the next
    /// round, after the other clients' turn.
    int lines_per_round = 32;
    /// Actions one table's record may hold (a game of pool takes a few hundred); beyond, an
    /// action is refused, so that a record cannot grow without end.
    std::size_t max_actions = 5000;
    /// The server exits once nothing has kept it for this long (0: never): no connection, no
    /// computer's search, no save waiting, and no table that lives only in memory (with a
    /// state folder every table is on disk and restored by the next server; without one, a
    /// table keeps the server). A hall `termpool hall` starts in the background runs with 60 s.
    std::chrono::seconds idle_exit{0};
    /// Where the racks' deals and the computers' seeds come from: the system's randomness when
    /// empty; with a seed, the same deals in the same order on every run (tests, which must not
    /// meet by chance a rack that ends at once). Seat tokens never come from it.
    std::optional<std::uint64_t> deal_seed;
    HallLog* log = nullptr; ///< where to log (nothing when null)
};

/// A hall server. `open`, then `run` until `stop`.
class Server {
public:
    /// A server that is not listening yet.
    explicit Server(ServerOptions options);
    /// Closes every socket, removes the socket file when it made one, joins its threads.
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    /// Restores the saved tables and listens on the socket; "" or why not. A socket file left
    /// by a server that is gone is replaced; one a server answers on is refused.
    std::string open();
    /// Serves until `stop`, then saves every table; returns 0 (1 if a save failed).
    int run();
    /// Asks `run` to return; callable from any thread and from a signal handler.
    void stop();

    /// Tables held (for tests and the log).
    std::size_t table_count() const;
    /// Rounds of the poll loop so far, one per return of poll (for tests: a loop that spins
    /// shows as rounds without end).
    std::size_t rounds() const;
    /// Times accept failed for want of file descriptors (or memory) and the listener was left
    /// out of poll for a while (for tests).
    std::size_t accept_pauses() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace termpool::hall
