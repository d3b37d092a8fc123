#include "hall/client.hpp"

#include <cerrno>
#include <cstring>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>

namespace termpool::hall {

std::string HallClient::connect(const std::string& socket_path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (socket_path.size() >= sizeof address.sun_path)
        return "socket path too long: " + socket_path;
    std::memcpy(address.sun_path, socket_path.c_str(), socket_path.size() + 1);
    UniqueFd fd(::socket(AF_UNIX, SOCK_STREAM, 0));
    if (!fd)
        return std::string("socket: ") + std::strerror(errno);
    if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0)
        return socket_path + ": " + std::strerror(errno);
    fd_ = std::move(fd);
    in_.clear();
    followed_.clear();
    table_ = seat_ = 0;
    bounds_.reset();
    broken_.clear();
    return {};
}

pid_t HallClient::server_pid() const {
    ucred peer{};
    socklen_t size = sizeof peer;
    if (!fd_ || ::getsockopt(fd_.get(), SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0)
        return 0;
    return peer.pid;
}

bool HallClient::send(const ClientMessage& message) {
    return send_raw(format_client(message));
}

bool HallClient::send_raw(std::string_view bytes) {
    while (fd_ && !bytes.empty()) {
        const ssize_t n = ::send(fd_.get(), bytes.data(), bytes.size(), MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            fd_.reset();
            return false;
        }
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return static_cast<bool>(fd_);
}

std::optional<ServerMessage> HallClient::receive(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        if (const std::size_t end = in_.find('\n'); end != std::string::npos) {
            const std::string line = in_.substr(0, end);
            in_.erase(0, end + 1);
            auto parsed = parse_server(line);
            if (std::holds_alternative<ProtocolError>(parsed)) {
                ++bad_lines_;
                return std::nullopt;
            }
            ServerMessage message = std::move(std::get<ServerMessage>(parsed));
            if (std::string why = bounds_.check(message); !why.empty()) {
                // Not a hall of ours: what it sends is not kept, the connection ends.
                broken_ = "the hall is broken: it sent " + why;
                in_.clear();
                followed_.clear();
                fd_.reset();
                return std::nullopt;
            }
            if (keep_copies_)
                follow(message);
            return message;
        }
        if (in_.size() >= max_line_bytes) {
            // No server of ours sends such a line: what follows cannot be read either.
            ++bad_lines_;
            in_.clear();
            fd_.reset();
            return std::nullopt;
        }
        if (!fd_)
            return std::nullopt;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        pollfd p{fd_.get(), POLLIN, 0};
        const int ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0)
            return std::nullopt;
        char buffer[65536];
        const ssize_t n = ::recv(fd_.get(), buffer, sizeof buffer, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            fd_.reset();
            continue; // what is buffered still reads
        }
        in_.append(buffer, static_cast<std::size_t>(n));
    }
}

std::optional<ServerMessage>
HallClient::wait_for(const std::function<bool(const ServerMessage&)>& done,
                     std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0)
            return std::nullopt;
        auto message = receive(left);
        if (message && done(*message))
            return message;
        if (!message && closed() && in_.find('\n') == std::string::npos)
            return std::nullopt;
    }
}

std::string HallClient::hello(const std::string& name, const std::string& token,
                              std::chrono::milliseconds timeout) {
    if (!send(Hello{protocol_version, token, name}))
        return "the hall closed the connection";
    const auto answer = wait_for(
        [](const ServerMessage& m) {
            return std::holds_alternative<Welcome>(m) || std::holds_alternative<Error>(m);
        },
        timeout);
    if (!answer)
        return "no welcome";
    if (const auto* e = std::get_if<Error>(&*answer))
        return std::string(error_code_name(e->code)) + ": " + e->text;
    token_ = std::get<Welcome>(*answer).token;
    return {};
}

const Match* HallClient::match(int number) const {
    const auto found = followed_.find(number);
    return found == followed_.end() || !found->second.match ? nullptr : &*found->second.match;
}

void HallClient::resync(int number, Followed& followed) {
    ++mismatches_;
    // What the copy came to goes with the request, for the server's log.
    Sync sync;
    if (followed.match) {
        sync.seq = followed.match->record().actions.size();
        sync.hash = followed.match->state_hash();
    }
    followed.match.reset();
    followed.record_text.clear();
    send(sync);
    (void)number;
}

void HallClient::follow(const ServerMessage& message) {
    if (const auto* m = std::get_if<Joined>(&message)) {
        table_ = m->table;
        seat_ = m->seat;
        followed_[m->table] = Followed{};
    } else if (const auto* m = std::get_if<Left>(&message)) {
        followed_.erase(m->table);
        table_ = seat_ = 0;
    } else if (const auto* m = std::get_if<RecordLine>(&message)) {
        followed_[m->table].record_text += m->text + "\n";
    } else if (const auto* m = std::get_if<RecordEnd>(&message)) {
        Followed& followed = followed_[m->table];
        const std::string text = std::exchange(followed.record_text, {});
        auto record = parse_record(text);
        followed.match.reset();
        if (const auto* r = std::get_if<GameRecord>(&record)) {
            auto replayed = Match::replay(*r);
            if (auto* match = std::get_if<Match>(&replayed))
                followed.match = std::move(*match);
        }
        // A record that does not rebuild the server's state cannot be fixed by asking again.
        if (!followed.match || followed.match->record().actions.size() != m->seq ||
            followed.match->state_hash() != m->hash)
            ++mismatches_;
    } else if (const auto* m = std::get_if<ActionDone>(&message)) {
        const auto found = followed_.find(m->table);
        if (found == followed_.end() || !found->second.match)
            return; // a sync is on its way, or the table is not followed
        Match& match = *found->second.match;
        if (match.record().actions.size() + 1 != m->seq ||
            match.apply(m->action) != MatchError::none || match.state_hash() != m->hash)
            resync(m->table, found->second);
    } else if (const auto* m = std::get_if<SeatChange>(&message)) {
        // Names are not in the hash, but a follower's record should read as the server's.
        const auto found = followed_.find(m->table);
        if (found != followed_.end() && found->second.match)
            found->second.match->rename(m->seat, m->view.kind == SeatKind::empty
                                                     ? "Player " + std::to_string(m->seat)
                                                     : m->view.name);
    }
}

} // namespace termpool::hall
