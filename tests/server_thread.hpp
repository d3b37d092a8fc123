#pragma once
// A hall server in the test's own process, on `dir`/hall.sock with its state in `dir`, serving
// on a thread until destroyed.

#include <catch2/catch.hpp>
#include <memory>
#include <string>
#include <thread>

#include "hall/server.hpp"

namespace termpool::test {

/// A server serving on a thread from construction until destruction.
class ServerThread {
public:
    /// Opens a server on `dir`/hall.sock, its tables in `dir`; the test stops if it cannot.
    ServerThread(const std::string& dir, hall::ServerOptions options) {
        options.socket_path = dir + "/hall.sock";
        options.state_dir = dir;
        server_ = std::make_unique<hall::Server>(options);
        REQUIRE(server_->open() == "");
        thread_ = std::thread([this] { server_->run(); });
    }
    ~ServerThread() {
        server_->stop();
        thread_.join();
    }
    ServerThread(const ServerThread&) = delete;
    ServerThread& operator=(const ServerThread&) = delete;

private:
    std::unique_ptr<hall::Server> server_;
    std::thread thread_;
};

} // namespace termpool::test
