#include "hall/autostart.hpp"

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "files/atomic_file.hpp"
#include "files/file_limits.hpp"
#include "files/read_file.hpp"
#include "hall/hall_state.hpp"
#include "hall/socket_dir.hpp"
#include "hall/socket_trust.hpp"
#include "hall/unique_fd.hpp"

namespace termpool::hall {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

// What the children tell the parent through the report pipe, one write each (shorter than
// PIPE_BUF, so never torn): the server's process id from the first child, or why not.
struct Report {
    char kind;
    int value;
};
constexpr char server_started = 'p'; // value: the server's pid
constexpr char fork_failed = 'f';    // value: errno
constexpr char exec_failed = 'e';    // value: errno

// Starts again at most this often when a started server went without anyone answering.
constexpr int max_starts = 3;
// How long a started server may be gone, nobody answering, before it is started again: the
// server that beat it to the lock binds within milliseconds of taking it.
constexpr auto gone_grace = 250ms;
constexpr auto poll_interval = 20ms;

// `fd` moved above 2 (close-on-exec), so that putting /dev/null and the log on 0, 1 and 2
// cannot overwrite it, even when the caller runs with a standard descriptor closed.
UniqueFd above_stdio(int fd) {
    if (fd < 0 || fd > 2)
        return UniqueFd(fd);
    const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
    ::close(fd);
    return UniqueFd(moved);
}

void report(int fd, char kind, int value) {
    const Report r{kind, value};
    [[maybe_unused]] const auto ignored = ::write(fd, &r, sizeof r);
}

// The server's side of the second fork: only async-signal-safe calls until exec.
[[noreturn]] void become_server(char* const* argv, int null_fd, int log_fd, int report_fd) {
    // Signals as a shell gives them: nothing blocked, nothing ignored (the client's own
    // settings must not reach the server; a handler is reset by exec anyway).
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    for (int sig = 1; sig < NSIG; ++sig)
        ::sigaction(sig, &fallback, nullptr); // SIGKILL, SIGSTOP and glibc's own refuse: fine
    ::dup2(null_fd, STDIN_FILENO);
    ::dup2(null_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    for (int fd = 0; fd <= 2; ++fd)
        ::fcntl(fd, F_SETFD, 0);
    // Nothing else of the client's: not its connections, not its terminal. The report pipe
    // stays until exec closes it (close-on-exec), which tells the parent exec worked.
    if (report_fd > 3)
        ::close_range(3, static_cast<unsigned>(report_fd - 1), 0);
    ::close_range(static_cast<unsigned>(report_fd + 1), ~0U, 0);
    ::execv(argv[0], argv);
    report(report_fd, exec_failed, errno);
    ::_exit(127);
}

// The first child: a session of its own, then the server forked off it, then gone, so that
// the server is no session leader (it can never get a controlling terminal) and its parent
// becomes init, which reaps it.
[[noreturn]] void first_child(char* const* argv, int null_fd, int log_fd, int report_fd) {
    ::setsid();
    const pid_t server = ::fork();
    if (server == 0)
        become_server(argv, null_fd, log_fd, report_fd);
    if (server < 0)
        report(report_fd, fork_failed, errno);
    else
        report(report_fd, server_started, static_cast<int>(server));
    ::_exit(server < 0 ? 1 : 0);
}

// True when nothing answers at `path`: no file there, or a socket file nobody listens on.
bool nobody_answers(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0)
        return errno == ENOENT;
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (!S_ISSOCK(st.st_mode) || path.size() >= sizeof address.sun_path)
        return false;
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    const UniqueFd probe(::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0));
    if (!probe)
        return false;
    if (::connect(probe.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0)
        return false;
    return errno == ECONNREFUSED;
}

// True once process `pid` has exited: no such process, or one that is only waiting to be
// reaped (a zombie, under an init that is slow to reap or a subreaper).
bool process_gone(pid_t pid) {
    if (::kill(pid, 0) != 0)
        return errno == ESRCH;
    const std::string path = "/proc/" + std::to_string(pid) + "/stat";
    std::string error;
    const auto stat = read_whole_file(path, error, max_proc_file_bytes);
    if (!stat)
        return error.empty();                   // vanished between the two looks
    const std::size_t paren = stat->rfind(')'); // the name in parentheses may hold anything
    return paren != std::string::npos && paren + 2 < stat->size() &&
           ((*stat)[paren + 2] == 'Z' || (*stat)[paren + 2] == 'X');
}

// Connects `client` to the hall at `path` only when its folder and socket file are this
// user's, and then keeps the connection only when the server runs as this user, so that a
// hall another user planted is never sent a name or a token. `refused` is set when one of
// those checks said no (the client is left closed).
std::string connect_trusted(HallClient& client, const std::string& path, bool& refused) {
    if (std::string problem = check_socket_path(path); !problem.empty()) {
        refused = true;
        return problem;
    }
    if (std::string error = client.connect(path); !error.empty())
        return error;
    if (std::string problem = check_peer(client.fd(), path); !problem.empty()) {
        client.disconnect();
        refused = true;
        return problem;
    }
    return {};
}

// The last line of the log (it grows with every start; only its end is read).
std::string last_log_line(const std::string& path) {
    const UniqueFd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (!fd)
        return {};
    const off_t size = ::lseek(fd.get(), 0, SEEK_END);
    const off_t from = size > 4096 ? size - 4096 : 0;
    char buffer[4096];
    const ssize_t n = size > 0 ? ::pread(fd.get(), buffer, sizeof buffer, from) : 0;
    std::string text(buffer, static_cast<std::size_t>(n > 0 ? n : 0));
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    const std::size_t start = text.rfind('\n');
    return start == std::string::npos ? text : text.substr(start + 1);
}

} // namespace

std::string own_executable() {
    char path[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0)
        return {};
    const std::string self(path, static_cast<std::size_t>(n));
    // Rebuilt or upgraded while this one runs: the file at that path is another program (or
    // none), but /proc/self/exe still opens this one, in a forked child too.
    return self.ends_with(" (deleted)") ? "/proc/self/exe" : self;
}

std::string started_hall_log_path(const std::string& state) {
    return state + "/hall.log";
}

pid_t start_detached(const std::vector<std::string>& args, const std::string& log_path,
                     std::string& error) {
    error.clear();
    if (args.empty()) {
        error = "nothing to start";
        return 0;
    }
    const UniqueFd null_fd = above_stdio(::open("/dev/null", O_RDWR | O_CLOEXEC | O_NOCTTY));
    if (!null_fd) {
        error = std::string("/dev/null: ") + std::strerror(errno);
        return 0;
    }
    const UniqueFd log = above_stdio(
        // O_NOFOLLOW: the server's --log refuses a link, and so does the log it is started
        // with (a link left in the state folder would have its lines appended elsewhere).
        ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOCTTY | O_NOFOLLOW,
               0600));
    if (!log) {
        error = log_path + ": cannot open the log: " + std::strerror(errno);
        return 0;
    }
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0) {
        error = std::string("pipe: ") + std::strerror(errno);
        return 0;
    }
    const UniqueFd read_end = above_stdio(ends[0]);
    UniqueFd write_end = above_stdio(ends[1]);
    if (!read_end || !write_end) {
        error = std::string("pipe: ") + std::strerror(errno);
        return 0;
    }
    // Built before fork: after it, the children make only async-signal-safe calls.
    std::vector<char*> argv;
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    const pid_t first = ::fork();
    if (first < 0) {
        error = std::string("fork: ") + std::strerror(errno);
        return 0;
    }
    if (first == 0)
        first_child(argv.data(), null_fd.get(), log.get(), write_end.get());
    write_end.reset();
    int status = 0;
    while (::waitpid(first, &status, 0) < 0 && errno == EINTR) {
    }

    // The reports come until every copy of the write end is closed: the first child's when it
    // exits, the server's when exec succeeds (or after it said exec failed).
    pid_t server = 0;
    const auto until = Clock::now() + hall_start_wait;
    for (int reads = 0; reads < 8;) {
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - Clock::now());
        pollfd p{read_end.get(), POLLIN, 0};
        const int ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0)
            break; // no word in time: the server, if any, is taken as started
        Report r{};
        const ssize_t n = ::read(read_end.get(), &r, sizeof r);
        if (n < 0 && errno == EINTR)
            continue;
        ++reads;
        if (n != static_cast<ssize_t>(sizeof r))
            break; // the end: everyone closed the pipe
        if (r.kind == server_started) {
            server = static_cast<pid_t>(r.value);
        } else {
            error = (r.kind == exec_failed ? "cannot run " + args[0] : std::string("fork")) + ": " +
                    std::strerror(r.value);
            return 0;
        }
    }
    if (!server && error.empty())
        error = "the server's process did not start";
    return server;
}

HallReach connect_or_start(HallClient& client, const std::string& socket_path,
                           const std::string& self_exe) {
    HallReach reach;
    std::string& error = reach.error;
    error = connect_trusted(client, socket_path, reach.refused);
    if (error.empty() || reach.refused)
        return reach;
    // Somebody answers now though the connection was refused: a hall another client started
    // came up between the two (or the path is no socket: then the same error again).
    if (!nobody_answers(socket_path)) {
        error = connect_trusted(client, socket_path, reach.refused);
        return reach;
    }
    // The folder the server would refuse is refused here, before anything is started.
    if (std::string problem = prepare_socket_dir(socket_path); !problem.empty()) {
        error = problem;
        return reach;
    }
    if (std::string problem = make_directories(default_state_dir()); !problem.empty()) {
        error = problem;
        return reach;
    }
    // So is a state folder others may write to: a server started on it would only refuse it,
    // again at every retry, and the player would wait for nothing.
    std::string state = default_state_dir();
    if (std::string problem = check_state_folder(state); !problem.empty()) {
        error = problem;
        reach.refused = true;
        return reach;
    }
    // In the folder as it really is (its links resolved above), as the server will use it.
    const std::string log = started_hall_log_path(state);
    const std::vector<std::string> args = {self_exe,      "hall", "serve", "--socket", socket_path,
                                           "--idle-exit", "60",   "--log", log};
    const auto until = Clock::now() + hall_start_wait;
    pid_t server = 0;
    int starts = 0;
    constexpr Clock::time_point not_gone = Clock::time_point::max();
    Clock::time_point gone_since = not_gone;
    for (int round = 0; round < 1000; ++round) {
        if (!server) {
            std::string why;
            server = start_detached(args, log, why);
            if (!server) {
                error = why;
                return reach;
            }
            reach.started_log = log;
            ++starts;
            gone_since = not_gone;
        }
        std::this_thread::sleep_for(poll_interval);
        error = connect_trusted(client, socket_path, reach.refused);
        if (error.empty() || reach.refused)
            return reach;
        const auto now = Clock::now();
        if (now >= until)
            break;
        // Gone without anyone answering: it lost the lock to a hall that was going away (or
        // failed for good: then the log says why once the starts are spent).
        if (!process_gone(server))
            continue;
        if (gone_since == not_gone)
            gone_since = now;
        if (now - gone_since < gone_grace || !nobody_answers(socket_path))
            continue;
        if (starts >= max_starts)
            break;
        server = 0;
    }
    const std::string last = last_log_line(log);
    error = socket_path + ": the hall started in the background does not answer (" + log +
            (last.empty() ? std::string() : ": " + last) + ")";
    return reach;
}

} // namespace termpool::hall
