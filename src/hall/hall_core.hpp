#pragma once
/// \file
/// The hall without its sockets: tables of Matches, the people at them, their seats, the
/// lobby, the computer seats and the saves. It takes what each client says, by the client's
/// id, and answers into an outbox of (client id, lines) and "end this connection" requests,
/// which the connection layer (server.cpp, server_connections.cpp) turns into bytes. The
/// clock is the caller's: every call takes `now`, so that tests drive it with a fake clock.
///
/// One thread calls it; the computer pool's and the save crew's workers see only what is
/// handed to them.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <string_view>
#include <termpool/match.hpp>
#include <utility>
#include <vector>

#include "hall/computer_pool.hpp"
#include "hall/hall_state.hpp"
#include "hall/latency_histogram.hpp"
#include "hall/protocol.hpp"
#include "hall/server.hpp"
#include "hall/token_bucket.hpp"
#include "hall/work_crew.hpp"

namespace termpool::hall {

/// What the hall says to one client: protocol lines, and whether its connection ends after them.
struct Outgoing {
    int client = 0;     ///< the client's id (as given to HallCore::on_connect)
    std::string text;   ///< whole protocol lines, each ending in '\n' (may be empty)
    bool close = false; ///< end the connection once `text` is sent
    /// `text` is a table's record, queued as one bulk with an allowance of its own
    /// (ServerOptions::record_allowance, Connection::queue_bulk).
    bool bulk = false;
};

namespace serving {

using Clock = std::chrono::steady_clock;

// A person connected: who they said they are, where they are.
struct Client {
    Client(int client_id, Clock::time_point now)
        : id(client_id), connected_at(now), last_heard(now) {}
    int id = 0;
    bool welcomed = false;
    std::string token;
    std::string token_hash;
    std::string name;
    int table = 0;      // 0: in the lobby
    int seat = 0;       // 1 or 2 seated, 0 watching
    TokenBucket errors; // error replies: max_errors at once, error_rate a second after
    bool closing = false;
    std::optional<Clock::time_point> last_chat;
    TokenBucket requests;           // sit, watch, leave, create, sync
    bool lobby_owed = false;        // a lobby snapshot is due once its output queue drains
    Clock::time_point connected_at; // hello is due within hello_timeout of it
    Clock::time_point last_heard;   // its last line but a ping (lobby_idle_limit)
};

// A seat as the server keeps it.
struct SeatSlot {
    std::string token_hash; // the owner's; empty for an empty or computer seat
    int client = 0;         // the owner's connection, 0 while away
    bool computer = false;
    std::optional<Strike> pending_aim; // the newest aim not yet forwarded
    std::optional<Clock::time_point> last_aim;
    std::optional<Clock::time_point> away_since; // while the owner's token keeps it, unseated
    TokenBucket actions; // each action is validated, saved (fsync) and broadcast
};

// How many actions' hashes a table keeps for the log of a sync (Table::recent_hashes).
inline constexpr std::size_t recent_hashes_kept = 16;
// How many chat lines a table keeps for whoever sits or watches next (Table::chat).
inline constexpr std::size_t chat_lines_kept = 50;

// "1 table", "3 tables": the log's counts of tables.
inline std::string tables_count(std::size_t n) {
    return std::to_string(n) + (n == 1 ? " table" : " tables");
}

// A table: its match (the authority on the game), its seats, and the bookkeeping of its
// computer searches and saves.
struct Table {
    int number = 0;
    Match match;
    SeatSlot seats[2];
    // From a server-wide count, moved on by every change of the table (a seat, a name, a
    // computer, an action): a computer's answer asked at an older ticket is for a table that
    // is no more, and is dropped. Tables never share one, even a table number used again.
    std::uint64_t ticket = 0;
    bool searching = false; // a search is out, asked at search_ticket
    std::string creator;    // the creator's token hash (empty for a restored table)
    std::uint64_t search_ticket = 0;
    int refusals = 0;    // the computer's moves refused in a row
    bool saving = false; // an action waits for its save (HallCore::batch_)
    // The state hash after each of the last few actions (SEQ, HASH): a client's copy that
    // disagreed is logged against the server's hash at the same action.
    std::deque<std::pair<std::size_t, std::uint64_t>> recent_hashes{};
    std::string creator_name{};    // the creator's name (empty for a restored table)
    Clock::time_point last_move{}; // its creation or its last action (archive_after)
    // The last chat_lines_kept lines said at the table, oldest first: a player who comes
    // back (or a spectator who comes in) reads what was said, after the record.
    std::deque<ChatShown> chat{};
};

// An action played on a copy of a table's match, waiting for its save: only once saved is it
// the table's. Where it came from says what a failed save does.
struct Proposal {
    enum class From { person, computer_move, computer_rack };
    int table = 0;
    Match next;
    From from = From::person;
    int client = 0;          // the person who acted
    int seat = 0;            // the seat that acted
    Clock::time_point since; // when the loop woke to it
    std::string problem;     // the save's: empty when saved
};

// The name a seat shows when nobody sits in it.
inline std::string default_name(int seat) {
    return "Player " + std::to_string(seat);
}

} // namespace serving

/// The hall's tables and people, driven by messages and a clock the caller gives.
class HallCore {
public:
    using Clock = serving::Clock;
    /// Bytes still waiting to be sent to a client (0 for an unknown one).
    using QueuedBytes = std::function<std::size_t(int client)>;
    /// The time now, for the figures only (how long an action took to handle and to save).
    using Stopwatch = std::function<Clock::time_point()>;

    /// A hall with no tables yet (`restore` reads the state folder's). `options`' socket_path
    /// is not used. `queued` tells how much output still waits for a client (a lobby goes to a
    /// client only once its queue is small); null: nothing ever waits. `stopwatch` times the
    /// figures; null: they read 0.
    explicit HallCore(ServerOptions options, QueuedBytes queued = {}, Stopwatch stopwatch = {});
    ~HallCore();
    HallCore(const HallCore&) = delete;
    HallCore& operator=(const HallCore&) = delete;

    /// True when the computer pool could start (its wake pipe).
    bool ok() const { return pool_.ok(); }
    /// Restores the tables saved in the state folder (none without one). `wall_now` is the
    /// system clock's time at `now`: a restored away seat counts from its file's last change.
    void restore(Clock::time_point now, std::chrono::system_clock::time_point wall_now);

    /// A new connection `client` (an id not in use).
    void on_connect(int client, Clock::time_point now);
    /// One line (without its '\n') from `client`.
    void on_line(int client, std::string_view line, Clock::time_point now);
    /// `client`'s connection is gone (closed by the peer, or cut for not reading); its seat goes
    /// away at once. Nothing for an id not known (one this core closed and dropped already).
    void on_disconnect(int client, Clock::time_point now);
    /// Takes the computer pool's answers (call when `computer_fd` is readable).
    void on_computer_answers(Clock::time_point now);
    /// Readable when the computer pool has answers: for poll(2).
    int computer_fd() const { return pool_.wake_fd(); }
    /// Waits at most `timeout` for the computer pool's answers and takes them; whether any
    /// came (for tests, which have no poll loop).
    bool await_computer(std::chrono::milliseconds timeout, Clock::time_point now);
    /// The end of a round: the round's actions saved and sent, aims forwarded, the closed
    /// clients dropped, away seats and silent connections expired, the lobby sent.
    void tick(Clock::time_point now);
    /// Milliseconds until `tick` has something to do by the clock, -1 for nothing.
    int timeout(Clock::time_point now) const;
    /// What was said since the last call, in order.
    std::vector<Outgoing> take_outbox() { return std::exchange(outbox_, {}); }

    /// With idle_exit set: true once nothing has kept the hall for that long
    /// (ServerOptions::idle_exit says what keeps it; the caller then stops).
    bool idle_for_good(Clock::time_point now);
    /// Milliseconds until the hall has been idle for idle_exit, -1 for never.
    int idle_timeout(Clock::time_point now) const;
    /// Saves every table not on disk as it stands (at the end): those whose last save failed;
    /// how many still could not be saved.
    std::size_t save_all();
    /// Logs how long actions took to handle and to save (`termpool hall bench` reads it).
    void log_figures() const;
    /// Writes `line` to the log, if any.
    void log(const std::string& line) const;
    /// Writes `line`, a kind of line client `client` can cause again and again, rate-limited
    /// per client and kind (HallLog::write_repeated).
    void log_repeated(int client, std::string_view kind, const std::string& line) const;

    /// Tables held (readable from any thread).
    std::size_t table_count() const { return table_count_; }
    /// Connections known (welcomed or not).
    std::size_t client_count() const { return clients_.size(); }
    /// Table `number`'s match, nullptr when there is no such table (for tests).
    const Match* match(int number) const {
        const auto found = tables_.find(number);
        return found == tables_.end() ? nullptr : &found->second.match;
    }

private:
    using Client = serving::Client;
    using SeatSlot = serving::SeatSlot;
    using Table = serving::Table;
    using Proposal = serving::Proposal;

    static bool seat_taken(const SeatSlot& slot) {
        return slot.computer || !slot.token_hash.empty();
    }
    static bool full(const Table& table) {
        return seat_taken(table.seats[0]) && seat_taken(table.seats[1]);
    }
    static bool started(const Table& table) { return !table.match.record().actions.empty(); }
    static bool over(const Table& table) { return table.match.pending().kind == Pending::over; }

    void changed(Table& table) { table.ticket = ++last_ticket_; }
    Clock::time_point stopwatch() const { return stopwatch_ ? stopwatch_() : Clock::time_point{}; }
    std::size_t queued(int client) const { return queued_ ? queued_(client) : 0; }

    // --- hall_core.cpp: the outbox, clients coming and going
    void send(Client& client, const ServerMessage& message);
    void send_text(Client& client, std::string text);
    void send_bulk(Client& client, std::string text);
    void send_error(Client& client, ErrorCode code, const std::string& text, Clock::time_point now);
    void send_and_close(Client& client, ErrorCode code, const std::string& text);
    void close(Client& client);
    void send_to_table(const Table& table, const ServerMessage& message, int except = 0);
    void expire_unwelcomed(Clock::time_point now);
    int hello_timeout(Clock::time_point now) const;
    void drop_closed(Clock::time_point now);
    void drop(int id, Clock::time_point now);

    // --- hall_core_lobby.cpp: the lobby snapshot
    SeatView seat_view(const Table& table, int seat) const;
    TableView table_view(const Table& table, int spectators) const;
    std::string lobby_text() const;
    void send_lobbies(Clock::time_point now);
    int lobby_timeout(Clock::time_point now) const;

    // --- hall_core_seats.cpp: people at tables, seats, away seats, tables coming and going
    void send_record(Client& client, const Table& table);
    void seat_changed(Table& table, int seat);
    void expire_away(Clock::time_point now);
    int away_timeout(Clock::time_point now) const;
    Table* table_of(const Client& client);
    void leave_table(Client& client, Clock::time_point now, int staying = 0);
    void forget_if_idle(Table& table);
    void join(Client& client, Table& table, int seat);
    void on_hello(Client& client, const Hello& hello, Clock::time_point now);
    void on_create(Client& client, const Create& create, Clock::time_point now);
    void on_sit(Client& client, const Sit& sit, Clock::time_point now);
    void on_watch(Client& client, const Watch& watch, Clock::time_point now);
    void on_computer(Client& client, const SeatComputer& request, Clock::time_point now);
    void forget_waiting_tables_of(const std::string& token_hash);

    // --- hall_core_limits.cpp: what one person may hold, who gives way, idle tables archived
    bool holds(const Table& table, const Client& client) const;
    int tables_held(const Client& client) const;
    std::string create_refusal(const Client& client) const;
    std::string sit_refusal(const Table& table, const Client& client) const;
    void evict_for_newcomer(const Client& newcomer);
    bool evict_idle_lobby(const std::string& newcomer_hash, Clock::time_point now);
    void archive_idle(Clock::time_point now);
    int archive_timeout(Clock::time_point now) const;

    // --- hall_core_actions.cpp: the game: actions, their saves, the computer, aims, chat
    bool at_action_cap(const Table& table) const;
    void think(Table& table, Clock::time_point now);
    void propose(Table& table, Match next, Proposal::From from, int client, int seat,
                 Clock::time_point now);
    void settle(Clock::time_point now);
    void taken_or_not(Proposal& p, Clock::time_point now);
    void action_taken(Table& table, Clock::time_point now);
    static MatchError play(Match& match, int seat, const RecordedAction& action);
    void computer_answers(std::vector<ComputerJob> answers, Clock::time_point now);
    void computer_refused(Table& table, int seat, const std::string& why, Clock::time_point now);
    void on_act(Client& client, const RecordedAction& action, Clock::time_point now);
    void on_aim(Client& client, const Aim& aim, Clock::time_point now);
    void flush_aims(Clock::time_point now);
    int aim_timeout(Clock::time_point now) const;
    void on_chat(Client& client, const Chat& chat, Clock::time_point now);
    void on_sync(Client& client, const Sync& sync, Clock::time_point now);

    // --- hall_core_persistence.cpp: saving and restoring tables
    static SavedTable saved_form(const Table& table, const Match& match);
    std::string save(const Table& table);
    Clock::time_point file_changed(int number, Clock::time_point now,
                                   std::chrono::system_clock::time_point wall_now) const;

    // --- hall_core_who.cpp: the hall's state for its host
    std::vector<std::string> who_lines(int asker, Clock::time_point now) const;

    // --- hall_core_messages.cpp: each client message to its handler
    void on_message(Client& client, const ClientMessage& message, Clock::time_point now);

    ServerOptions options_;
    QueuedBytes queued_;
    Stopwatch stopwatch_;
    ComputerPool pool_;
    std::map<int, Client> clients_; // by id
    std::map<int, Table> tables_;   // by number
    std::vector<Outgoing> outbox_;
    std::uint64_t last_ticket_ = 0; // the newest Table::ticket given
    bool lobby_dirty_ = false;      // the lobby changed since the last snapshot went out
    std::optional<Clock::time_point> last_lobby_;
    std::atomic<std::size_t> table_count_{0};
    std::mt19937_64 random_; // the deals and the computers' seeds (ServerOptions::deal_seed)
    // The actions of this round waiting for their saves, at most one a table (Table::saving).
    std::vector<Proposal> batch_;
    bool settling_ = false;
    WorkCrew savers_;
    std::optional<Clock::time_point> idle_since_;   // nothing keeps the hall since then
    std::optional<Clock::time_point> next_archive_; // when archive_idle looks again
    std::set<int> unsaved_;                         // the tables whose last save failed (by number)
    LatencyHistogram handling_; // each action, from the loop's wake-up to its broadcast queued
    LatencyHistogram saving_;   // each round's saves of actions, side by side
};

} // namespace termpool::hall
