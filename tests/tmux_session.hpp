#pragma once
// Driving the real binary in tmux, as a player would: a tmux server of its own, keys, the
// screen, the shell's record of the exit status, and a scratch directory for saves.

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>

namespace tmux_session {

/// What `command` (run by sh) prints on stdout.
inline std::string run(const std::string& command) {
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
        return out;
    std::array<char, 4096> buffer{};
    while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        out.append(buffer.data(), n);
    pclose(pipe);
    return out;
}

/// A tmux server of its own, killed with the value; its session is called e2e.
struct Tmux {
    // A socket of its own for each session: a server that is still shutting down must not
    // take the next one's socket with it.
    std::string socket =
        "termpool-e2e-" + std::to_string(getpid()) + "-" + std::to_string(next_id());
    static int next_id() {
        static int id = 0;
        return ++id;
    }
    /// Runs a tmux command on this server; its output, errors included.
    std::string tmux(const std::string& args) const {
        return run("tmux -L " + socket + " -f /dev/null " + args + " 2>&1");
    }
    /// The pane's text.
    std::string screen() const { return tmux("capture-pane -p -t e2e"); }
    /// A format variable of the pane (mouse_any_flag, pane_pid, ...).
    std::string flag(const std::string& name) const {
        std::string v = tmux("display-message -p -t e2e '#{" + name + "}'");
        while (!v.empty() && (v.back() == '\n' || v.back() == '\r'))
            v.pop_back();
        return v;
    }
    /// Starts `command` (run by sh) in the session, `width` x `height` cells.
    void start(const std::string& command, int width = 100, int height = 32) const {
        tmux("new-session -d -s e2e -x " + std::to_string(width) + " -y " + std::to_string(height) +
             " \"" + command + "\"");
    }
    /// send-keys to the pane.
    void keys(const std::string& args) const { tmux("send-keys -t e2e " + args); }
    /// The same key `count` times, in one send-keys.
    void repeat(const std::string& key, int count) const {
        std::string args;
        for (int i = 0; i < count; ++i)
            args += " " + key;
        keys(args);
    }
    /// Polls the screen until `ok` holds; false after `seconds`.
    bool wait_for(const std::function<bool(const std::string&)>& ok, double seconds = 10) const {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (ok(screen()))
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }
    /// Polls the screen until it shows `text`.
    bool wait_for_text(const std::string& text, double seconds = 10) const {
        return wait_for([&](const std::string& s) { return s.find(text) != std::string::npos; },
                        seconds);
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
            for (int i = 0; i < 60 && !run(running).empty(); ++i)
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
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

/// The whole file, empty when it cannot be read.
inline std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// What the pane's shell wrote to `file` as the game's exit status (waits up to 5 s).
inline std::string exit_status(const std::string& file) {
    std::string status;
    for (int i = 0; i < 100 && status.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::ifstream in(file);
        std::getline(in, status);
    }
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
        for (int i = 0; i < 40 && !path.empty(); ++i) {
            if (std::system(("rm -rf " + path + " 2>/dev/null").c_str()) == 0)
                break;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
};

/// True when tmux can be run; a test without it warns and passes.
inline bool have_tmux() {
    return std::system("command -v tmux >/dev/null 2>&1") == 0;
}

} // namespace tmux_session
