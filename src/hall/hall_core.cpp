// The hall core's outbox, its clients coming and going, the end of a round, and its figures.
// The other parts are in hall_core_*.cpp: the lobby, seats, the game's actions, persistence,
// and the messages' dispatch.

#include <sys/stat.h>

#include "hall/hall_core.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <poll.h>

namespace termpool::hall {

HallCore::HallCore(ServerOptions options, QueuedBytes queued, Stopwatch stopwatch)
    : options_(std::move(options)), queued_(std::move(queued)), stopwatch_(std::move(stopwatch)),
      pool_(options_.computer_threads),
      random_(options_.deal_seed ? *options_.deal_seed : std::random_device{}()),
      savers_(std::max(0, options_.save_threads - 1)) {}

HallCore::~HallCore() = default;

void HallCore::log(const std::string& line) const {
    if (options_.log)
        options_.log->write(line);
}

void HallCore::log_repeated(int client, std::string_view kind, const std::string& line) const {
    if (options_.log)
        options_.log->write_repeated(client, kind, line);
}

void HallCore::send(Client& client, const ServerMessage& message) {
    send_text(client, format_server(message));
}

// Lines for one client in a row go out as one entry: a record is a few hundred lines.
void HallCore::send_text(Client& client, std::string text) {
    if (client.closing)
        return;
    if (!outbox_.empty() && outbox_.back().client == client.id && !outbox_.back().close &&
        !outbox_.back().bulk)
        outbox_.back().text += text;
    else
        outbox_.push_back(Outgoing{client.id, std::move(text), false});
}

// A record: an entry of its own, which the connection queues with the record's allowance.
void HallCore::send_bulk(Client& client, std::string text) {
    if (!client.closing)
        outbox_.push_back(Outgoing{client.id, std::move(text), false, true});
}

void HallCore::send_error(Client& client, ErrorCode code, const std::string& text,
                          Clock::time_point now) {
    send(client, Error{code, text});
    // A budget that refills: a player who now and then sends something stale (a lobby row that
    // just went, a second Enter) over a long evening is not cut off; a flood is.
    if (!client.errors.take(options_.error_rate, std::max(0, options_.max_errors - 1), now)) {
        log("client " + std::to_string(client.id) + ": too many errors, disconnected");
        close(client);
    }
}

void HallCore::close(Client& client) {
    if (client.closing)
        return;
    outbox_.push_back(Outgoing{client.id, {}, true});
    client.closing = true;
}

// Sends the error and ends the connection (after a fatal error): the connection layer sends
// what it can now and closes its writing side, so that the peer reads the reply before the
// close rather than lose it to a reset.
void HallCore::send_and_close(Client& client, ErrorCode code, const std::string& text) {
    if (client.closing)
        return;
    outbox_.push_back(Outgoing{client.id, format_server(Error{code, text}), true});
    client.closing = true;
}

void HallCore::send_to_table(const Table& table, const ServerMessage& message, int except) {
    const std::string line = format_server(message);
    for (auto& [id, client] : clients_)
        if (client.table == table.number && id != except)
            send_text(client, line);
}

void HallCore::on_connect(int client, Clock::time_point now) {
    clients_.emplace(client, Client(client, now));
    const auto unwelcomed = std::count_if(clients_.begin(), clients_.end(), [](const auto& e) {
        return !e.second.welcomed && !e.second.closing;
    });
    if (unwelcomed > options_.max_unwelcomed)
        evict_for_newcomer(clients_.at(client));
}

void HallCore::on_disconnect(int client, Clock::time_point now) {
    if (!clients_.count(client))
        return;
    // The seat it leaves must see the round's actions taken first (a leave renames the seat of
    // a game not started, which an action waiting for its save would undo).
    if (!batch_.empty())
        settle(now);
    drop(client, now);
}

void HallCore::on_computer_answers(Clock::time_point now) {
    computer_answers(pool_.take_answers(), now);
}

bool HallCore::await_computer(std::chrono::milliseconds timeout, Clock::time_point now) {
    pollfd p{pool_.wake_fd(), POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0)
        return false;
    std::vector<ComputerJob> answers = pool_.take_answers();
    const bool any = !answers.empty();
    computer_answers(std::move(answers), now);
    return any;
}

void HallCore::tick(Clock::time_point now) {
    settle(now);
    flush_aims(now);
    drop_closed(now);
    expire_away(now);
    archive_idle(now);
    expire_unwelcomed(now);
    send_lobbies(now);
}

int HallCore::timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const int due : {aim_timeout(now), away_timeout(now), lobby_timeout(now),
                          hello_timeout(now), idle_timeout(now), archive_timeout(now)})
        if (due >= 0)
            timeout = timeout < 0 ? due : std::min(timeout, due);
    return timeout;
}

// A connection that has not said hello within hello_timeout goes: a silent one must not
// hold a place.
void HallCore::expire_unwelcomed(Clock::time_point now) {
    for (auto& [id, client] : clients_)
        if (!client.welcomed && !client.closing &&
            now - client.connected_at >= options_.hello_timeout) {
            log("client " + std::to_string(id) + " said no hello: disconnected");
            send_and_close(client, ErrorCode::hello_first, "no hello in time");
        }
}

// Milliseconds until a connection's hello is due, -1 for none.
int HallCore::hello_timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const auto& [id, client] : clients_)
        if (!client.welcomed && !client.closing) {
            const auto due = client.connected_at + options_.hello_timeout - now;
            const int ms = static_cast<int>(
                std::max<long long>(0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
            timeout = timeout < 0 ? ms : std::min(timeout, ms);
        }
    return timeout;
}

void HallCore::drop_closed(Clock::time_point now) {
    std::vector<int> closed;
    for (auto& [id, client] : clients_)
        if (client.closing)
            closed.push_back(id);
    for (const int id : closed)
        drop(id, now);
}

// Client `id` goes: its seat goes away (or is freed), and the tables nobody will come back to.
void HallCore::drop(int id, Clock::time_point now) {
    Client& client = clients_.at(id);
    client.closing = true;
    const int number = client.table;
    const std::string token_hash = client.token_hash;
    leave_table(client, now);
    clients_.erase(id);
    if (auto found = tables_.find(number); found != tables_.end())
        forget_if_idle(found->second);
    forget_waiting_tables_of(token_hash);
    lobby_dirty_ = true;
}

// With idle_exit set, a hall nobody uses goes: nobody connected, no search or save under way,
// and no table that lives only here, for idle_exit in a row (counted from when it last had one,
// or from its start). With a state folder every table is on disk as it stands (each change is
// saved before it is taken), so an unfinished game does not keep the process: the next
// `termpool hall` starts the hall again and it restores the table, its away seats counting
// from the file's last change as before.
bool HallCore::idle_for_good(Clock::time_point now) {
    const bool searching = std::any_of(tables_.begin(), tables_.end(),
                                       [](const auto& entry) { return entry.second.searching; });
    const bool tables_held = !tables_.empty() && (options_.state_dir.empty() || !unsaved_.empty());
    if (!clients_.empty() || tables_held || searching || !batch_.empty()) {
        idle_since_.reset();
        return false;
    }
    if (!idle_since_)
        idle_since_ = now;
    if (options_.idle_exit.count() <= 0 || now - *idle_since_ < options_.idle_exit)
        return false;
    log("no connection for " + std::to_string(options_.idle_exit.count()) +
        " s and every table saved: exiting (" + serving::tables_count(tables_.size()) +
        " in the state folder)");
    return true;
}

int HallCore::idle_timeout(Clock::time_point now) const {
    if (options_.idle_exit.count() <= 0 || !idle_since_)
        return -1;
    const auto due = *idle_since_ + options_.idle_exit - now;
    return static_cast<int>(
        std::clamp<long long>(std::chrono::ceil<std::chrono::milliseconds>(due).count(), 0,
                              std::numeric_limits<int>::max()));
}

// Only the tables whose last save failed (or that have no file): every other one is on disk
// as it stands, and writing it again would move its file's date, which a restored away seat
// counts from.
std::size_t HallCore::save_all() {
    std::size_t failed = 0;
    for (auto& [number, table] : tables_) {
        struct stat st {};
        const bool on_disk = options_.state_dir.empty() ||
                             ::stat(table_path(options_.state_dir, number).c_str(), &st) == 0;
        if ((unsaved_.count(number) || !on_disk) && !save(table).empty())
            ++failed;
    }
    return failed;
}

// How long actions took to handle (`termpool hall bench` reads these two lines).
void HallCore::log_figures() const {
    char line[200];
    std::snprintf(line, sizeof line,
                  "handling: %llu actions, p50 %.2f ms, p99 %.2f ms (from the loop's "
                  "wake-up to the broadcast queued)",
                  static_cast<unsigned long long>(handling_.count()), handling_.percentile_ms(0.5),
                  handling_.percentile_ms(0.99));
    log(line);
    std::snprintf(line, sizeof line,
                  "saving: %llu rounds of saves, p50 %.2f ms, p99 %.2f ms (a round's saves "
                  "side by side)",
                  static_cast<unsigned long long>(saving_.count()), saving_.percentile_ms(0.5),
                  saving_.percentile_ms(0.99));
    log(line);
}

} // namespace termpool::hall
