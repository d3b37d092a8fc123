#include "hall/hall_main.hpp"

#include "support/text_numbers.hpp"
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "files/atomic_file.hpp"
#include "hall/hall_bench.hpp"
#include "hall/hall_lock.hpp"
#include "hall/hall_log.hpp"
#include "hall/hall_state.hpp"
#include "hall/hall_who.hpp"
#include "hall/server.hpp"
#include "hall/socket_dir.hpp"
#include "hall/socket_trust.hpp"

namespace termpool::hall {

namespace {

constexpr const char* kUsage =
    "usage: termpool hall serve [--socket PATH] [--state DIR] [--max-clients N] [--max-tables N]\n"
    "                           [--idle-exit S] [--archive-after H] [--log FILE]\n"
    "                           [--log-cap BYTES]\n"
    "  serve            run the hall's server in the foreground (SIGTERM or SIGINT: save, exit)\n"
    "  --socket PATH    the Unix socket (default $XDG_RUNTIME_DIR/termpool/hall.sock, or\n"
    "                   /tmp/termpool-UID/hall.sock)\n"
    "  --state DIR      where tables are saved (default $XDG_STATE_HOME/termpool/hall)\n"
    "  --max-clients N  people in the hall at once (default 256)\n"
    "  --max-tables N   tables at once (default 100)\n"
    "  --idle-exit S    exit 0 after S seconds with nobody connected and every table saved\n"
    "                   (default 0: never)\n"
    "  --archive-after H\n"
    "                   a table nobody is at with no action for H hours leaves the lobby for\n"
    "                   the state folder's archive/ (default 24)\n"
    "  --log FILE       append the log to FILE (default: stderr); each line starts with its\n"
    "                   UTC time, a client's repeated lines are cut to one a minute\n"
    "  --log-cap BYTES  past this FILE is renamed FILE.1, over the older one (default 1048576;\n"
    "                   0: never)\n"
    "       termpool hall who [--socket PATH]\n"
    "  who              print a running hall's tables, people and connections (for its host)\n"
    "       termpool hall bench [--tables N] [--seconds S] [--think MS] [--seed S]\n"
    "  bench            play N tables of computers through a private server; print actions a\n"
    "                   second, the action round trip, the server's CPU and memory\n";

// The server a signal stops. A lock-free atomic pointer is safe to read in a handler, and
// Server::stop only writes a byte to a pipe.
std::atomic<Server*> signalled_server{nullptr};

extern "C" void on_stop_signal(int) {
    if (Server* server = signalled_server.load())
        server->stop();
}

int usage_error(const std::string& why) {
    std::cerr << "termpool hall: " << why << "\n\n" << kUsage;
    return 2;
}

int serve(const std::vector<std::string>& args) {
    ServerOptions options;
    HallLogOptions log_options;
    log_options.stream = &std::cerr;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--help" || arg == "-h") {
            std::cout << kUsage;
            return 0;
        }
        if (i + 1 >= args.size())
            return usage_error(arg.starts_with("--") ? arg + " needs a value"
                                                     : "unknown argument '" + arg + "'");
        const std::string& value = args[++i];
        if (arg == "--socket") {
            options.socket_path = value;
        } else if (arg == "--state") {
            options.state_dir = value;
        } else if (arg == "--max-clients" || arg == "--max-tables") {
            const auto n = parse_integer(value);
            if (!n || *n < 1 || *n > 100000)
                return usage_error(arg + " takes a whole number from 1 to 100000");
            (arg == "--max-clients" ? options.max_clients : options.max_tables) =
                static_cast<int>(*n);
        } else if (arg == "--idle-exit") {
            const auto n = parse_integer(value);
            if (!n || *n < 0 || *n > 1000000)
                return usage_error(arg + " takes a whole number of seconds from 0 to 1000000");
            options.idle_exit = std::chrono::seconds(*n);
        } else if (arg == "--archive-after") {
            const auto n = parse_integer(value);
            if (!n || *n < 1 || *n > 100000)
                return usage_error(arg + " takes a whole number of hours from 1 to 100000");
            options.archive_after = std::chrono::hours(*n);
        } else if (arg == "--log") {
            log_options.path = value;
        } else if (arg == "--log-cap") {
            const auto n = parse_integer(value);
            if (!n || *n < 0 || *n > (1ll << 40))
                return usage_error(arg + " takes a whole number of bytes from 0 to 2^40");
            log_options.cap_bytes = static_cast<std::uint64_t>(*n);
        } else {
            return usage_error("unknown option '" + arg + "'");
        }
    }
    HallLog log(log_options);
    options.log = &log;
    if (const std::string problem = log.open(); !problem.empty())
        std::cerr << "termpool hall: cannot keep the log in " << problem << "; it goes to stderr\n";
    // Why the server cannot start goes to the log too, where a hall started in the background
    // is looked into.
    const auto cannot_start = [&](const std::string& problem) {
        if (log_options.path.empty() || ::isatty(STDERR_FILENO))
            std::cerr << "termpool hall: " << problem << '\n';
        if (!log_options.path.empty())
            log.write(problem);
        return 1;
    };
    if (options.socket_path.empty())
        options.socket_path = default_socket_path();
    // tmux's rule: the socket's folder is ours alone, or the server does not start.
    if (const std::string problem = prepare_socket_dir(options.socket_path); !problem.empty())
        return cannot_start(problem);
    // One server per socket, even when two start at once (hall/hall_lock.hpp); held until exit.
    UniqueFd lock;
    if (const std::string problem = lock_hall(options.socket_path, lock); !problem.empty())
        return cannot_start(problem);
    if (options.state_dir.empty())
        options.state_dir = default_state_dir();
    if (const std::string problem = make_directories(options.state_dir); !problem.empty())
        return cannot_start(problem);
    // Whoever else could write there could plant a table with a seat token of their own; the
    // folder is used by its resolved path from here on.
    if (const std::string problem = check_state_folder(options.state_dir); !problem.empty())
        return cannot_start(problem);
    UniqueFd state_lock;
    if (const std::string problem = lock_state_dir(options.state_dir, state_lock); !problem.empty())
        return cannot_start(problem);
    // A hall whose folder cannot take a save could make no table that can be played: the host
    // hears it now, not a player at the first table (a folder that fails later refuses new
    // tables, HallCore::on_create).
    if (const std::string problem = can_write_in(options.state_dir); !problem.empty())
        return cannot_start(problem);

    // The log goes to stderr, which may be a pipe whose reader is gone: a write there must
    // fail, not kill the hall with every table unsaved.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, nullptr);
    // The computer pool's workers start with SIGTERM and SIGINT blocked, so that the handler
    // runs on the loop's thread, never in the middle of a search.
    sigset_t stopping;
    sigset_t previous;
    sigemptyset(&stopping);
    sigaddset(&stopping, SIGTERM);
    sigaddset(&stopping, SIGINT);
    ::pthread_sigmask(SIG_BLOCK, &stopping, &previous);
    Server server(options);
    signalled_server = &server;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGTERM, &action, nullptr);
    ::sigaction(SIGINT, &action, nullptr);
    // Still blocked while the socket opens: a client may connect and a SIGTERM come at once,
    // and it must wait for the stop pipe, not kill the hall by default or wake a pipe not
    // open yet. Unblocked, a signal that came meanwhile stops the loop at its first poll.
    const std::string problem = server.open();
    ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    if (!problem.empty()) {
        signalled_server = nullptr;
        return cannot_start(problem);
    }
    const int status = server.run();
    signalled_server = nullptr;
    return status;
}

} // namespace

const char* hall_usage() {
    return kUsage;
}

int hall_command(const std::vector<std::string>& args) {
    if (args.empty())
        return usage_error("which hall command? (serve, who or bench)");
    if (args.front() == "--help" || args.front() == "-h") {
        std::cout << kUsage;
        return 0;
    }
    if (args.front() == "serve")
        return serve(args);
    if (args.front() == "bench")
        return hall_bench_command(args);
    if (args.front() == "who")
        return hall_who_command(args);
    return usage_error("unknown hall command '" + args.front() + "'");
}

} // namespace termpool::hall
