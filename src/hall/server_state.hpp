#pragma once
// The hall server's state and the pieces of its loop, shared by the server's own files only
// (server*.cpp); the public face is server.hpp. One thread, the poll loop's, touches it,
// except the computer pool's and the save crew's workers, which see only what is handed to
// them.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <termpool/match.hpp>
#include <utility>
#include <vector>

#include "hall/computer_pool.hpp"
#include "hall/connection.hpp"
#include "hall/hall_state.hpp"
#include "hall/latency_histogram.hpp"
#include "hall/protocol.hpp"
#include "hall/server.hpp"
#include "hall/token_bucket.hpp"
#include "hall/unique_fd.hpp"
#include "hall/work_crew.hpp"

namespace termpool::hall::serving {

using Clock = std::chrono::steady_clock;

// A person connected: their socket, who they said they are, where they are.
struct Client {
    Client(int client_id, Connection c, Clock::time_point now)
        : id(client_id), connection(std::move(c)), connected_at(now) {}
    int id = 0;
    Connection connection;
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
    bool saving = false; // an action waits for its save (State::batch)
    // The state hash after each of the last few actions (SEQ, HASH): a client's copy that
    // disagreed is logged against the server's hash at the same action.
    std::deque<std::pair<std::size_t, std::uint64_t>> recent_hashes{};
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

} // namespace termpool::hall::serving

namespace termpool::hall {

struct Server::State {
    using Client = serving::Client;
    using SeatSlot = serving::SeatSlot;
    using Table = serving::Table;
    using Proposal = serving::Proposal;
    using Clock = serving::Clock;

    ServerOptions options;
    UniqueFd listener;
    bool made_socket = false;
    std::pair<dev_t, ino_t> socket_id{}; // the socket file it made, to remove only that one
    WakePipe stop_pipe;
    ComputerPool pool;
    std::map<int, Client> clients; // by id
    std::map<int, Table> tables;   // by number
    int next_client_id = 1;
    std::uint64_t last_ticket = 0; // the newest Table::ticket given
    bool lobby_dirty = false;      // the lobby changed since the last snapshot went out
    std::optional<Clock::time_point> last_lobby;
    // Out of file descriptors, accept fails while the listener stays readable: it is left out
    // of poll until then, rather than spin.
    std::optional<Clock::time_point> accept_paused_until;
    std::atomic<std::size_t> table_count{0};
    std::atomic<std::size_t> rounds{0};        // returns of poll (Server::rounds)
    std::atomic<std::size_t> accept_pauses{0}; // accept_paused_until set (Server::accept_pauses)
    std::mt19937_64 random; // the deals and the computers' seeds (ServerOptions::deal_seed)
    // The actions of this round waiting for their saves, at most one a table (Table::saving).
    std::vector<Proposal> batch;
    bool settling = false;
    WorkCrew savers;
    Clock::time_point woke;                      // when poll last returned
    std::optional<Clock::time_point> idle_since; // no connection and no table since then
    LatencyHistogram handling; // each action, from the loop's wake-up to its broadcast queued
    LatencyHistogram saving;   // each round's saves of actions, side by side

    explicit State(ServerOptions o)
        : options(std::move(o)), pool(options.computer_threads),
          random(options.deal_seed ? *options.deal_seed : std::random_device{}()),
          savers(std::max(0, options.save_threads - 1)) {}

    void log(const std::string& line) const {
        if (options.log)
            options.log->write(line);
    }
    // A line a client can cause again and again: rate-limited per client and kind (HallLog).
    void log_repeated(int client, std::string_view kind, const std::string& line) const {
        if (options.log)
            options.log->write_repeated(client, kind, line);
    }

    static bool seat_taken(const SeatSlot& slot) {
        return slot.computer || !slot.token_hash.empty();
    }
    static bool full(const Table& table) {
        return seat_taken(table.seats[0]) && seat_taken(table.seats[1]);
    }
    static bool started(const Table& table) { return !table.match.record().actions.empty(); }
    static bool over(const Table& table) { return table.match.pending().kind == Pending::over; }

    void changed(Table& table) { table.ticket = ++last_ticket; }

    // --- server.cpp: idleness and the figures (the poll loop itself is Server::run)
    bool idle_for_good(Clock::time_point now);
    int idle_timeout(Clock::time_point now) const;
    void log_figures() const;

    // --- server_connections.cpp: sockets, sending, connections coming and going
    void send(Client& client, const ServerMessage& message);
    void send_bulk(Client& client, const std::string& text); // see Connection::queue_bulk
    void send_error(Client& client, ErrorCode code, const std::string& text);
    void send_and_close(Client& client, ErrorCode code, const std::string& text);
    void send_to_table(const Table& table, const ServerMessage& message, int except = 0);
    void expire_unwelcomed(Clock::time_point now);
    int hello_timeout(Clock::time_point now) const;
    void accept_clients();
    void serve_client(Client& client, bool readable);
    void drop_closed();
    std::string listen_on(const std::string& path);

    // --- server_lobby.cpp: the lobby snapshot
    SeatView seat_view(const Table& table, int seat) const;
    TableView table_view(const Table& table, int spectators) const;
    std::string lobby_text() const;
    void send_lobby(Client& client, const std::string& text);
    void send_lobbies(Clock::time_point now);
    int lobby_timeout(Clock::time_point now) const;

    // --- server_seats.cpp: people at tables, seats, away seats, tables coming and going
    void send_record(Client& client, const Table& table);
    void seat_changed(Table& table, int seat);
    void expire_away(Clock::time_point now);
    int away_timeout(Clock::time_point now) const;
    Table* table_of(const Client& client);
    void leave_table(Client& client, int staying = 0);
    void forget_if_idle(Table& table);
    void join(Client& client, Table& table, int seat);
    void on_hello(Client& client, const Hello& hello);
    void on_create(Client& client, const Create& create);
    void on_sit(Client& client, const Sit& sit);
    void on_watch(Client& client, const Watch& watch);
    void on_computer(Client& client, const SeatComputer& request);
    void forget_waiting_tables_of(const std::string& token_hash);

    // --- server_actions.cpp: the game: actions, their saves, the computer, aims, chat
    bool at_action_cap(const Table& table) const;
    void think(Table& table);
    void propose(Table& table, Match next, Proposal::From from, int client, int seat);
    void settle();
    void taken_or_not(Proposal& p);
    void action_taken(Table& table);
    static MatchError play(Match& match, int seat, const RecordedAction& action);
    void computer_answers();
    void computer_refused(Table& table, int seat, const std::string& why);
    void on_act(Client& client, const RecordedAction& action);
    void on_aim(Client& client, const Aim& aim);
    void flush_aims(Clock::time_point now);
    int aim_timeout(Clock::time_point now) const;
    void on_chat(Client& client, const Chat& chat);
    void on_sync(Client& client, const Sync& sync);

    // --- server_persistence.cpp: saving and restoring tables
    static SavedTable saved_form(const Table& table, const Match& match);
    bool save(const Table& table);
    void restore();
    Clock::time_point file_changed(int number) const;

    // --- server_messages.cpp: each client message to its handler
    void on_message(Client& client, const ClientMessage& message);
    void on_line(Client& client, std::string_view line);
};

} // namespace termpool::hall
