#pragma once
// Driving the real binary in tmux, as a player would: a tmux server of its own, keys, the
// screen, the shell's record of the exit status, and a scratch directory for saves. Every tmux
// test goes through `Tmux`: it starts the program, sends keys, waits for a screen and reads it.
// Every wait is bounded and ends as soon as its condition holds; none decides by sleeping.

#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <utility>

#include "wait_until.hpp"

namespace tmux_session {

/// The exit status of `command` (run by sh; -1 when it did not exit) and what it printed on
/// stdout.
inline std::pair<int, std::string> run_with_status(const std::string& command) {
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
        return {-1, out};
    std::array<char, 4096> buffer{};
    while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        out.append(buffer.data(), n);
    const int raw = pclose(pipe);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

/// What `command` printed on standard output (its status aside).
inline std::string run(const std::string& command) {
    return run_with_status(command).second;
}

/// `text` as one word for sh: in single quotes, each ' written as '\''.
inline std::string shell_quote(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

/// Fails the test unless `tool` is on the PATH. An end-to-end test never passes without its
/// tool: the message says how to install it, or how to skip every end-to-end test on purpose
/// (the closing line of `make test` then counts them as skipped).
inline void require_tool(const std::string& tool, const std::string& package) {
    if (std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) != 0)
        FAIL(
            tool << " is not installed, and this end-to-end test needs it: `make deps` installs it "
                    "(apt-get install "
                 << package
                 << "), or `TERMPOOL_SKIP_E2E=1 make test` skips the end-to-end tests and counts "
                    "them as skipped");
}

/// Polls `ok` every 20 ms until it holds; false after `seconds` (10 unless told).
inline bool wait_until(const std::function<bool()>& ok, double seconds = 10) {
    return termpool::test::wait_until(ok, seconds);
}

/// The whole file, empty when it cannot be read.
inline std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// A tmux server of its own (tmux is required), killed with the value. Its methods act on the
/// session `e2e` unless told another.
struct Tmux {
    // A socket of its own for each session: a server that is still shutting down must not
    // take the next one's socket with it.
    std::string socket =
        "termpool-e2e-" + std::to_string(getpid()) + "-" + std::to_string(next_id());
    static int next_id() {
        static int id = 0;
        return ++id;
    }
    Tmux() { require_tool("tmux", "tmux"); }
    Tmux(const Tmux&) = delete;
    Tmux& operator=(const Tmux&) = delete;

    /// Runs a tmux command on this server; its output, errors included.
    std::string tmux(const std::string& args) const {
        return run("tmux -L " + socket + " -f /dev/null " + args + " 2>&1");
    }
    /// Starts `command` (run by sh) in a new session, `width` x `height` cells. The server
    /// stays up with no session (exit-empty off), so that a test may end one session and start
    /// the next: a server that exits with its last session can take the next one's start with
    /// it (seen once under load: the resumed game never appeared).
    void start(const std::string& command, int width = 100, int height = 32,
               const std::string& session = "e2e") const {
        tmux("new-session -d -s " + session + " -x " + std::to_string(width) + " -y " +
             std::to_string(height) + " " + shell_quote(command) +
             " \\; set-option -g exit-empty off");
    }
    /// Ends a session (its pane's processes get a hangup).
    void kill_session(const std::string& session = "e2e") const {
        tmux("kill-session -t " + session);
    }
    /// The pane's text; `joined` joins the lines tmux wrapped.
    std::string screen(const std::string& session = "e2e", bool joined = false) const {
        return tmux(std::string("capture-pane -p ") + (joined ? "-J " : "") + "-t " + session);
    }
    /// A format variable of the pane (mouse_any_flag, pane_pid, ...).
    std::string flag(const std::string& name, const std::string& session = "e2e") const {
        std::string v = tmux("display-message -p -t " + session + " '#{" + name + "}'");
        while (!v.empty() && (v.back() == '\n' || v.back() == '\r'))
            v.pop_back();
        return v;
    }
    /// send-keys to the pane.
    void keys(const std::string& args, const std::string& session = "e2e") const {
        tmux("send-keys -t " + session + " " + args);
    }
    /// The same key `count` times, in one send-keys.
    void repeat(const std::string& key, int count, const std::string& session = "e2e") const {
        std::string args;
        for (int i = 0; i < count; ++i)
            args += " " + key;
        keys(args, session);
    }
    /// Polls the screen until `ok` holds; false after `seconds`. `joined`: the screen with the
    /// lines tmux wrapped joined, for a line longer than the pane.
    bool wait_for(const std::function<bool(const std::string&)>& ok, double seconds = 10,
                  const std::string& session = "e2e", bool joined = false) const {
        return wait_until([&] { return ok(screen(session, joined)); }, seconds);
    }
    /// Polls the screen until it shows `text`.
    bool wait_for_text(const std::string& text, double seconds = 10,
                       const std::string& session = "e2e", bool joined = false) const {
        return wait_for([&](const std::string& s) { return s.find(text) != std::string::npos; },
                        seconds, session, joined);
    }
    /// Polls the screen until `text` is gone from it.
    bool wait_gone(const std::string& text, double seconds = 10,
                   const std::string& session = "e2e") const {
        return wait_for([&](const std::string& s) { return s.find(text) == std::string::npos; },
                        seconds, session);
    }
    /// Polls the screen until it differs from `before`.
    bool wait_changed(const std::string& before, double seconds = 10,
                      const std::string& session = "e2e") const {
        return wait_for([&](const std::string& s) { return s != before; }, seconds, session);
    }
    /// Kills the server, then waits (up to 3 s) for the panes' processes to end: a game saves
    /// on its way out, and must be done before the test removes the save's directory.
    ~Tmux() {
        const std::string panes = tmux("list-panes -a -F '#{pane_pid}'");
        tmux("kill-server");
        std::istringstream in(panes);
        for (std::string pid; in >> pid;) {
            if (pid.find_first_not_of("0123456789") != std::string::npos)
                continue; // no server, no panes
            // Each pane is a session of its own, led by the pane's process; zombies (waiting
            // for init to reap them) are done.
            const std::string running = "ps -o stat= -s " + pid + " | grep -av '^Z'";
            wait_until([&] { return run(running).empty(); }, 3);
            // Whatever still runs 3 s after its terminal went away is killed, so that no test
            // leaves a process behind (the hangup test times the game's own exit). Seen once:
            // a sanitized build stuck in LeakSanitizer's exit-time scan.
            run("pkill -KILL -s " + pid + " 2>/dev/null");
        }
    }
};

/// Two hex digits, for send-keys -H.
inline std::string hex(int value) {
    char b[8];
    std::snprintf(b, sizeof b, "%02x", value);
    return b;
}

/// An SGR mouse report (what xterm-256color's kmous, ESC [ <, announces) at the 0-based cell
/// x, y, as send-keys arguments: `button` 35 is motion with no button held, 0 a press of button
/// 1 (`release` for its release), 32 motion with button 1 held.
inline std::string mouse_report(int button, int x, int y, bool release = false) {
    std::string bytes = "-H 1b 5b 3c";
    for (const char c : std::to_string(button) + ";" + std::to_string(x + 1) + ";" +
                            std::to_string(y + 1) + (release ? "m" : "M"))
        bytes += " " + hex(static_cast<unsigned char>(c));
    return bytes;
}

/// Motion with no button held, at the 0-based cell x, y.
inline std::string mouse_motion(int x, int y) {
    return mouse_report(35, x, y);
}

/// The binary under test.
inline std::string termpool_binary() {
    const char* bin = std::getenv("TERMPOOL_BIN");
    return bin ? bin : "build/termpool";
}

/// What the pane's shell wrote to `file` as the game's exit status, once it has written it
/// (waits up to 10 s; empty if it never did).
inline std::string exit_status(const std::string& file) {
    std::string status;
    wait_until([&] {
        std::ifstream in(file);
        return std::getline(in, status) && !status.empty();
    });
    return status;
}

/// A fresh directory under /tmp, removed with the value.
struct ScratchDir {
    std::string path;
    explicit ScratchDir(const std::string& name) {
        std::string pattern = "/tmp/" + name + "-XXXXXX";
        if (const char* made = mkdtemp(pattern.data()))
            path = made;
    }
    ~ScratchDir() {
        // A game that was just killed may still be writing its last save: try again a while.
        if (!path.empty())
            wait_until(
                [&] { return std::system(("rm -rf " + path + " 2>/dev/null").c_str()) == 0; }, 2);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    /// The file where `game_command` has the shell write the game's exit status.
    std::string status_file() const { return path + "/status"; }
    /// The save of the first slot, under this directory as XDG_STATE_HOME.
    std::string save() const { return path + "/termpool/game.save"; }
};

/// `termpool ARGS` with no terminal (standard input /dev/null), its state and config in `dir` and
/// `env` (VAR=VALUE words) before it: its exit status and both streams.
inline std::pair<int, std::string> run_termpool(const ScratchDir& dir, const std::string& args,
                                                const std::string& env = "") {
    return run_with_status("env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path + " " +
                           env + " '" + termpool_binary() + "' " + args + " </dev/null 2>&1");
}

/// The command line that runs `termpool ARGS` with its state and config in `dir`, in
/// `term` with UTF-8, then writes its exit status to dir.status_file() and, with `keep_pane`,
/// keeps the pane (and its last screen) for a minute.
inline std::string game_command(const ScratchDir& dir, const std::string& args,
                                const std::string& term = "xterm-256color", bool keep_pane = true) {
    return "env XDG_STATE_HOME=" + dir.path + " XDG_CONFIG_HOME=" + dir.path + " TERM=" + term +
           " LANG=C.UTF-8 " + termpool_binary() + " " + args + "; echo $? > " + dir.status_file() +
           (keep_pane ? "; sleep 60" : "");
}

} // namespace tmux_session
