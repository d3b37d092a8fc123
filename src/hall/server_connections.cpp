// The hall server's connections: the listening socket, accepting, reading lines for the
// hall core, and sending what the core says (each client's queue bounded: a client that
// stops reading is cut off).

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>
#include <vector>

#include "hall/server_loop.hpp"

namespace termpool::hall {

// The core's outbox, queued on each client's connection; a connection the core ends sends
// what it can now and closes its writing side, so that the peer reads the last reply before
// the close rather than lose it to a reset (its unread input is discarded with the socket).
void Server::State::deliver() {
    for (Outgoing& out : core.take_outbox()) {
        const auto found = links.find(out.client);
        if (found == links.end() || found->second.closing)
            continue;
        Link& link = found->second;
        // A record goes as one bulk with an allowance of its own (Connection::queue_bulk).
        const bool queued = out.text.empty() ||
                            (out.bulk ? link.connection.queue_bulk(out.text, options.output_limit,
                                                                   options.record_allowance)
                                      : link.connection.queue(out.text, options.output_limit));
        if (!queued) {
            core.log("client " + std::to_string(out.client) + " stopped reading: disconnected");
            link.closing = true;
            continue;
        }
        if (out.close) {
            link.connection.flush();
            ::shutdown(link.connection.fd(), SHUT_WR);
            link.closing = true;
        }
    }
}

void Server::State::accept_clients() {
    // A few at a time, so that a flood of connections cannot starve the others' input.
    for (int i = 0; i < 16; ++i) {
        UniqueFd fd(::accept(listener.get(), nullptr, nullptr));
        if (!fd) {
            if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
                core.log_repeated(0, "accept",
                                  std::string("accept: ") + std::strerror(errno) +
                                      ": pausing 100 ms");
                accept_paused_until = Clock::now() + std::chrono::milliseconds(100);
                ++accept_pauses;
            }
            return;
        }
        if (!make_nonblocking(fd.get()))
            continue;
        const int id = next_client_id++;
        links.emplace(id, Link{Connection(std::move(fd)), false});
        core.on_connect(id, Clock::now());
        deliver();
    }
}

// Reads what the socket holds only once the lines read before are handled (the input
// buffer stays bounded), then hands the core at most lines_per_round of them: a client that
// sends a flood waits its turn behind the others, round by round.
void Server::State::serve_client(int id, Link& link, bool readable) {
    if (readable && !link.connection.has_line()) {
        switch (link.connection.read()) {
        case Connection::ReadResult::closed:
            link.closing = true;
            return;
        case Connection::ReadResult::too_long:
            link.connection.queue(
                format_server(
                    Error{ErrorCode::too_long,
                          "a line is at most " + std::to_string(max_line_bytes) + " bytes"}),
                options.output_limit);
            link.connection.flush();
            ::shutdown(link.connection.fd(), SHUT_WR);
            link.closing = true;
            return;
        case Connection::ReadResult::ok:
            break;
        }
    }
    for (int i = 0; i < options.lines_per_round && link.connection.has_line(); ++i) {
        if (link.closing)
            return;
        core.on_line(id, link.connection.take_line(), woke);
        deliver();
    }
}

// The connections to close go, and the core is told (their seats go away, which others see).
void Server::State::drop_closed() {
    for (;;) {
        std::vector<int> closed;
        for (const auto& [id, link] : links)
            if (link.closing)
                closed.push_back(id);
        if (closed.empty())
            return;
        for (const int id : closed) {
            links.erase(id);
            core.on_disconnect(id, Clock::now());
        }
        deliver();
    }
}

// Writes what each socket takes now.
void Server::State::flush_all() {
    for (auto& [id, link] : links)
        if (!link.closing && link.connection.wants_write() && !link.connection.flush())
            link.closing = true;
}

std::string Server::State::listen_on(const std::string& path) {
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

} // namespace termpool::hall
