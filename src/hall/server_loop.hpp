#pragma once
// The hall server's connection layer: the listening socket, each client's Connection, and
// the hall core they talk to. Shared by server.cpp (the poll loop) and server_connections.cpp
// only; the public face is server.hpp, the tables and people are the core's (hall_core.hpp).

#include <atomic>
#include <chrono>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <sys/types.h>
#include <utility>

#include "hall/connection.hpp"
#include "hall/hall_core.hpp"
#include "hall/server.hpp"
#include "hall/unique_fd.hpp"

namespace termpool::hall {

struct Server::State {
    using Clock = std::chrono::steady_clock;

    // A client's socket, and whether it is to be closed at the end of the round.
    struct Link {
        Connection connection;
        bool closing = false;
    };

    ServerOptions options;
    UniqueFd listener;
    bool made_socket = false;
    std::pair<dev_t, ino_t> socket_id{}; // the socket file it made, to remove only that one
    WakePipe stop_pipe;
    std::map<int, Link> links; // by client id, as the core knows them
    HallCore core;             // after links: it asks how much waits in a link's queue
    int next_client_id = 1;
    // Out of file descriptors, accept fails while the listener stays readable: it is left out
    // of poll until then, rather than spin.
    std::optional<Clock::time_point> accept_paused_until;
    std::atomic<std::size_t> rounds{0};        // returns of poll (Server::rounds)
    std::atomic<std::size_t> accept_pauses{0}; // accept_paused_until set (Server::accept_pauses)
    Clock::time_point woke;                    // when poll last returned

    explicit State(ServerOptions o)
        : options(std::move(o)),
          core(
              options,
              [this](int id) {
                  const auto found = links.find(id);
                  return found == links.end() ? std::size_t{0} : found->second.connection.queued();
              },
              [] { return Clock::now(); }) {}

    // --- server_connections.cpp: sockets, the core's outbox turned into bytes
    void deliver();
    void accept_clients();
    void serve_client(int id, Link& link, bool readable);
    void drop_closed();
    void flush_all();
    std::string listen_on(const std::string& path);
};

} // namespace termpool::hall
