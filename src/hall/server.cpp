// The hall's poll loop. Plain POSIX sockets and poll(2), one thread: the hall needs no
// dependency for this, and its load is small (a few hundred connections, a few messages a
// second each); tmux uses libevent for portability to systems we do not target. The computer
// seats think on a small worker pool (computer_pool.hpp) so that no search stalls the loop,
// and the actions a round took are saved side by side on a work crew (work_crew.hpp): each
// save waits for the disk, and a hundred tables' saves one after the other held every table
// up behind them.

#include "hall/server.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <poll.h>
#include <random>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <termpool/match.hpp>
#include <unistd.h>
#include <vector>

#include "hall/computer_pool.hpp"
#include "hall/connection.hpp"
#include "hall/hall_state.hpp"
#include "hall/latency_histogram.hpp"
#include "hall/protocol.hpp"
#include "hall/token_bucket.hpp"
#include "hall/unique_fd.hpp"
#include "hall/work_crew.hpp"

namespace termpool::hall {

namespace {

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
    int table = 0; // 0: in the lobby
    int seat = 0;  // 1 or 2 seated, 0 watching
    int errors = 0;
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

std::variant<Match, MatchError> new_match(const Create& create, std::uint64_t seed) {
    GameRecord header;
    header.setup.game = create.game;
    header.setup.table = create.size;
    header.seed = seed;
    header.race_to = create.race_to;
    return Match::start(header, seed);
}

std::string default_name(int seat) {
    return "Player " + std::to_string(seat);
}

std::string computer_name(Level level) {
    return std::string("Computer (") + level_name(level) + ")";
}

} // namespace

struct Server::State {
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
    std::mt19937_64 random{std::random_device{}()};
    // The actions of this round waiting for their saves, at most one a table (Table::saving).
    std::vector<Proposal> batch;
    bool settling = false;
    WorkCrew savers;
    Clock::time_point woke;    // when poll last returned
    LatencyHistogram handling; // each action, from the loop's wake-up to its broadcast queued
    LatencyHistogram saving;   // each round's saves of actions, side by side

    explicit State(ServerOptions o)
        : options(std::move(o)), pool(options.computer_threads),
          savers(std::max(0, options.save_threads - 1)) {}

    void log(const std::string& line) const {
        if (options.log)
            *options.log << "termpool hall: " << line << '\n' << std::flush;
    }

    // How long actions took to handle (`termpool hall bench` reads these two lines).
    void log_figures() const {
        char line[200];
        std::snprintf(line, sizeof line,
                      "handling: %llu actions, p50 %.2f ms, p99 %.2f ms (from the loop's "
                      "wake-up to the broadcast queued)",
                      static_cast<unsigned long long>(handling.count()),
                      handling.percentile_ms(0.5), handling.percentile_ms(0.99));
        log(line);
        std::snprintf(line, sizeof line,
                      "saving: %llu rounds of saves, p50 %.2f ms, p99 %.2f ms (a round's saves "
                      "side by side)",
                      static_cast<unsigned long long>(saving.count()), saving.percentile_ms(0.5),
                      saving.percentile_ms(0.99));
        log(line);
    }

    // --- sending ---------------------------------------------------------------------------

    void send(Client& client, const ServerMessage& message) {
        if (client.closing)
            return;
        if (!client.connection.queue(format_server(message), options.output_limit)) {
            log("client " + std::to_string(client.id) + " stopped reading: disconnected");
            client.closing = true;
        }
    }

    void send_error(Client& client, ErrorCode code, const std::string& text) {
        send(client, Error{code, text});
        if (++client.errors >= options.max_errors) {
            log("client " + std::to_string(client.id) + ": too many errors, disconnected");
            client.closing = true;
        }
    }

    // Sends what can go now and ends the connection (after a fatal error).
    void send_and_close(Client& client, ErrorCode code, const std::string& text) {
        send(client, Error{code, text});
        client.connection.flush();
        // The end of the stream follows the reply, so the peer reads it before the close
        // rather than lose it to a reset (its unread input is discarded with the socket).
        ::shutdown(client.connection.fd(), SHUT_WR);
        client.closing = true;
    }

    void send_to_table(const Table& table, const ServerMessage& message, int except = 0) {
        const std::string line = format_server(message);
        for (auto& [id, client] : clients)
            if (client.table == table.number && id != except && !client.closing &&
                !client.connection.queue(line, options.output_limit)) {
                log("client " + std::to_string(id) + " stopped reading: disconnected");
                client.closing = true;
            }
    }

    // --- views -----------------------------------------------------------------------------

    SeatView seat_view(const Table& table, int seat) const {
        const SeatSlot& slot = table.seats[seat - 1];
        if (slot.computer)
            return {SeatKind::computer, table.match.name(seat)};
        if (slot.token_hash.empty())
            return {SeatKind::empty, ""};
        return {slot.client != 0 ? SeatKind::player : SeatKind::away, table.match.name(seat)};
    }

    static bool seat_taken(const SeatSlot& slot) {
        return slot.computer || !slot.token_hash.empty();
    }
    static bool full(const Table& table) {
        return seat_taken(table.seats[0]) && seat_taken(table.seats[1]);
    }
    static bool started(const Table& table) { return !table.match.record().actions.empty(); }
    static bool over(const Table& table) { return table.match.pending().kind == Pending::over; }

    TableView table_view(const Table& table, int spectators) const {
        TableView view;
        view.number = table.number;
        view.game = table.match.setup().game;
        view.size = table.match.setup().table;
        view.race_to = std::max(1, table.match.record().race_to);
        view.state = over(table)   ? TableState::over
                     : full(table) ? TableState::playing
                                   : TableState::waiting;
        for (int s = 1; s <= 2; ++s)
            view.seats[s - 1] = seat_view(table, s);
        view.spectators = spectators;
        return view;
    }

    // The whole lobby as it goes out, made once for everyone it goes to: with a few hundred
    // people and a hundred tables, a snapshot made per client (each table counting its
    // spectators among all clients) stalled the loop for tens of milliseconds.
    std::string lobby_text() const {
        std::map<int, int> spectators; // by table
        for (const auto& [id, client] : clients)
            if (client.table != 0 && client.seat == 0)
                ++spectators[client.table];
        std::string text = format_server(LobbyBegin{});
        for (const auto& [number, table] : tables) {
            const auto found = spectators.find(number);
            text += format_server(table_view(table, found == spectators.end() ? 0 : found->second));
        }
        for (const auto& [id, other] : clients)
            if (other.welcomed && !other.closing)
                text += format_server(PlayerView{other.name, other.table, other.seat});
        return text + format_server(LobbyEnd{});
    }

    void send_lobby(Client& client, const std::string& text) {
        if (client.closing)
            return;
        if (!client.connection.queue(text, options.output_limit)) {
            log("client " + std::to_string(client.id) + " stopped reading: disconnected");
            client.closing = true;
        }
    }

    // The lobby's changes go out as one snapshot at most every lobby_interval; a client whose
    // output still holds more than lobby_queue_limit bytes gets it once it has read them.
    void send_lobbies(Clock::time_point now) {
        if (lobby_dirty && (!last_lobby || now - *last_lobby >= options.lobby_interval)) {
            lobby_dirty = false;
            last_lobby = now;
            for (auto& [id, client] : clients)
                client.lobby_owed = client.welcomed;
        }
        std::optional<std::string> text; // made once, when the first client is due one
        for (auto& [id, client] : clients)
            if (client.lobby_owed && !client.closing &&
                client.connection.queued() <= options.lobby_queue_limit) {
                client.lobby_owed = false;
                if (!text)
                    text = lobby_text();
                send_lobby(client, *text);
            }
    }

    // A connection that has not said hello within hello_timeout goes: a silent one must not
    // hold a place.
    void expire_unwelcomed(Clock::time_point now) {
        for (auto& [id, client] : clients)
            if (!client.welcomed && !client.closing &&
                now - client.connected_at >= options.hello_timeout) {
                log("client " + std::to_string(id) + " said no hello: disconnected");
                send_and_close(client, ErrorCode::hello_first, "no hello in time");
            }
    }

    // Milliseconds until a connection's hello is due, -1 for none.
    int hello_timeout(Clock::time_point now) const {
        int timeout = -1;
        for (const auto& [id, client] : clients)
            if (!client.welcomed && !client.closing) {
                const auto due = client.connected_at + options.hello_timeout - now;
                const int ms = static_cast<int>(std::max<long long>(
                    0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
                timeout = timeout < 0 ? ms : std::min(timeout, ms);
            }
        return timeout;
    }

    // Milliseconds until a lobby snapshot is due, -1 for none.
    int lobby_timeout(Clock::time_point now) const {
        for (const auto& [id, client] : clients)
            if (client.lobby_owed && !client.closing &&
                client.connection.queued() <= options.lobby_queue_limit)
                return 0;
        if (!lobby_dirty)
            return -1;
        if (!last_lobby)
            return 0;
        const auto due = *last_lobby + options.lobby_interval - now;
        return static_cast<int>(
            std::max<long long>(0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
    }

    void send_record(Client& client, const Table& table) {
        const std::string text = format_record(table.match.record());
        for (std::size_t start = 0; start < text.size();) {
            const std::size_t end = text.find('\n', start);
            const std::size_t stop = end == std::string::npos ? text.size() : end;
            send(client, RecordLine{table.number, text.substr(start, stop - start)});
            start = stop + 1;
        }
        send(client, RecordEnd{table.number, table.match.record().actions.size(),
                               table.match.state_hash()});
        for (int s = 1; s <= 2; ++s)
            send(client, SeatChange{table.number, s, seat_view(table, s)});
    }

    void changed(Table& table) { table.ticket = ++last_ticket; }

    void seat_changed(Table& table, int seat) {
        changed(table);
        send_to_table(table, SeatChange{table.number, seat, seat_view(table, seat)});
        lobby_dirty = true;
    }

    // --- saving ----------------------------------------------------------------------------

    // `table` as it is with `match` in place of its own, as it is saved.
    static SavedTable saved_form(const Table& table, const Match& match) {
        SavedTable stored{table.number, match.record(), {}};
        for (int s = 0; s < 2; ++s)
            stored.seat_tokens[s] = table.seats[s].token_hash;
        return stored;
    }

    bool save(const Table& table) {
        if (options.state_dir.empty())
            return true;
        if (const std::string problem =
                save_table(options.state_dir, saved_form(table, table.match));
            !problem.empty()) {
            log("cannot save table " + std::to_string(table.number) + ": " + problem);
            return false;
        }
        return true;
    }

    void restore() {
        if (options.state_dir.empty())
            return;
        std::vector<std::string> problems;
        for (SavedTable& stored : load_tables(options.state_dir, problems)) {
            // A restored computer starts a new stream, as a resumed local game's does.
            auto replayed =
                Match::replay(stored.record, std::numeric_limits<std::size_t>::max(), {}, random());
            if (!std::holds_alternative<Match>(replayed))
                continue;
            Table table{stored.number,
                        std::move(std::get<Match>(replayed)),
                        {},
                        ++last_ticket,
                        false,
                        {},
                        0,
                        0};
            const auto away_since = file_changed(stored.number);
            for (int s = 0; s < 2; ++s) {
                table.seats[s].computer = stored.record.computers[s].has_value();
                // Nobody is connected yet: a seat of a game not started is nobody's.
                if (started(table)) {
                    table.seats[s].token_hash = stored.seat_tokens[s];
                    table.seats[s].away_since = away_since;
                }
            }
            tables.emplace(stored.number, std::move(table));
        }
        for (const std::string& problem : problems)
            log("not restored: " + problem);
        table_count = tables.size();
        expire_away(Clock::now());
        std::vector<int> numbers;
        for (const auto& [number, table] : tables)
            numbers.push_back(number);
        for (const int number : numbers)
            forget_if_idle(tables.at(number));
        log("restored " + std::to_string(tables.size()) + " tables");
        for (auto& [number, table] : tables)
            think(table);
    }

    // When table `number`'s file last changed, on the steady clock: a restored away seat went
    // away then at the latest (the file is rewritten on every change of the table).
    Clock::time_point file_changed(int number) const {
        struct stat info {};
        const auto now = Clock::now();
        if (::stat(table_path(options.state_dir, number).c_str(), &info) != 0)
            return now;
        const auto changed = std::chrono::system_clock::from_time_t(info.st_mtim.tv_sec);
        const auto age = std::chrono::system_clock::now() - changed;
        return age > Clock::duration::zero()
                   ? now - std::chrono::duration_cast<Clock::duration>(age)
                   : now;
    }

    // Frees every away seat whose owner has been gone longer than away_limit; a table left
    // with nobody goes.
    void expire_away(Clock::time_point now) {
        std::vector<int> emptied;
        for (auto& [number, table] : tables)
            for (int s = 1; s <= 2; ++s) {
                SeatSlot& slot = table.seats[s - 1];
                if (slot.token_hash.empty() || slot.client != 0 || !slot.away_since ||
                    now - *slot.away_since < options.away_limit)
                    continue;
                log("table " + std::to_string(number) + ": seat " + std::to_string(s) +
                    " was away too long: freed");
                slot.token_hash.clear();
                slot.away_since.reset();
                table.match.rename(s, default_name(s));
                save(table);
                seat_changed(table, s);
                emptied.push_back(number);
            }
        for (const int number : emptied)
            if (auto found = tables.find(number); found != tables.end())
                forget_if_idle(found->second);
    }

    // Milliseconds until the next away seat is due to be freed, -1 for none.
    int away_timeout(Clock::time_point now) const {
        int timeout = -1;
        for (const auto& [number, table] : tables)
            for (const SeatSlot& slot : table.seats)
                if (!slot.token_hash.empty() && slot.client == 0 && slot.away_since) {
                    const auto due = *slot.away_since + options.away_limit - now;
                    const auto ms = std::clamp<long long>(
                        std::chrono::ceil<std::chrono::milliseconds>(due).count(), 0,
                        std::numeric_limits<int>::max());
                    timeout = timeout < 0 ? static_cast<int>(ms)
                                          : std::min(timeout, static_cast<int>(ms));
                }
        return timeout;
    }

    // --- the game --------------------------------------------------------------------------

    // After a change: a computer to act gets a search; a race whose next breaker is a computer
    // racks at once (a person racks with next-rack when they are ready).
    // Two seats trading fouls could grow a record without end: a table keeps so many actions.
    bool at_action_cap(const Table& table) const {
        return table.match.record().actions.size() >= options.max_actions;
    }

    // A table whose action waits for its save thinks once it is saved (action_taken).
    void think(Table& table) {
        if (!full(table) || table.searching || table.saving || at_action_cap(table))
            return;
        const PendingAction pending = table.match.pending();
        if (pending.kind == Pending::next_rack && table.seats[pending.player - 1].computer) {
            Match next = table.match;
            if (next.next_rack(pending.player) == MatchError::none)
                propose(table, std::move(next), Proposal::From::computer_rack, 0, pending.player);
            return;
        }
        if (!table.match.computer_to_act())
            return;
        table.searching = true;
        table.search_ticket = table.ticket;
        pool.submit(ComputerJob{table.number, table.ticket, table.match, std::nullopt});
    }

    // `next`, the table's match with one more action, is saved at the end of the round (or
    // sooner, see on_message); only then does it become the table's, and the table is told. An
    // action that could not be saved is not taken: were it played, a restart would lose it.
    void propose(Table& table, Match next, Proposal::From from, int client, int seat) {
        table.saving = true;
        batch.push_back(Proposal{table.number, std::move(next), from, client, seat, woke, {}});
    }

    // Saves the actions waiting, side by side (each save waits for the disk: a round's saves
    // one after the other held every table up), then takes each one saved and tells its
    // table. Nothing else happened to those tables in between: the result is as if each had
    // been saved and taken at once.
    void settle() {
        if (settling)
            return; // settle's own loop takes what is proposed meanwhile
        settling = true;
        while (!batch.empty()) {
            std::vector<Proposal> round = std::exchange(batch, {});
            if (!options.state_dir.empty()) {
                std::vector<SavedTable> stored;
                for (const Proposal& p : round)
                    stored.push_back(saved_form(tables.at(p.table), p.next));
                const auto start = Clock::now();
                savers.run(round.size(), [&](std::size_t i) {
                    round[i].problem = save_table(options.state_dir, stored[i]);
                });
                saving.add(Clock::now() - start);
            }
            for (Proposal& p : round)
                taken_or_not(p);
        }
        settling = false;
    }

    void taken_or_not(Proposal& p) {
        const auto found = tables.find(p.table);
        if (found == tables.end())
            return;
        Table& table = found->second;
        table.saving = false;
        if (p.problem.empty()) {
            table.match = std::move(p.next);
            action_taken(table);
            handling.add(Clock::now() - p.since);
            if (p.from == Proposal::From::computer_move)
                table.refusals = 0;
            return;
        }
        log("cannot save table " + std::to_string(table.number) + ": " + p.problem);
        switch (p.from) {
        case Proposal::From::person:
            if (const auto client = clients.find(p.client); client != clients.end())
                send_error(client->second, ErrorCode::internal,
                           "the action could not be saved: nothing changed, try again");
            break;
        case Proposal::From::computer_move:
            computer_refused(table, p.seat, "it could not be saved");
            break;
        case Proposal::From::computer_rack:
            log("table " + std::to_string(table.number) + ": the next rack waits");
            break;
        }
    }

    // The match took an action (saved): tell the table, move on.
    void action_taken(Table& table) {
        changed(table);
        const bool now_over = over(table);
        const auto& actions = table.match.record().actions;
        send_to_table(table, ActionDone{table.number, actions.size(), table.match.state_hash(),
                                        actions.back()});
        for (SeatSlot& slot : table.seats)
            slot.pending_aim.reset();
        if (now_over)
            lobby_dirty = true;
        think(table);
    }

    static MatchError play(Match& match, int seat, const RecordedAction& action) {
        switch (action.kind) {
        case RecordedAction::Kind::place:
            return match.place(seat, action.place);
        case RecordedAction::Kind::choose:
            return match.choose(seat, action.choice);
        case RecordedAction::Kind::shot: {
            const auto played = match.shoot(seat, action.strike, action.call);
            const MatchError* error = std::get_if<MatchError>(&played);
            return error ? *error : MatchError::none;
        }
        case RecordedAction::Kind::rack:
            return match.next_rack(seat);
        }
        return MatchError::not_now;
    }

    void computer_answers() {
        for (ComputerJob& answer : pool.take_answers()) {
            const auto found = tables.find(answer.table);
            if (found == tables.end() || !found->second.searching ||
                found->second.search_ticket != answer.ticket)
                continue; // a table that is gone (its number may be another table's now)
            Table& table = found->second;
            if (table.saving)
                settle();
            table.searching = false;
            // The table changed while the computer thought (someone left, a seat changed):
            // the answer is for a table that is no more; ask again if still the computer's turn.
            if (answer.ticket != table.ticket) {
                think(table);
                continue;
            }
            if (!full(table) || !table.match.computer_to_act())
                continue;
            const int seat = table.match.to_act();
            if (!answer.move) {
                computer_refused(table, seat, "it found no move");
                continue;
            }
            RecordedAction action;
            action.kind = answer.move->kind == Pending::place    ? RecordedAction::Kind::place
                          : answer.move->kind == Pending::choose ? RecordedAction::Kind::choose
                                                                 : RecordedAction::Kind::shot;
            action.place = answer.move->spot;
            action.choice = answer.move->choice;
            action.strike = answer.move->shot.strike;
            action.call = answer.move->shot.call;
            // Played on a copy of the live match, which stays the authority; the computers go
            // on with new streams (the one the search moved on is in the job's copy, not worth
            // carrying).
            Match next = table.match;
            if (const MatchError error = play(next, seat, action); error != MatchError::none) {
                computer_refused(table, seat, match_error_text(error));
                continue;
            }
            next.reseed_computers(random());
            propose(table, std::move(next), Proposal::From::computer_move, 0, seat);
        }
    }

    // The computer's move did not play: it searches again (with a new stream); after a few
    // refusals in a row the seat is freed rather than leave the table stuck.
    void computer_refused(Table& table, int seat, const std::string& why) {
        log("table " + std::to_string(table.number) + ": the computer's move was refused: " + why);
        table.match.reseed_computers(random());
        if (++table.refusals < 3)
            return think(table);
        log("table " + std::to_string(table.number) + ": seat " + std::to_string(seat) +
            " freed: its computer cannot move");
        table.refusals = 0;
        table.seats[seat - 1].computer = false;
        table.match.seat_computer(seat, std::nullopt);
        table.match.rename(seat, default_name(seat));
        save(table);
        seat_changed(table, seat);
    }

    // --- people ----------------------------------------------------------------------------

    Table* table_of(const Client& client) {
        const auto found = tables.find(client.table);
        return found == tables.end() ? nullptr : &found->second;
    }

    // `client` leaves its table: by `leave` (or moving on), or because its connection dropped
    // (both are the same to the seat).
    // The table closes if idle, unless it is `staying` (the client moves to another seat of it).
    void leave_table(Client& client, int staying = 0) {
        Table* table = table_of(client);
        const int seat = client.seat;
        client.table = 0;
        client.seat = 0;
        lobby_dirty = true;
        if (!table)
            return;
        if (seat != 0) {
            SeatSlot& slot = table->seats[seat - 1];
            slot.client = 0;
            slot.pending_aim.reset();
            // A seat in a game under way waits for its owner (for away_limit at most); before
            // the first action, or once the match is over, a leave or a drop frees it, so
            // that a table nobody plays at does not stay.
            if (!started(*table) || over(*table)) {
                slot.token_hash.clear();
                table->match.rename(seat, default_name(seat));
            } else {
                slot.away_since = Clock::now();
            }
            save(*table);
            seat_changed(*table, seat);
        }
        if (table->number != staying)
            forget_if_idle(*table);
    }

    // A table nobody is at, and nobody will come back to, goes.
    void forget_if_idle(Table& table) {
        for (const auto& [id, client] : clients)
            if (client.table == table.number && !client.closing)
                return;
        const bool away = !table.seats[0].token_hash.empty() || !table.seats[1].token_hash.empty();
        const bool computers_play = table.seats[0].computer && table.seats[1].computer;
        if (!over(table) && (away || computers_play))
            return;
        if (!options.state_dir.empty())
            forget_table(options.state_dir, table.number);
        log("table " + std::to_string(table.number) + " closed");
        tables.erase(table.number);
        table_count = tables.size();
        lobby_dirty = true;
    }

    void join(Client& client, Table& table, int seat) {
        client.table = table.number;
        client.seat = seat;
        send(client, Joined{table.number, seat});
        send_record(client, table);
        lobby_dirty = true;
    }

    void on_hello(Client& client, const Hello& hello) {
        if (client.welcomed)
            return send_error(client, ErrorCode::hello_first, "hello comes once");
        std::string token = hello.token.empty() ? new_seat_token() : hello.token;
        if (token.empty())
            return send_error(client, ErrorCode::internal, "no random token to give: try again");
        const std::string hash = seat_token_hash(token);
        // Only people who said hello count toward max_clients (the same person again does
        // not: their old connection gives way below).
        const auto others = std::count_if(clients.begin(), clients.end(), [&](const auto& entry) {
            const Client& other = entry.second;
            return other.welcomed && !other.closing && other.token_hash != hash;
        });
        if (others >= options.max_clients)
            return send_and_close(client, ErrorCode::full, "the hall has all the clients it takes");
        // The same person again: the old connection gives way (its seats go away, then the
        // new one may take them back).
        for (auto& [id, other] : clients)
            if (id != client.id && other.welcomed && other.token_hash == hash && !other.closing) {
                send_and_close(other, ErrorCode::replaced, "you connected again elsewhere");
                leave_table(other);
            }
        client.welcomed = true;
        client.token = std::move(token);
        client.token_hash = hash;
        client.name = hello.name;
        send(client, Welcome{protocol_version, client.token});
        for (const auto& [number, table] : tables)
            for (int s = 1; s <= 2; ++s)
                if (table.seats[s - 1].token_hash == hash && table.seats[s - 1].client == 0)
                    send(client, Yours{number, s});
        lobby_dirty = true;
        send_lobby(client, lobby_text());
    }

    void on_create(Client& client, const Create& create) {
        if (static_cast<int>(tables.size()) >= options.max_tables)
            return send_error(client, ErrorCode::full, "the hall has all the tables it takes");
        const auto waiting = std::count_if(tables.begin(), tables.end(), [&](const auto& entry) {
            return entry.second.creator == client.token_hash && !started(entry.second);
        });
        if (waiting >= options.max_waiting_tables)
            return send_error(client, ErrorCode::full,
                              "you have " + std::to_string(waiting) + " tables waiting already");
        int number = 1;
        while (tables.count(number))
            ++number;
        if (number > max_table_number)
            return send_error(client, ErrorCode::full, "no table number is free");
        auto started_match = new_match(create, random());
        if (const MatchError* e = std::get_if<MatchError>(&started_match))
            return send_error(client, ErrorCode::refused, match_error_text(*e));
        tables.emplace(number, Table{number,
                                     std::move(std::get<Match>(started_match)),
                                     {},
                                     ++last_ticket,
                                     false,
                                     client.token_hash,
                                     0,
                                     0});
        table_count = tables.size();
        save(tables.at(number));
        send(client, Created{number});
        lobby_dirty = true;
        log("table " + std::to_string(number) + " created by " + client.name);
    }

    void on_sit(Client& client, const Sit& sit) {
        const auto found = tables.find(sit.table);
        if (found == tables.end())
            return send_error(client, ErrorCode::no_table, "no such table");
        Table& table = found->second;
        SeatSlot& slot = table.seats[sit.seat - 1];
        // Sitting again where one sits changes nothing (a leave first would free the seat
        // before the first shot): the record comes again, as after a sync.
        if (client.table == sit.table && client.seat == sit.seat)
            return join(client, table, sit.seat);
        if (slot.computer || (!slot.token_hash.empty() && slot.token_hash != client.token_hash))
            return send_error(client, ErrorCode::seat_taken, "that seat is taken");
        if (slot.token_hash != client.token_hash && over(table))
            return send_error(client, ErrorCode::refused, "the match is over");
        // One person holds one seat of a table: the other seat stays theirs unless they sit in
        // it now and a leave frees it (before the first action).
        const SeatSlot& other = table.seats[2 - sit.seat];
        const bool moving_over = client.table == sit.table && client.seat == 3 - sit.seat &&
                                 !started(table) && !over(table);
        if (other.token_hash == client.token_hash && !moving_over)
            return send_error(client, ErrorCode::refused, "you hold the other seat of this table");
        if (client.table != 0)
            leave_table(client, sit.table); // never closes this table
        const bool mine = slot.token_hash == client.token_hash;
        slot.client = client.id;
        slot.away_since.reset();
        if (!mine) {
            slot.token_hash = client.token_hash;
            table.match.rename(sit.seat, client.name);
        }
        save(table);
        join(client, table, sit.seat);
        seat_changed(table, sit.seat);
        think(table);
    }

    void on_watch(Client& client, const Watch& watch) {
        if (!tables.count(watch.table))
            return send_error(client, ErrorCode::no_table, "no such table");
        if (client.table != 0)
            leave_table(client, watch.table);
        join(client, tables.at(watch.table), 0);
    }

    void on_act(Client& client, const RecordedAction& action) {
        Table* table = table_of(client);
        if (!table)
            return send_error(client, ErrorCode::no_table, "you are at no table");
        if (client.seat == 0)
            return send_error(client, ErrorCode::not_seated, "spectators do not play");
        if (!full(*table))
            return send_error(client, ErrorCode::refused, "waiting for an opponent");
        if (!table->seats[client.seat - 1].actions.take(options.action_rate, options.action_burst,
                                                        Clock::now()))
            return send_error(client, ErrorCode::rate, "too many actions: slow down");
        if (at_action_cap(*table))
            return send_error(client, ErrorCode::refused,
                              "this game has had " + std::to_string(options.max_actions) +
                                  " actions, the most a table keeps: no more are taken");
        Match next = table->match;
        if (const MatchError error = play(next, client.seat, action); error != MatchError::none)
            return send_error(client, ErrorCode::refused, match_error_text(error));
        propose(*table, std::move(next), Proposal::From::person, client.id, client.seat);
    }

    void on_aim(Client& client, const Aim& aim) {
        Table* table = table_of(client);
        // An aim from someone not to shoot is dropped silently: one sent just before the
        // other player's shot arrived is no fault.
        if (!table || client.seat == 0 || !full(*table) || table->match.to_act() != client.seat)
            return;
        table->seats[client.seat - 1].pending_aim = aim.strike;
        flush_aims(Clock::now());
    }

    // Forwards each seat's newest aim once its interval has passed.
    void flush_aims(Clock::time_point now) {
        for (auto& [number, table] : tables)
            for (int s = 1; s <= 2; ++s) {
                SeatSlot& slot = table.seats[s - 1];
                if (!slot.pending_aim ||
                    (slot.last_aim && now - *slot.last_aim < options.aim_interval))
                    continue;
                send_to_table(table, AimShown{number, s, *slot.pending_aim}, slot.client);
                slot.pending_aim.reset();
                slot.last_aim = now;
            }
    }

    // Milliseconds until the next aim is due, -1 for none.
    int aim_timeout(Clock::time_point now) const {
        int timeout = -1;
        for (const auto& [number, table] : tables)
            for (const SeatSlot& slot : table.seats)
                if (slot.pending_aim && slot.last_aim) {
                    const auto due = *slot.last_aim + options.aim_interval - now;
                    const int ms = static_cast<int>(std::max<long long>(
                        0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
                    timeout = timeout < 0 ? ms : std::min(timeout, ms);
                }
        return timeout;
    }

    void on_chat(Client& client, const Chat& chat) {
        Table* table = table_of(client);
        if (!table)
            return send_error(client, ErrorCode::no_table, "chat is at a table");
        const auto now = Clock::now();
        if (client.last_chat && now - *client.last_chat < options.chat_interval)
            return send_error(client, ErrorCode::rate, "one chat line a second");
        client.last_chat = now;
        send_to_table(*table, ChatShown{table->number, client.name, chat.text});
    }

    void on_computer(Client& client, const SeatComputer& request) {
        Table* table = table_of(client);
        if (!table)
            return send_error(client, ErrorCode::no_table, "you are at no table");
        // The players choose their opponent; a spectator must not change the game.
        if (client.seat == 0)
            return send_error(client, ErrorCode::not_seated,
                              "only a player seated here seats the computer");
        SeatSlot& slot = table->seats[request.seat - 1];
        if (!slot.token_hash.empty() || (slot.computer && request.level && started(*table)))
            return send_error(client, ErrorCode::seat_taken, "that seat is taken");
        if (!request.level && (!slot.computer || started(*table)))
            return send_error(client, ErrorCode::refused, "no computer to unseat");
        if (over(*table))
            return send_error(client, ErrorCode::refused, "the match is over");
        table->match.seat_computer(request.seat, request.level);
        table->match.rename(request.seat, request.level ? computer_name(*request.level)
                                                        : default_name(request.seat));
        slot.computer = request.level.has_value();
        save(*table);
        seat_changed(*table, request.seat);
        think(*table);
    }

    void on_message(Client& client, const ClientMessage& message) {
        if (!client.welcomed && !std::holds_alternative<Hello>(message))
            return send_error(client, ErrorCode::hello_first, "say hello first");
        // An action at a table waits for its save (settle) until the round ends, unless a
        // message could see or change that table first: every message but an action, an aim
        // or a chat line at the sender's own table settles the round's actions before it is
        // handled, so that it finds each table as if every action had been saved at once.
        const bool own_table_only =
            std::holds_alternative<Act>(message) || std::holds_alternative<NextRack>(message) ||
            std::holds_alternative<Aim>(message) || std::holds_alternative<Chat>(message) ||
            std::holds_alternative<Ping>(message);
        if (const Table* own = table_of(client);
            !batch.empty() && (!own_table_only || (own && own->saving)))
            settle();
        if (const auto* m = std::get_if<Hello>(&message))
            return on_hello(client, *m);
        // The requests that send a record or change the lobby have a budget, so that one
        // client cannot make the hall busy for everyone.
        const bool costly =
            std::holds_alternative<Create>(message) || std::holds_alternative<Sit>(message) ||
            std::holds_alternative<Watch>(message) || std::holds_alternative<Leave>(message) ||
            std::holds_alternative<Sync>(message);
        if (costly &&
            !client.requests.take(options.request_rate, options.request_burst, Clock::now()))
            return send_error(client, ErrorCode::rate, "too many requests: slow down");
        if (const auto* m = std::get_if<Create>(&message))
            return on_create(client, *m);
        if (const auto* m = std::get_if<Sit>(&message))
            return on_sit(client, *m);
        if (const auto* m = std::get_if<Watch>(&message))
            return on_watch(client, *m);
        if (std::holds_alternative<Leave>(message)) {
            const int number = client.table;
            if (number == 0)
                return send_error(client, ErrorCode::no_table, "you are at no table");
            leave_table(client);
            return send(client, Left{number});
        }
        if (const auto* m = std::get_if<Act>(&message))
            return on_act(client, m->action);
        if (std::holds_alternative<NextRack>(message)) {
            RecordedAction rack;
            rack.kind = RecordedAction::Kind::rack;
            return on_act(client, rack);
        }
        if (const auto* m = std::get_if<Aim>(&message))
            return on_aim(client, *m);
        if (const auto* m = std::get_if<Chat>(&message))
            return on_chat(client, *m);
        if (const auto* m = std::get_if<SeatComputer>(&message))
            return on_computer(client, *m);
        if (std::holds_alternative<Sync>(message)) {
            Table* table = table_of(client);
            if (!table)
                return send_error(client, ErrorCode::no_table, "you are at no table");
            log("client " + std::to_string(client.id) + " resynchronises table " +
                std::to_string(table->number));
            return send_record(client, *table);
        }
        send(client, Pong{});
    }

    void on_line(Client& client, std::string_view line) {
        auto parsed = parse_client(line);
        if (const auto* error = std::get_if<ProtocolError>(&parsed)) {
            if (error->code == ErrorCode::version)
                return send_and_close(client, ErrorCode::version, error->text);
            return send_error(client, error->code, error->text);
        }
        on_message(client, std::get<ClientMessage>(parsed));
    }

    // --- sockets ---------------------------------------------------------------------------

    void accept_clients() {
        // A few at a time, so that a flood of connections cannot starve the others' input.
        for (int i = 0; i < 16; ++i) {
            UniqueFd fd(::accept(listener.get(), nullptr, nullptr));
            if (!fd) {
                if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
                    log(std::string("accept: ") + std::strerror(errno) + ": pausing 100 ms");
                    accept_paused_until = Clock::now() + std::chrono::milliseconds(100);
                }
                return;
            }
            if (!make_nonblocking(fd.get()))
                continue;
            Client client(next_client_id++, Connection(std::move(fd)), Clock::now());
            const auto unwelcomed =
                std::count_if(clients.begin(), clients.end(), [](const auto& e) {
                    return !e.second.welcomed && !e.second.closing;
                });
            if (unwelcomed >= options.max_unwelcomed) {
                send_and_close(client, ErrorCode::full, "too many connections wait for hello");
                continue; // closed as it goes out of scope
            }
            clients.emplace(client.id, std::move(client));
        }
    }

    // Reads what the socket holds only once the lines read before are handled (the input
    // buffer stays bounded), then handles at most lines_per_round of them: a client that
    // sends a flood waits its turn behind the others, round by round.
    void serve_client(Client& client, bool readable) {
        if (readable && !client.connection.has_line()) {
            switch (client.connection.read()) {
            case Connection::ReadResult::closed:
                client.closing = true;
                return;
            case Connection::ReadResult::too_long:
                send_and_close(client, ErrorCode::too_long,
                               "a line is at most " + std::to_string(max_line_bytes) + " bytes");
                return;
            case Connection::ReadResult::ok:
                break;
            }
        }
        for (int i = 0; i < options.lines_per_round && client.connection.has_line(); ++i) {
            if (client.closing)
                return;
            on_line(client, client.connection.take_line());
        }
    }

    void drop_closed() {
        std::vector<int> closed;
        for (auto& [id, client] : clients)
            if (client.closing)
                closed.push_back(id);
        for (const int id : closed) {
            Client& client = clients.at(id);
            const int number = client.table;
            const std::string token_hash = client.token_hash;
            leave_table(client);
            clients.erase(id);
            if (auto found = tables.find(number); found != tables.end())
                forget_if_idle(found->second);
            forget_waiting_tables_of(token_hash);
            lobby_dirty = true;
        }
    }

    // A creator gone (and not connected again elsewhere) takes the tables they made and
    // nobody came to: a table not started, nobody at it.
    void forget_waiting_tables_of(const std::string& token_hash) {
        if (token_hash.empty())
            return;
        for (const auto& [id, client] : clients)
            if (client.token_hash == token_hash && !client.closing)
                return;
        std::vector<int> numbers;
        for (const auto& [number, table] : tables)
            if (table.creator == token_hash && !started(table))
                numbers.push_back(number);
        for (const int number : numbers)
            forget_if_idle(tables.at(number));
    }

    std::string listen_on(const std::string& path) {
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        if (path.empty() || path.size() >= sizeof address.sun_path)
            return "socket path too long (at most " + std::to_string(sizeof address.sun_path - 1) +
                   " bytes): " + path;
        std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
        const auto* raw = reinterpret_cast<const sockaddr*>(&address);

        // A socket of ours that nobody answers on is a dead server's: replace it. One that
        // answers is a live hall's; anything else at the path is not ours to delete.
        struct stat st {};
        if (::lstat(path.c_str(), &st) == 0) {
            if (!S_ISSOCK(st.st_mode) || st.st_uid != ::getuid())
                return path + ": not a socket of this user's: it is left alone";
            const UniqueFd probe(::socket(AF_UNIX, SOCK_STREAM, 0));
            if (probe && ::connect(probe.get(), raw, sizeof address) == 0)
                return "a hall already serves on " + path;
            if (errno != ECONNREFUSED)
                return path + ": " + std::strerror(errno);
            ::unlink(path.c_str());
        }
        listener = UniqueFd(::socket(AF_UNIX, SOCK_STREAM, 0));
        if (!listener || !make_nonblocking(listener.get()))
            return std::string("socket: ") + std::strerror(errno);
        if (::bind(listener.get(), raw, sizeof address) != 0)
            return path + ": " + std::strerror(errno);
        made_socket = true;
        if (::stat(path.c_str(), &st) == 0)
            socket_id = {st.st_dev, st.st_ino};
        if (::listen(listener.get(), 64) != 0)
            return path + ": " + std::strerror(errno);
        return {};
    }
};

Server::Server(ServerOptions options) : state_(std::make_unique<State>(std::move(options))) {}

Server::~Server() {
    // The workers stop before the sockets close (the pool is a member, destroyed with state_).
    // Only the socket it made: another server may have replaced it since.
    struct stat st {};
    const std::string& path = state_->options.socket_path;
    if (state_->made_socket && ::lstat(path.c_str(), &st) == 0 &&
        std::pair{st.st_dev, st.st_ino} == state_->socket_id)
        ::unlink(path.c_str());
}

std::string Server::open() {
    State& s = *state_;
    if (!s.stop_pipe.open() || !s.pool.ok())
        return std::string("pipe: ") + std::strerror(errno);
    if (std::string problem = s.listen_on(s.options.socket_path); !problem.empty())
        return problem;
    s.restore();
    s.log("serving on " + s.options.socket_path);
    return {};
}

void Server::stop() {
    state_->stop_pipe.wake();
}

std::size_t Server::table_count() const {
    return state_->table_count;
}

int Server::run() {
    State& s = *state_;
    std::vector<pollfd> fds;
    std::vector<int> ids; // the client of fds[i + 3]
    for (;;) {
        fds.clear();
        ids.clear();
        fds.push_back({s.stop_pipe.read_end.get(), POLLIN, 0});
        fds.push_back({s.pool.wake_fd(), POLLIN, 0});
        const auto now = Clock::now();
        if (s.accept_paused_until && now >= *s.accept_paused_until)
            s.accept_paused_until.reset();
        // A negative fd is left out by poll.
        fds.push_back({s.accept_paused_until ? -1 : s.listener.get(), POLLIN, 0});
        bool lines_waiting = false; // lines read and not handled yet: poll must not sleep
        for (auto& [id, client] : s.clients) {
            const bool waiting = client.connection.has_line() && !client.closing;
            lines_waiting = lines_waiting || waiting;
            const short events = static_cast<short>(
                (waiting ? 0 : POLLIN) | (client.connection.wants_write() ? POLLOUT : 0));
            fds.push_back({client.connection.fd(), events, 0});
            ids.push_back(id);
        }
        // A lobby change left over from the last round (a connection dropped) goes out now.
        const int aim = s.aim_timeout(now);
        const int away = s.away_timeout(now);
        int timeout = aim < 0 ? away : away < 0 ? aim : std::min(aim, away);
        const int paused = s.accept_paused_until
                               ? static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(
                                                      *s.accept_paused_until - now)
                                                      .count())
                               : -1;
        for (const int due : {s.lobby_timeout(now), s.hello_timeout(now), paused})
            if (due >= 0)
                timeout = timeout < 0 ? due : std::min(timeout, due);
        if (lines_waiting)
            timeout = 0;
        if (::poll(fds.data(), fds.size(), timeout) < 0 && errno != EINTR) {
            s.log(std::string("poll: ") + std::strerror(errno));
            break;
        }
        s.woke = Clock::now();
        if (fds[0].revents & POLLIN)
            break;
        if (fds[1].revents & POLLIN)
            s.computer_answers();
        if (fds[2].revents & POLLIN)
            s.accept_clients();
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const auto found = s.clients.find(ids[i]);
            if (found == s.clients.end() || found->second.closing)
                continue;
            const bool readable = fds[i + 3].revents & (POLLIN | POLLHUP | POLLERR);
            if (readable || found->second.connection.has_line())
                s.serve_client(found->second, readable);
        }
        s.settle();
        s.flush_aims(Clock::now());
        s.drop_closed();
        s.expire_away(Clock::now());
        s.expire_unwelcomed(Clock::now());
        s.send_lobbies(Clock::now());
        for (auto& [id, client] : s.clients)
            if (!client.closing && client.connection.wants_write() && !client.connection.flush())
                client.closing = true;
        s.drop_closed();
    }

    int status = 0;
    for (auto& [number, table] : s.tables)
        if (!s.save(table))
            status = 1;
    s.log_figures();
    s.log("stopped with " + std::to_string(s.tables.size()) + " tables saved");
    return status;
}

} // namespace termpool::hall
