// The hall's poll loop. Plain POSIX sockets and poll(2), one thread: the hall needs no
// dependency for this, and its load is small (a few hundred connections, a few messages a
// second each); tmux uses libevent for portability to systems we do not target. The computer
// seats think on a small worker pool (computer_pool.hpp) so that no search stalls the loop,
// and the actions a round took are saved side by side on a work crew (work_crew.hpp): each
// save waits for the disk, and a hundred tables' saves one after the other held every table
// up behind them.
//
// The loop turns bytes into lines for the hall core (hall_core.hpp: tables, seats, the lobby,
// the computer seats, the saves) and the core's outbox into bytes; its state is in
// server_loop.hpp, its connections in server_connections.cpp.

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

#include "hall/server_loop.hpp"

namespace termpool::hall {

using Clock = std::chrono::steady_clock;

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
    if (!s.stop_pipe.open() || !s.core.ok())
        return std::string("pipe: ") + std::strerror(errno);
    if (std::string problem = s.listen_on(s.options.socket_path); !problem.empty())
        return problem;
    s.core.restore(Clock::now(), std::chrono::system_clock::now());
    s.core.log("serving on " + s.options.socket_path);
    return {};
}

void Server::stop() {
    state_->stop_pipe.wake();
}

std::size_t Server::table_count() const {
    return state_->core.table_count();
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
        fds.push_back({s.core.computer_fd(), POLLIN, 0});
        const auto now = Clock::now();
        if (s.core.idle_for_good(now))
            break;
        if (s.accept_paused_until && now >= *s.accept_paused_until)
            s.accept_paused_until.reset();
        // A negative fd is left out by poll.
        fds.push_back({s.accept_paused_until ? -1 : s.listener.get(), POLLIN, 0});
        bool lines_waiting = false; // lines read and not handled yet: poll must not sleep
        for (auto& [id, link] : s.links) {
            const bool waiting = link.connection.has_line() && !link.closing;
            lines_waiting = lines_waiting || waiting;
            const short events = static_cast<short>((waiting ? 0 : POLLIN) |
                                                    (link.connection.wants_write() ? POLLOUT : 0));
            fds.push_back({link.connection.fd(), events, 0});
            ids.push_back(id);
        }
        // A lobby change left over from the last round (a connection dropped) goes out now.
        int timeout = s.core.timeout(now);
        if (s.accept_paused_until) {
            const int paused = static_cast<int>(
                std::chrono::ceil<std::chrono::milliseconds>(*s.accept_paused_until - now).count());
            timeout = timeout < 0 ? paused : std::min(timeout, paused);
        }
        if (lines_waiting)
            timeout = 0;
        if (::poll(fds.data(), fds.size(), timeout) < 0 && errno != EINTR) {
            s.core.log(std::string("poll: ") + std::strerror(errno));
            break;
        }
        s.woke = Clock::now();
        ++s.rounds;
        if (fds[0].revents & POLLIN)
            break;
        if (fds[1].revents & POLLIN) {
            s.core.on_computer_answers(s.woke);
            s.deliver();
        }
        if (fds[2].revents & POLLIN)
            s.accept_clients();
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const auto found = s.links.find(ids[i]);
            if (found == s.links.end() || found->second.closing)
                continue;
            const bool readable = fds[i + 3].revents & (POLLIN | POLLHUP | POLLERR);
            if (readable || found->second.connection.has_line())
                s.serve_client(found->first, found->second, readable);
        }
        s.core.tick(Clock::now());
        s.deliver();
        s.drop_closed();
        s.flush_all();
        s.drop_closed();
    }

    const std::size_t unsaved = s.core.save_all();
    s.core.log_figures();
    const std::size_t tables = s.core.table_count();
    if (unsaved == 0) {
        s.core.log("stopped with " + serving::tables_count(tables) + " saved");
        return 0;
    }
    s.core.log("stopped: " + std::to_string(unsaved) + " of " + std::to_string(tables) +
               " tables could not be saved (see above why); the rest are saved");
    return 1;
}

} // namespace termpool::hall
