#include "hall/hall_who.hpp"

#include <chrono>
#include <iostream>

#include "hall/client.hpp"
#include "hall/socket_dir.hpp"
#include "hall/socket_trust.hpp"

namespace termpool::hall {

namespace {

// How long the hall has to answer in all, and the most lines its answer may hold (a full hall,
// 100 tables and 256 connections, is under 400).
constexpr std::chrono::seconds answer_wait{5};
constexpr std::size_t max_answer_lines = 10000;

int fail(const std::string& why) {
    std::cerr << "termpool hall who: " << why << '\n';
    return 1;
}

} // namespace

int hall_who_command(const std::vector<std::string>& args) {
    std::string socket_path;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--socket" && i + 1 < args.size()) {
            socket_path = args[++i];
        } else {
            std::cerr << "termpool hall who: unknown argument '" << args[i]
                      << "'\nusage: termpool hall who [--socket PATH]\n";
            return 2;
        }
    }
    if (socket_path.empty())
        socket_path = default_socket_path();
    if (const std::string problem = check_socket_path(socket_path); !problem.empty())
        return fail(problem);
    HallClient client;
    if (const std::string problem = client.connect(socket_path); !problem.empty())
        return fail("no hall answers on " + socket_path + ": " + problem);
    if (const std::string problem = check_peer(client.fd(), socket_path); !problem.empty())
        return fail(problem);
    if (!client.send(Who{}))
        return fail("the hall on " + socket_path + " closed the connection");
    const auto deadline = std::chrono::steady_clock::now() + answer_wait;
    for (std::size_t lines = 0; lines <= max_answer_lines;) {
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0)
            return fail("the hall on " + socket_path + " did not answer within 5 s");
        const auto message = client.receive(left);
        if (!message) {
            if (client.closed())
                return fail("the hall on " + socket_path + " closed the connection");
            continue;
        }
        if (const auto* line = std::get_if<WhoLine>(&*message)) {
            std::cout << line->text << '\n';
            ++lines;
        } else if (std::holds_alternative<WhoEnd>(*message)) {
            return 0;
        } else if (const auto* error = std::get_if<Error>(&*message)) {
            return fail("the hall refused: " + error->text);
        }
    }
    return fail("the hall's answer is longer than " + std::to_string(max_answer_lines) + " lines");
}

} // namespace termpool::hall
