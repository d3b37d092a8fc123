// The hall's poll loop. Plain POSIX sockets and poll(2), one thread: the hall needs no
// dependency for this, and its load is small (a few hundred connections, a few messages a
// second each); tmux uses libevent for portability to systems we do not target. The computer
// seats think on a small worker pool (computer_pool.hpp) so that no search stalls the loop,
// and the actions a round took are saved side by side on a work crew (work_crew.hpp): each
// save waits for the disk, and a hundred tables' saves one after the other held every table
// up behind them.
//
// The loop's state and its pieces are in server_state.hpp; each server_*.cpp holds one part:
// connections, the lobby, seats, the game's actions, persistence, and the messages' dispatch.

#include "hall/server.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "hall/server_state.hpp"

namespace termpool::hall {

using serving::Clock;

// With idle_exit set, a hall nobody uses goes: no connection and no table for idle_exit in a
// row (counted from when it last had one, or from its start).
bool Server::State::idle_for_good(Clock::time_point now) {
    if (!clients.empty() || !tables.empty()) {
        idle_since.reset();
        return false;
    }
    if (!idle_since)
        idle_since = now;
    if (options.idle_exit.count() <= 0 || now - *idle_since < options.idle_exit)
        return false;
    log("no connection and no table for " + std::to_string(options.idle_exit.count()) +
        " s: exiting");
    return true;
}

// Milliseconds until the hall has been idle for idle_exit, -1 for never.
int Server::State::idle_timeout(Clock::time_point now) const {
    if (options.idle_exit.count() <= 0 || !idle_since)
        return -1;
    const auto due = *idle_since + options.idle_exit - now;
    return static_cast<int>(
        std::clamp<long long>(std::chrono::ceil<std::chrono::milliseconds>(due).count(), 0,
                              std::numeric_limits<int>::max()));
}

// How long actions took to handle (`termpool hall bench` reads these two lines).
void Server::State::log_figures() const {
    char line[200];
    std::snprintf(line, sizeof line,
                  "handling: %llu actions, p50 %.2f ms, p99 %.2f ms (from the loop's "
                  "wake-up to the broadcast queued)",
                  static_cast<unsigned long long>(handling.count()), handling.percentile_ms(0.5),
                  handling.percentile_ms(0.99));
    log(line);
    std::snprintf(line, sizeof line,
                  "saving: %llu rounds of saves, p50 %.2f ms, p99 %.2f ms (a round's saves "
                  "side by side)",
                  static_cast<unsigned long long>(saving.count()), saving.percentile_ms(0.5),
                  saving.percentile_ms(0.99));
    log(line);
}

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

std::size_t Server::rounds() const {
    return state_->rounds;
}

std::size_t Server::accept_pauses() const {
    return state_->accept_pauses;
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
        if (s.idle_for_good(now))
            break;
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
        for (const int due :
             {s.lobby_timeout(now), s.hello_timeout(now), paused, s.idle_timeout(now)})
            if (due >= 0)
                timeout = timeout < 0 ? due : std::min(timeout, due);
        if (lines_waiting)
            timeout = 0;
        if (::poll(fds.data(), fds.size(), timeout) < 0 && errno != EINTR) {
            s.log(std::string("poll: ") + std::strerror(errno));
            break;
        }
        s.woke = Clock::now();
        ++s.rounds;
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
