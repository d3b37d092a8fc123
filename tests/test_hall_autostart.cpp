// `termpool hall` starting the hall when none runs: the reconnect backoff's schedule, the
// socket's lock, and connect_or_start through the real binary. The servers it starts detach
// (a session of their own, their first parent gone); while a test runs, this process is their
// subreaper, so that they are reparented here and can be stopped and reaped by their pid:
// DetachedServers SIGTERMs, then SIGKILLs, and reaps every one of them whatever way the test
// ends. Every wait is bounded (kWait).
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <optional>
#include <poll.h>
#include <string>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "child_process.hpp"
#include "file_helpers.hpp"
#include "files/atomic_file.hpp"
#include "hall/autostart.hpp"
#include "hall/client.hpp"
#include "hall/hall_lock.hpp"
#include "hall/reconnect_backoff.hpp"
#include "hall/socket_trust.hpp"
#include "hall_helpers.hpp"
#include "scoped_env.hpp"
#include "temp_dir.hpp"
#include "tmux_session.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using tmux_session::file_text;

namespace {

namespace fs = std::filesystem;

// Fields of /proc/PID/stat after the name: state, parent, group, session, terminal.
struct ProcStat {
    char state = '?';
    pid_t parent = 0;
    pid_t session = 0;
    int tty = 0;
};
std::optional<ProcStat> proc_stat(pid_t pid) {
    // Read with read(2), not a stream: a process that ends while it is read makes the read fail
    // (ESRCH), which a filebuf throws for, and any process of the machine's may end so.
    std::string text;
    if (const UniqueFd fd(
            ::open(("/proc/" + std::to_string(pid) + "/stat").c_str(), O_RDONLY | O_CLOEXEC));
        fd) {
        char buffer[1024];
        for (ssize_t n; (n = ::read(fd.get(), buffer, sizeof buffer)) > 0;)
            text.append(buffer, static_cast<std::size_t>(n));
    }
    const std::size_t paren = text.rfind(')');
    if (paren == std::string::npos)
        return std::nullopt;
    ProcStat s;
    int group = 0;
    if (std::sscanf(text.c_str() + paren + 1, " %c %d %d %d %d", &s.state, &s.parent, &group,
                    &s.session, &s.tty) != 5)
        return std::nullopt;
    return s;
}

// The processes whose parent is this one and that are in a session of their own: the servers
// connect_or_start detached (ChildProcess children keep the test's session).
std::vector<pid_t> detached_children() {
    std::vector<pid_t> found;
    DIR* proc = ::opendir("/proc");
    if (!proc)
        return found; // (no REQUIRE: DetachedServers calls this from its destructor)
    while (const dirent* entry = ::readdir(proc)) {
        const pid_t pid = static_cast<pid_t>(std::atoi(entry->d_name));
        if (pid <= 0)
            continue;
        if (const auto s = proc_stat(pid);
            s && s->parent == ::getpid() && s->session != ::getsid(0))
            found.push_back(pid);
    }
    ::closedir(proc);
    std::sort(found.begin(), found.end());
    return found;
}

// The exit status (or 128 + signal) of child `pid` once it has exited, waiting at most
// `timeout`; nothing when it still runs.
std::optional<int> reap(pid_t pid, std::chrono::milliseconds timeout) {
    for (const auto end = Clock::now() + timeout;;) {
        int status = 0;
        const pid_t got = ::waitpid(pid, &status, WNOHANG);
        if (got == pid)
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        if (got < 0 && errno != EINTR)
            return std::nullopt;
        if (Clock::now() >= end)
            return std::nullopt;
        std::this_thread::sleep_for(5ms);
    }
}

// While it lives this process is a child subreaper (prctl), so the servers connect_or_start
// detaches become its children when their first parent exits. On its end each one still
// there is sent SIGTERM, SIGKILLed if it has not gone within kWait, and reaped.
class DetachedServers {
public:
    DetachedServers() {
        ::prctl(PR_GET_CHILD_SUBREAPER, &was_);
        REQUIRE(::prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
    }
    ~DetachedServers() {
        for (const pid_t pid : detached_children())
            ::kill(pid, SIGTERM);
        const auto end = Clock::now() + kWait;
        for (std::vector<pid_t> left = detached_children(); !left.empty();
             left = detached_children()) {
            for (const pid_t pid : left) {
                if (Clock::now() >= end)
                    ::kill(pid, SIGKILL);
                reap(pid, 0ms);
            }
            std::this_thread::sleep_for(5ms);
        }
        ::prctl(PR_SET_CHILD_SUBREAPER, was_);
    }
    DetachedServers(const DetachedServers&) = delete;
    DetachedServers& operator=(const DetachedServers&) = delete;

    /// Stops server `pid` with SIGTERM as a host would, and reaps it; its exit status, or
    /// nothing when it did not go within kWait.
    std::optional<int> stop(pid_t pid) {
        ::kill(pid, SIGTERM);
        return reap(pid, kWait);
    }
    /// Waits (at most kWait) for every other detached child (but `except`) to exit by itself;
    /// their statuses.
    std::vector<int> reap_the_rest(pid_t except = 0) {
        const auto others = [except] {
            std::vector<pid_t> left = detached_children();
            std::erase(left, except);
            return left;
        };
        std::vector<int> statuses;
        const auto end = Clock::now() + kWait;
        for (auto left = others(); !left.empty() && Clock::now() < end; left = others())
            for (const pid_t pid : left)
                if (const auto status = reap(pid, 10ms))
                    statuses.push_back(*status);
        return statuses;
    }

private:
    int was_ = 0;
};

std::string binary() {
    return fs::absolute(tmux_session::termpool_binary()).string();
}

std::string link_of(const std::string& path) {
    std::error_code error;
    const fs::path target = fs::read_symlink(path, error);
    return error ? std::string() : target.string();
}

std::size_t count_of(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
        ++n;
    return n;
}

// A socket file at `path` that nobody listens on, as a server killed outright leaves it.
void make_stale_socket(const std::string& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(path.size() < sizeof address.sun_path);
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    const UniqueFd fd(::socket(AF_UNIX, SOCK_STREAM, 0));
    REQUIRE(fd);
    REQUIRE(::bind(fd.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
    REQUIRE(fs::is_socket(path));
}

// connect_or_start's error; the started server's log in `log`, whether it refused the hall
// in `refused`.
std::string reach_hall(HallClient& client, const std::string& socket, const std::string& exe,
                       std::string& log, bool* refused = nullptr) {
    const HallReach reach = connect_or_start(client, socket, exe);
    log = reach.started_log;
    if (refused)
        *refused = reach.refused;
    return reach.error;
}

// A listening socket at `path`, as a planted hall has: it accepts nothing by itself, so that
// the test can see whether anyone connected (accepted_any).
UniqueFd listen_at(const std::string& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(path.size() < sizeof address.sun_path);
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    UniqueFd fd(::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    REQUIRE(fd);
    REQUIRE(::bind(fd.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
    REQUIRE(::listen(fd.get(), 8) == 0);
    return fd;
}

// True when a connection waits on the listening (non-blocking) socket `listener`.
bool accepted_any(const UniqueFd& listener) {
    const UniqueFd connection(::accept4(listener.get(), nullptr, nullptr, SOCK_CLOEXEC));
    return static_cast<bool>(connection);
}

// A stat as lstat gives it, for the judgements: a file of type and mode `mode`, owned by `uid`.
struct stat stat_of(mode_t mode, uid_t uid) {
    struct stat st {};
    st.st_mode = mode;
    st.st_uid = uid;
    return st;
}

// The folders of one test, nothing of the user's: the state (and so hall.log) in `dir`.
struct PrivateEnv {
    explicit PrivateEnv(const std::string& dir)
        : state("XDG_STATE_HOME", dir + "/state"), runtime("XDG_RUNTIME_DIR", dir + "/runtime") {}
    ScopedEnv state;
    ScopedEnv runtime;
};

} // namespace

TEST_CASE("reconnect backoff: 0.25, 0.5, 1, 2, 4, then 5 s; reset starts again",
          "[hall][autostart]") {
    ReconnectBackoff backoff;
    CHECK(backoff.tries() == 0);
    const std::vector<long> expected = {250, 500, 1000, 2000, 4000, 5000, 5000, 5000};
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("try " << i + 1);
        CHECK(backoff.next().count() == expected[i]);
        CHECK(backoff.tries() == static_cast<int>(i + 1));
    }
    for (int i = 0; i < 100; ++i)
        REQUIRE(backoff.next() == 5000ms); // never longer, however long the hall is away
    backoff.reset();
    CHECK(backoff.tries() == 0);
    CHECK(backoff.next() == 250ms);
    CHECK(backoff.next() == 500ms);
}

TEST_CASE("own_executable: the running program's own file", "[hall][autostart]") {
    const std::string self = own_executable();
    CHECK(fs::path(self).is_absolute());
    CHECK(fs::path(self).filename() == "termpool_tests");
    CHECK(fs::equivalent(self, "/proc/self/exe"));
}

TEST_CASE("hall lock: one holder at a time, the file kept private", "[hall][autostart]") {
    TempDir dir("termpool-autostart");
    const std::string socket = dir.path() + "/hall.sock";
    CHECK(hall_lock_path(socket) == socket + ".lock");
    UniqueFd first;
    REQUIRE(lock_hall(socket, first) == "");
    CHECK(first);
    CHECK(mode_of(socket + ".lock") == 0600);
    UniqueFd second;
    CHECK(lock_hall(socket, second) == "a hall is already starting/running at " + socket);
    CHECK_FALSE(second);
    first.reset(); // the holder goes: the next one takes it
    CHECK(lock_hall(socket, second) == "");
    CHECK(second);
    CHECK_THAT(lock_hall(dir.path() + "/missing/hall.sock", first),
               Catch::Contains("cannot open the hall's lock"));
}

TEST_CASE("hall lock: a lock file someone else made is said to be theirs, not another hall's",
          "[hall][autostart]") {
    // Only root can give a file away (as anyone else, the test says why it did not run, as the
    // other tests of another user's files do).
    if (::geteuid() != 0) {
        WARN("not root: a lock file of another user's cannot be made");
        return;
    }
    TempDir dir("termpool-autostart");
    const std::string state = dir.path();
    {
        UniqueFd made;
        REQUIRE(lock_state_dir(state, made) == "");
    }
    REQUIRE(::chown((state + "/hall.lock").c_str(), 65534, 65534) == 0);
    UniqueFd held;
    CHECK(lock_state_dir(state, held) ==
          state + "/hall.lock: the hall's lock is owned by " + describe_uid(65534) +
              ", not by this user (" + describe_uid(0) + "); someone else put it there: remove it");
    CHECK_FALSE(held);
}

TEST_CASE("hall serve: a second server on a locked socket says so and exits 1",
          "[hall][e2e][autostart]") {
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    const std::string socket = dir.path() + "/hall.sock";
    const std::string log = dir.path() + "/serve.log";
    // Another server holds the lock (and may not have made its socket yet).
    UniqueFd held;
    REQUIRE(lock_hall(socket, held) == "");
    {
        ChildProcess server({binary(), "hall", "serve", "--socket", socket, "--idle-exit", "60"},
                            log);
        REQUIRE(server.pid() > 0);
        const auto status = server.wait_exit(kWait);
        INFO(file_text(log));
        CHECK(status == 1);
        CHECK(file_text(log) ==
              "termpool hall: a hall is already starting/running at " + socket + "\n");
        CHECK_FALSE(fs::exists(socket));
    }
    // Once it is free, the server takes it and serves.
    held.reset();
    ChildProcess server({binary(), "hall", "serve", "--socket", socket, "--idle-exit", "60"}, log);
    bool up = false;
    for (const auto end = Clock::now() + kWait; !up && server.running() && Clock::now() < end;) {
        HallClient probe;
        up = probe.connect(socket).empty();
        if (!up)
            std::this_thread::sleep_for(10ms);
    }
    INFO(file_text(log));
    REQUIRE(up);
    CHECK(lock_hall(socket, held) == "a hall is already starting/running at " + socket);
    server.signal(SIGTERM);
    CHECK(server.wait_exit(kWait) == 0);
    CHECK(server.gone());
}

TEST_CASE("connect_or_start: no hall, one is started detached; the next client joins it; a "
          "stale socket is replaced",
          "[hall][e2e][autostart]") {
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    DetachedServers servers;
    const std::string sockets = dir.path() + "/run";
    const std::string socket = sockets + "/hall.sock";
    const std::string expected_log = dir.path() + "/state/termpool/hall/hall.log";
    REQUIRE(started_hall_log_path() == expected_log);

    HallClient ann;
    std::string log = "unset";
    const auto start = Clock::now();
    REQUIRE(reach_hall(ann, socket, binary(), log) == "");
    CHECK(Clock::now() - start < hall_start_wait);
    CHECK(log == expected_log);
    CHECK(mode_of(sockets) == 0700); // made as the server wants it
    const pid_t pid = ann.server_pid();
    REQUIRE(pid > 0);
    CHECK(pid != ::getpid());

    // Detached as tmux's server: its first parent is gone (reaped: no zombie of it stays), it
    // leads no session but is in one of its own, with no terminal; stdin and stdout are
    // /dev/null, stderr the log, and nothing of the client's is open in it.
    const auto stat = proc_stat(pid);
    REQUIRE(stat);
    CHECK(stat->parent == ::getpid()); // reparented to this process, the subreaper
    CHECK(stat->session != ::getsid(0));
    CHECK(stat->session != pid);
    CHECK(stat->tty == 0);
    CHECK(detached_children() == std::vector<pid_t>{pid});
    const std::string fds = "/proc/" + std::to_string(pid) + "/fd/";
    CHECK(link_of(fds + "0") == "/dev/null");
    CHECK(link_of(fds + "1") == "/dev/null");
    CHECK(link_of(fds + "2") == expected_log);
    for (const auto& entry : fs::directory_iterator(fds)) {
        const std::string target = link_of(entry.path().string());
        INFO("fd " << entry.path().filename() << " -> " << target);
        CHECK_FALSE(target.starts_with("/dev/pts"));
        CHECK_FALSE(target.starts_with("/dev/tty"));
        // Of the test's folder, only what the server opens itself.
        const bool ours = target == expected_log || target == socket + ".lock" ||
                          target.starts_with(dir.path() + "/state/");
        CHECK((ours || !target.starts_with(dir.path() + "/")));
    }
    const std::string command = file_text("/proc/" + std::to_string(pid) + "/cmdline");
    std::string expected_command;
    for (const std::string& arg :
         {binary(), std::string("hall"), std::string("serve"), std::string("--socket"), socket,
          std::string("--idle-exit"), std::string("60"), std::string("--log"), expected_log})
        expected_command += arg + '\0';
    CHECK(command == expected_command);
    // A real hall.
    REQUIRE(ann.hello("Ann", "", kWait) == "");

    // The next client finds it running: nothing is started.
    HallClient bob;
    REQUIRE(reach_hall(bob, socket, binary(), log) == "");
    CHECK(log == "");
    CHECK(bob.server_pid() == pid);
    REQUIRE(bob.hello("Bob", "", kWait) == "");
    CHECK(detached_children() == std::vector<pid_t>{pid});

    // Stopped as a host stops it.
    CHECK(servers.stop(pid) == 0);
    CHECK_FALSE(fs::exists(socket));
    INFO(file_text(expected_log));

    // A server killed outright leaves its socket file: nobody answers there, so a new one is
    // started in its place.
    HallClient cy;
    REQUIRE(reach_hall(cy, socket, binary(), log) == "");
    const pid_t killed = cy.server_pid();
    REQUIRE(killed > 0);
    ::kill(killed, SIGKILL);
    CHECK(reap(killed, kWait) == 128 + SIGKILL);
    REQUIRE(fs::is_socket(socket));
    HallClient dee;
    REQUIRE(reach_hall(dee, socket, binary(), log) == "");
    CHECK(log == expected_log);
    const pid_t fresh = dee.server_pid();
    CHECK(fresh > 0);
    CHECK(fresh != killed);
    CHECK(servers.stop(fresh) == 0);
    CHECK(servers.reap_the_rest().empty());
    CHECK(detached_children().empty());
}

TEST_CASE("connect_or_start: two clients starting at once end on one server",
          "[hall][e2e][autostart]") {
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    DetachedServers servers;
    const std::string socket = dir.path() + "/run/hall.sock";
    int losers = 0;
    constexpr int rounds = 4;
    for (int round = 0; round < rounds; ++round) {
        // No socket file, or a dead server's: then both servers find it stale, and without the
        // lock the second would unlink the first one's new socket and bind its own.
        const bool stale = round % 2 == 1;
        INFO("round " << round << (stale ? ", a stale socket" : ", no socket"));
        if (stale)
            make_stale_socket(socket);
        HallClient clients[2];
        std::string errors[2], logs[2];
        std::atomic<int> ready{0};
        std::vector<std::thread> threads;
        for (int c = 0; c < 2; ++c)
            threads.emplace_back([&, c] {
                // Both wait for each other, then go at the same moment (bounded spin).
                ++ready;
                for (const auto end = Clock::now() + kWait; ready < 2 && Clock::now() < end;)
                    std::this_thread::yield();
                errors[c] = reach_hall(clients[c], socket, binary(), logs[c]);
            });
        for (std::thread& t : threads)
            t.join();
        CHECK(errors[0] == "");
        CHECK(errors[1] == "");
        const pid_t pid = clients[0].server_pid();
        REQUIRE(pid > 0);
        CHECK(clients[1].server_pid() == pid);
        CHECK((!logs[0].empty() || !logs[1].empty()));
        REQUIRE(clients[0].hello("Ann", "", kWait) == "");
        REQUIRE(clients[1].hello("Bob", "", kWait) == "");
        // A server that lost the race for the lock says so and exits 1. Every other one started
        // is waited for while the winner still holds the lock: one still starting (slow, under
        // a sanitizer) when the winner went would take the lock then, and serve the next round.
        for (const int status : servers.reap_the_rest(pid)) {
            CHECK(status == 1);
            ++losers;
        }
        CHECK(detached_children() == std::vector<pid_t>{pid});
        CHECK(servers.stop(pid) == 0);
        CHECK(servers.reap_the_rest().empty());
    }
    const std::string log = file_text(started_hall_log_path());
    INFO(log);
    CHECK(count_of(log, "a hall is already starting/running at " + socket) ==
          static_cast<std::size_t>(losers));
    WARN(losers << " of " << rounds << " rounds started two servers");
    CHECK(detached_children().empty());
}

TEST_CASE("connect_or_start: what cannot start says why, soon, and leaves nothing running",
          "[hall][e2e][autostart]") {
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    DetachedServers servers;
    const std::string socket = dir.path() + "/run/hall.sock";
    std::string log;

    SECTION("a program that is not there") {
        HallClient client;
        const auto start = Clock::now();
        CHECK_THAT(reach_hall(client, socket, dir.path() + "/no-such-termpool", log),
                   Catch::StartsWith("cannot run " + dir.path() + "/no-such-termpool: ") &&
                       Catch::Contains(std::strerror(ENOENT)));
        CHECK(Clock::now() - start < 2s);
        CHECK(client.closed());
        CHECK(servers.reap_the_rest() == std::vector<int>{127});
    }
    SECTION("a program that exits at once: three tries, then its log's last line") {
        HallClient client;
        const auto start = Clock::now();
        // sh takes "hall" for a script to run, finds none and says so on stderr (the log).
        const std::string error = reach_hall(client, socket, "/bin/sh", log);
        CHECK(Clock::now() - start < hall_start_wait);
        CHECK_THAT(error, Catch::StartsWith(socket +
                                            ": the hall started in the background does "
                                            "not answer (" +
                                            started_hall_log_path() + ": ") &&
                              Catch::Contains("hall"));
        CHECK(log == started_hall_log_path());
        const std::vector<int> statuses = servers.reap_the_rest();
        CHECK(statuses.size() == 3);
        for (const int status : statuses)
            CHECK(status != 0);
    }
    SECTION("a socket folder others may write to is refused before anything starts") {
        const std::string open = dir.path() + "/open";
        REQUIRE(::mkdir(open.c_str(), 0700) == 0);
        REQUIRE(::chmod(open.c_str(), 0777) == 0);
        HallClient client;
        CHECK_THAT(reach_hall(client, open + "/hall.sock", binary(), log),
                   Catch::Contains(open + ": the socket folder is writable by"));
        CHECK(log == "");
    }
    SECTION("a file at the socket's path that is not a socket is not a dead hall") {
        REQUIRE(::mkdir((dir.path() + "/run").c_str(), 0700) == 0);
        std::ofstream(socket) << "not a socket\n";
        HallClient client;
        CHECK_THAT(reach_hall(client, socket, binary(), log), Catch::StartsWith(socket + ": "));
        CHECK(log == "");
        CHECK(file_text(socket) == "not a socket\n");
    }
    CHECK(detached_children().empty());
}

TEST_CASE("socket trust: the folder, the socket file and the server must be this user's alone",
          "[hall][autostart][trust]") {
    const uid_t me = 1001;
    const uid_t other = 1002;
    const std::string folder = "/tmp/termpool-1001";
    const std::string socket = folder + "/hall.sock";
    CHECK(describe_uid(0) == "uid 0 (root)");
    CHECK(describe_uid(3999999999U) == "uid 3999999999"); // nobody's: no name

    SECTION("the folder") {
        CHECK(judge_socket_folder(folder, stat_of(S_IFDIR | 0700, me), me) == "");
        // Another user's folder, though private: whoever owns it can plant a socket in it.
        CHECK(judge_socket_folder(folder, stat_of(S_IFDIR | 0700, other), me) ==
              folder + ": the socket folder is owned by " + describe_uid(other) +
                  ", not by this user (" + describe_uid(me) + ")");
        CHECK_THAT(judge_socket_folder(folder, stat_of(S_IFDIR | 0755, other), me),
                   Catch::Contains("owned by uid 1002"));
        // Any permission for the group or others, read only too: they could reach the hall.
        for (const mode_t mode : {mode_t{0755}, mode_t{0750}, mode_t{0701}, mode_t{0710},
                                  mode_t{0770}, mode_t{0777}, mode_t{01777}}) {
            INFO("mode " << std::oct << mode);
            const std::string problem =
                judge_socket_folder(folder, stat_of(S_IFDIR | mode, me), me);
            CHECK_THAT(problem, Catch::StartsWith(folder + ": the socket folder is ") &&
                                    Catch::Contains("owned by " + describe_uid(me)) &&
                                    Catch::Contains("make it private with chmod 700"));
        }
        CHECK_THAT(judge_socket_folder(folder, stat_of(S_IFDIR | 0755, me), me),
                   Catch::Contains("open to others (mode 0755, owned by uid 1001"));
        CHECK_THAT(judge_socket_folder(folder, stat_of(S_IFDIR | 0750, me), me),
                   Catch::Contains("open to its group (mode 0750"));
        CHECK_THAT(judge_socket_folder(folder, stat_of(S_IFDIR | 0777, me), me),
                   Catch::Contains("writable by others (mode 0777"));
        CHECK(judge_socket_folder(folder, stat_of(S_IFLNK | 0777, other), me) ==
              folder + ": the socket folder is a symbolic link (owned by " + describe_uid(other) +
                  "), not a directory");
        CHECK(judge_socket_folder(folder, stat_of(S_IFREG | 0600, me), me) ==
              folder + ": the socket folder is not a directory (owned by " + describe_uid(me) +
                  ")");
    }
    SECTION("the state folder: others may read it, not write to it") {
        CHECK(judge_state_folder(folder, stat_of(S_IFDIR | 0700, me), me) == "");
        CHECK(judge_state_folder(folder, stat_of(S_IFDIR | 0755, me), me) == "");
        CHECK(judge_state_folder(folder, stat_of(S_IFDIR | 0750, me), me) == "");
        CHECK(judge_state_folder(folder, stat_of(S_IFDIR | 0700, other), me) ==
              folder + ": the state folder is owned by " + describe_uid(other) +
                  ", not by this user (" + describe_uid(me) + ")");
        for (const mode_t mode :
             {mode_t{0770}, mode_t{0720}, mode_t{0702}, mode_t{0777}, mode_t{01777}}) {
            INFO("mode " << std::oct << mode);
            CHECK_THAT(judge_state_folder(folder, stat_of(S_IFDIR | mode, me), me),
                       Catch::StartsWith(folder + ": the state folder is writable by ") &&
                           Catch::EndsWith("let no one else write to it: chmod go-w"));
        }
        CHECK_THAT(judge_state_folder(folder, stat_of(S_IFDIR | 0777, me), me),
                   Catch::Contains("writable by others (mode 0777, owned by uid 1001"));
        CHECK(judge_state_folder(folder, stat_of(S_IFREG | 0600, me), me) ==
              folder + ": the state folder is not a directory (owned by " + describe_uid(me) + ")");
    }
    SECTION("the folders above the state folder") {
        const std::string above = "/srv/shared";
        CHECK(judge_folder_above(above, stat_of(S_IFDIR | 0755, me), me) == "");
        CHECK(judge_folder_above(above, stat_of(S_IFDIR | 0755, 0), me) == "");
        CHECK(judge_folder_above(above, stat_of(S_IFDIR | 01777, 0), me) == ""); // as /tmp
        CHECK(judge_folder_above(above, stat_of(S_IFDIR | 0755, other), me) ==
              above + ": a folder above the state folder is owned by " + describe_uid(other) +
                  ", who could put another in its place; keep the state in a folder of your own");
        CHECK(judge_folder_above(above, stat_of(S_IFDIR | 0777, 0), me) ==
              above +
                  ": a folder above the state folder is writable by others (mode 0777), so that "
                  "the state folder could be swapped under the hall; keep the state in a folder "
                  "of your own");
        CHECK_THAT(judge_folder_above(above, stat_of(S_IFDIR | 0775, me), me),
                   Catch::Contains("writable by its group (mode 0775)"));
        // The user's own private group writing is the user writing (umask 002 on Debian and
        // Ubuntu makes ~/.local 0775); others writing is not.
        CHECK(judge_folder_above(above, stat_of(S_IFDIR | 0775, me), me, true) == "");
        CHECK(judge_state_folder(folder, stat_of(S_IFDIR | 0775, me), me, true) == "");
        CHECK_THAT(judge_folder_above(above, stat_of(S_IFDIR | 0777, me), me, true),
                   Catch::Contains("writable by others"));
        CHECK_THAT(judge_state_folder(folder, stat_of(S_IFDIR | 0757, me), me, true),
                   Catch::Contains("writable by others"));
        // A group with another member, or not the user's primary group, is not private.
        CHECK_FALSE(is_private_group(0, 3999999999U)); // no such user
    }
    SECTION("a table file") {
        const std::string table = folder + "/table-7.save";
        CHECK(judge_table_file(table, stat_of(S_IFREG | 0600, me), me) == "");
        CHECK(judge_table_file(table, stat_of(S_IFREG | 0666, other), me) ==
              table + ": the table file is owned by " + describe_uid(other) +
                  ", not by this user (" + describe_uid(me) + "); someone else put it there");
    }
    SECTION("the socket file") {
        CHECK(judge_socket_file(socket, stat_of(S_IFSOCK | 0777, me), me) == "");
        CHECK(judge_socket_file(socket, stat_of(S_IFSOCK | 0777, other), me) ==
              socket + ": the hall's socket is owned by " + describe_uid(other) +
                  ", not by this user (" + describe_uid(me) + ")");
        CHECK(judge_socket_file(socket, stat_of(S_IFREG | 0600, me), me) ==
              socket + ": not a socket (owned by " + describe_uid(me) + ")");
    }
    SECTION("the server at the other end") {
        CHECK(judge_peer(socket, me, me) == "");
        CHECK(judge_peer(socket, other, me) == socket + ": the hall there runs as " +
                                                   describe_uid(other) + ", not as this user (" +
                                                   describe_uid(me) + "); nothing was sent to it");
        CHECK_THAT(judge_peer(socket, 0, me), Catch::Contains("runs as uid 0 (root)"));
        // SO_PEERCRED on a real pair: both ends are this process, so this user.
        int ends[2];
        REQUIRE(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) == 0);
        const UniqueFd a(ends[0]), b(ends[1]);
        CHECK(check_peer(a.get(), socket) == "");
        CHECK_THAT(check_peer(-1, socket),
                   Catch::StartsWith(socket + ": cannot tell who runs the hall there: "));
    }
}

TEST_CASE("connect_or_start: a hall whose folder or socket is not this user's alone is refused "
          "before connecting",
          "[hall][e2e][autostart][trust]") {
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    DetachedServers servers;
    std::string log = "unset";
    bool refused = false;
    HallClient client;

    SECTION("a folder others may read (0755), with someone listening in it") {
        const std::string open = dir.path() + "/open";
        REQUIRE(::mkdir(open.c_str(), 0700) == 0);
        REQUIRE(::chmod(open.c_str(), 0755) == 0);
        const UniqueFd listener = listen_at(open + "/hall.sock");
        CHECK(reach_hall(client, open + "/hall.sock", binary(), log, &refused) ==
              open + ": the socket folder is open to others (mode 0755, owned by " +
                  describe_uid(::geteuid()) + "); make it private with chmod 700");
        CHECK(refused);
        CHECK_FALSE(accepted_any(listener)); // not even connected to
    }
    SECTION("a symbolic link to a good folder, with someone listening in it") {
        const std::string real = dir.path() + "/real";
        REQUIRE(::mkdir(real.c_str(), 0700) == 0);
        const UniqueFd listener = listen_at(real + "/hall.sock");
        REQUIRE(::symlink(real.c_str(), (dir.path() + "/link").c_str()) == 0);
        CHECK_THAT(reach_hall(client, dir.path() + "/link/hall.sock", binary(), log, &refused),
                   Catch::StartsWith(dir.path() + "/link: the socket folder is a symbolic link"));
        CHECK(refused);
        CHECK_FALSE(accepted_any(listener));
    }
    SECTION("a state folder others may write to: no hall is started on it") {
        const std::string state = dir.path() + "/state/termpool/hall"; // default_state_dir()
        REQUIRE(make_directories(state) == "");
        REQUIRE(::chmod(state.c_str(), 0777) == 0);
        CHECK(reach_hall(client, dir.path() + "/run/hall.sock", binary(), log, &refused) ==
              state + ": the state folder is writable by others (mode 0777, owned by " +
                  describe_uid(::geteuid()) + "); let no one else write to it: chmod go-w");
        CHECK(refused);
    }
    SECTION("a link in the place of the started hall's log: not followed, nothing started") {
        const std::string state = dir.path() + "/state/termpool/hall"; // default_state_dir()
        REQUIRE(make_directories(state) == "");
        const std::string victim = dir.path() + "/victim";
        REQUIRE(::symlink(victim.c_str(), (state + "/hall.log").c_str()) == 0);
        CHECK_THAT(reach_hall(client, dir.path() + "/run/hall.sock", binary(), log, &refused),
                   Catch::StartsWith(state + "/hall.log: cannot open the log: ") &&
                       Catch::Contains(std::strerror(ELOOP)));
        CHECK(::access(victim.c_str(), F_OK) != 0);
    }
    SECTION("a folder or a socket owned by another user (as root: given to uid 65534)") {
        if (::geteuid() != 0) {
            WARN("not root: another user's folder is judged by judge_socket_folder only");
            return;
        }
        // The attack as found: another user made /tmp/termpool-UID, and listens there.
        const std::string theirs = dir.path() + "/theirs";
        REQUIRE(::mkdir(theirs.c_str(), 0700) == 0);
        const UniqueFd listener = listen_at(theirs + "/hall.sock");
        REQUIRE(::chown(theirs.c_str(), 65534, 65534) == 0);
        CHECK(reach_hall(client, theirs + "/hall.sock", binary(), log, &refused) ==
              theirs + ": the socket folder is owned by " + describe_uid(65534) +
                  ", not by this user (" + describe_uid(::geteuid()) + ")");
        CHECK(refused);
        CHECK_FALSE(accepted_any(listener));
        // Our folder, their socket file.
        const std::string ours = dir.path() + "/ours";
        REQUIRE(::mkdir(ours.c_str(), 0700) == 0);
        const UniqueFd second = listen_at(ours + "/hall.sock");
        REQUIRE(::lchown((ours + "/hall.sock").c_str(), 65534, 65534) == 0);
        refused = false;
        CHECK(reach_hall(client, ours + "/hall.sock", binary(), log, &refused) ==
              ours + "/hall.sock: the hall's socket is owned by " + describe_uid(65534) +
                  ", not by this user (" + describe_uid(::geteuid()) + ")");
        CHECK(refused);
        CHECK_FALSE(accepted_any(second));
    }
    CHECK(client.closed());
    CHECK(log == ""); // nothing was started
    CHECK(detached_children().empty());
}

TEST_CASE("connect_or_start: a hall that runs as another user is refused before hello",
          "[hall][e2e][autostart][trust]") {
    if (::geteuid() != 0) {
        WARN("not root: a server of another uid is judged by judge_peer only");
        return;
    }
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    DetachedServers servers;
    // Our folder and our socket file, as a server of ours would leave them; but the process
    // that listens there runs as uid 65534 (it bound the socket as root, then changed its uid
    // and listened: SO_PEERCRED gives the uid at listen).
    const std::string folder = dir.path() + "/run";
    REQUIRE(::mkdir(folder.c_str(), 0700) == 0);
    const std::string socket = folder + "/hall.sock";
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(socket.size() < sizeof address.sun_path);
    std::memcpy(address.sun_path, socket.c_str(), socket.size() + 1);
    int ends[2];
    REQUIRE(::pipe2(ends, O_CLOEXEC) == 0);
    UniqueFd report(ends[0]);
    UniqueFd report_end(ends[1]);
    const pid_t planted = ::fork();
    REQUIRE(planted >= 0);
    if (planted == 0) {
        // The planted hall: only system calls until _exit. It reports 'r' once listening, then
        // the number of bytes the client sent before it closed (or -1 when none came in 5 s).
        const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
        if (fd < 0 || ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) ||
            ::setresgid(65534, 65534, 65534) || ::setresuid(65534, 65534, 65534) || ::listen(fd, 8))
            ::_exit(1);
        [[maybe_unused]] auto ignored = ::write(report_end.get(), "r", 1);
        pollfd p{fd, POLLIN, 0};
        int heard = -1;
        if (::poll(&p, 1, 5000) == 1) {
            const int connection = ::accept(fd, nullptr, nullptr);
            char buffer[512];
            heard = 0;
            for (ssize_t n; (n = ::read(connection, buffer, sizeof buffer)) > 0;)
                heard += static_cast<int>(n);
        }
        ignored = ::write(report_end.get(), &heard, sizeof heard);
        ::_exit(0);
    }
    report_end.reset();
    pollfd p{report.get(), POLLIN, 0};
    char ready = 0;
    REQUIRE(::poll(&p, 1, static_cast<int>(kWait.count())) == 1);
    REQUIRE(::read(report.get(), &ready, 1) == 1);
    REQUIRE(ready == 'r');

    HallClient client;
    std::string log = "unset";
    bool refused = false;
    CHECK(reach_hall(client, socket, binary(), log, &refused) ==
          socket + ": the hall there runs as " + describe_uid(65534) + ", not as this user (" +
              describe_uid(::geteuid()) + "); nothing was sent to it");
    CHECK(refused);
    CHECK(client.closed());
    CHECK(log == "");
    // It was connected to, and closed at once: not a byte of hello or token went to it.
    int heard = -2;
    REQUIRE(::poll(&p, 1, static_cast<int>(kWait.count())) == 1);
    REQUIRE(::read(report.get(), &heard, sizeof heard) == static_cast<ssize_t>(sizeof heard));
    CHECK(heard == 0);
    CHECK(reap(planted, kWait) == 0);
    CHECK(detached_children().empty());
}

TEST_CASE("termpool hall refuses a socket folder that is not the user's alone, exit status 1",
          "[hall][e2e][autostart][trust]") {
    TempDir dir("termpool-autostart");
    PrivateEnv env(dir.path());
    const std::string open = dir.path() + "/open";
    REQUIRE(::mkdir(open.c_str(), 0700) == 0);
    REQUIRE(::chmod(open.c_str(), 0777) == 0);
    const UniqueFd listener = listen_at(open + "/hall.sock");
    const std::string out = dir.path() + "/out.log";
    ChildProcess client({binary(), "hall", "--name", "Ann", "--socket", open + "/hall.sock"}, out);
    CHECK(client.wait_exit(kWait) == 1);
    CHECK(file_text(out) == "termpool hall: " + open +
                                ": the socket folder is writable by others (mode 0777, owned by " +
                                describe_uid(::geteuid()) + "); make it private with chmod 700\n");
    CHECK_FALSE(accepted_any(listener));
}
