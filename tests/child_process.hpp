#pragma once
// A child process of the tests (the binary under test, run as a player or a host would),
// started with fork and exec in a process group of its own, its output in a file. The value
// SIGKILLs the group and reaps the child whatever way a test ends, so that no test leaves a
// process behind; should the test binary itself die, the kernel kills the child
// (PR_SET_PDEATHSIG).

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace termpool::test {

/// A running child process, killed and reaped with the value.
class ChildProcess {
public:
    /// Runs `args` (args[0] is the program's path), stdin from /dev/null, stdout and stderr
    /// appended to the file `output`; `env` entries (NAME=VALUE) replace or add to the
    /// environment.
    ChildProcess(const std::vector<std::string>& args, const std::string& output,
                 const std::vector<std::string>& env = {}) {
        std::vector<std::string> environment = env;
        for (char** e = environ; *e; ++e) {
            const std::string entry = *e;
            const std::string name = entry.substr(0, entry.find('=') + 1);
            bool replaced = false;
            for (const std::string& mine : env)
                replaced = replaced || mine.starts_with(name);
            if (!replaced)
                environment.push_back(entry);
        }
        // Everything the child needs is built before fork: after it, only async-signal-safe
        // calls.
        std::vector<char*> argv;
        for (const std::string& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        std::vector<char*> envp;
        for (const std::string& e : environment)
            envp.push_back(const_cast<char*>(e.c_str()));
        envp.push_back(nullptr);
        const pid_t parent = ::getpid();
        pid_ = ::fork();
        if (pid_ == 0) {
            ::setpgid(0, 0);
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            if (::getppid() != parent)
                ::_exit(127);
            const int in = ::open("/dev/null", O_RDONLY);
            const int out = ::open(output.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0600);
            if (in < 0 || out < 0)
                ::_exit(127);
            ::dup2(in, STDIN_FILENO);
            ::dup2(out, STDOUT_FILENO);
            ::dup2(out, STDERR_FILENO);
            // The test's own sockets stay the test's: a server holding a copy of a client's
            // connection would never see it close.
            ::close_range(3, ~0U, 0);
            ::execve(argv[0], argv.data(), envp.data());
            ::_exit(127);
        }
        if (pid_ > 0)
            ::setpgid(pid_, pid_); // either side may set it first; one of them does
    }
    ~ChildProcess() { kill(); }
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    /// Its process id (-1 when fork failed).
    pid_t pid() const { return pid_; }
    /// True while it has not exited.
    bool running() { return pid_ > 0 && !status_ && !exited(); }
    /// Sends `sig` to it (not to its group).
    void signal(int sig) const {
        if (pid_ > 0 && !status_)
            ::kill(pid_, sig);
    }
    /// Waits at most `timeout` for it to exit; its status (the exit status, or 128 + the
    /// signal that ended it), or nothing when it still runs.
    std::optional<int> wait_exit(std::chrono::milliseconds timeout) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (pid_ > 0 && !status_) {
            if (exited())
                reap();
            else if (std::chrono::steady_clock::now() >= end)
                break;
            else
                std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return status_;
    }
    /// SIGKILLs its process group and reaps it; its status.
    std::optional<int> kill() {
        if (pid_ > 0 && !status_) {
            ::kill(-pid_, SIGKILL);
            ::kill(pid_, SIGKILL); // in case it had not joined its group yet
            reap();
        }
        return status_;
    }
    /// True once it was reaped and no process has its id any more.
    bool gone() const { return pid_ > 0 && status_ && ::kill(pid_, 0) != 0 && errno == ESRCH; }

private:
    // Exited but not reaped: the zombie keeps the group's id, so that killing the group (its
    // own children, if any) cannot reach anyone else.
    bool exited() {
        siginfo_t info{};
        return ::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
               info.si_pid == pid_;
    }
    void reap() {
        ::kill(-pid_, SIGKILL); // whatever it started goes with it
        int status = 0;
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

    pid_t pid_ = -1;
    std::optional<int> status_;
};

} // namespace termpool::test
