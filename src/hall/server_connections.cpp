// The hall server's connections: the listening socket, accepting, reading lines, sending
// (each client's queue bounded), and connections that go.

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "hall/server_state.hpp"

namespace termpool::hall {

void Server::State::send(Client& client, const ServerMessage& message) {
    if (client.closing)
        return;
    if (!client.connection.queue(format_server(message), options.output_limit)) {
        log("client " + std::to_string(client.id) + " stopped reading: disconnected");
        client.closing = true;
    }
}

void Server::State::send_bulk(Client& client, const std::string& text) {
    if (!client.closing &&
        !client.connection.queue_bulk(text, options.output_limit, options.record_allowance)) {
        log("client " + std::to_string(client.id) + " stopped reading: disconnected");
        client.closing = true;
    }
}

void Server::State::send_error(Client& client, ErrorCode code, const std::string& text) {
    send(client, Error{code, text});
    // A budget that refills: a player who now and then sends something stale (a lobby row that
    // just went, a second Enter) over a long evening is not cut off; a flood is.
    if (!client.errors.take(options.error_rate, std::max(0, options.max_errors - 1),
                            Clock::now())) {
        log("client " + std::to_string(client.id) + ": too many errors, disconnected");
        client.closing = true;
    }
}

// Sends what can go now and ends the connection (after a fatal error).
void Server::State::send_and_close(Client& client, ErrorCode code, const std::string& text) {
    send(client, Error{code, text});
    client.connection.flush();
    // The end of the stream follows the reply, so the peer reads it before the close
    // rather than lose it to a reset (its unread input is discarded with the socket).
    ::shutdown(client.connection.fd(), SHUT_WR);
    client.closing = true;
}

void Server::State::send_to_table(const Table& table, const ServerMessage& message, int except) {
    const std::string line = format_server(message);
    for (auto& [id, client] : clients)
        if (client.table == table.number && id != except && !client.closing &&
            !client.connection.queue(line, options.output_limit)) {
            log("client " + std::to_string(id) + " stopped reading: disconnected");
            client.closing = true;
        }
}

// A connection that has not said hello within hello_timeout goes: a silent one must not
// hold a place.
void Server::State::expire_unwelcomed(Clock::time_point now) {
    for (auto& [id, client] : clients)
        if (!client.welcomed && !client.closing &&
            now - client.connected_at >= options.hello_timeout) {
            log("client " + std::to_string(id) + " said no hello: disconnected");
            send_and_close(client, ErrorCode::hello_first, "no hello in time");
        }
}

// Milliseconds until a connection's hello is due, -1 for none.
int Server::State::hello_timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const auto& [id, client] : clients)
        if (!client.welcomed && !client.closing) {
            const auto due = client.connected_at + options.hello_timeout - now;
            const int ms = static_cast<int>(
                std::max<long long>(0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
            timeout = timeout < 0 ? ms : std::min(timeout, ms);
        }
    return timeout;
}

void Server::State::accept_clients() {
    // A few at a time, so that a flood of connections cannot starve the others' input.
    for (int i = 0; i < 16; ++i) {
        UniqueFd fd(::accept(listener.get(), nullptr, nullptr));
        if (!fd) {
            if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
                log_repeated(0, "accept",
                             std::string("accept: ") + std::strerror(errno) + ": pausing 100 ms");
                accept_paused_until = Clock::now() + std::chrono::milliseconds(100);
                ++accept_pauses;
            }
            return;
        }
        if (!make_nonblocking(fd.get()))
            continue;
        Client client(next_client_id++, Connection(std::move(fd)), Clock::now());
        const auto unwelcomed = std::count_if(clients.begin(), clients.end(), [](const auto& e) {
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
void Server::State::serve_client(Client& client, bool readable) {
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

void Server::State::drop_closed() {
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
