#pragma once
// The real binary in tmux, driven as a player would: a tmux server of its own per session,
// keys and raw bytes in, the pane's text out, and the pane shell's record of the exit status.

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <unistd.h>

namespace termpool::test {

/// Runs a shell command and returns what it printed on standard output.
inline std::string run_command(const std::string& command) {
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

/// True when tmux can be run here.
inline bool have_tmux() {
    return std::system("command -v tmux >/dev/null 2>&1") == 0;
}

/// The binary under test (TERMPOOL_BIN, set by the Makefile).
inline std::string termpool_binary() {
    const char* bin = std::getenv("TERMPOOL_BIN");
    return bin ? bin : "build/termpool";
}

/// A tmux server of its own with one session, "e2e"; killed with the value.
struct TmuxSession {
    // A socket of its own for each session: a server that is still shutting down must not
    // take the next one's socket with it.
    std::string socket = "termpool-t-" + std::to_string(getpid()) + "-" + std::to_string(next_id());
    static int next_id() {
        static int id = 0;
        return ++id;
    }
    /// Runs a tmux command on this server.
    std::string tmux(const std::string& args) const {
        return run_command("tmux -L " + socket + " -f /dev/null " + args + " 2>&1");
    }
    /// Starts `command` in a new session of `width` x `height`.
    void start(const std::string& command, int width = 100, int height = 32) const {
        tmux("new-session -d -s e2e -x " + std::to_string(width) + " -y " + std::to_string(height) +
             " \"" + command + "\"");
    }
    /// The pane's text.
    std::string screen() const { return tmux("capture-pane -p -t e2e"); }
    /// send-keys arguments, as tmux takes them.
    void keys(const std::string& args) const { tmux("send-keys -t e2e " + args); }
    /// The same key `count` times.
    void repeat(const std::string& key, int count) const {
        std::string args;
        for (int i = 0; i < count; ++i)
            args += " " + key;
        keys(args);
    }
    /// The pid of the pane's shell.
    std::string pane_pid() const {
        std::string pid = tmux("display-message -p -t e2e '#{pane_pid}'");
        while (!pid.empty() && (pid.back() == '\n' || pid.back() == '\r'))
            pid.pop_back();
        return pid;
    }
    /// Polls the screen until `ok` holds, for at most `seconds`.
    bool wait_for(const std::function<bool(const std::string&)>& ok, double seconds = 10) const {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (ok(screen()))
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }
    /// Polls until the screen shows `text`.
    bool wait_for_text(const std::string& text, double seconds = 10) const {
        return wait_for([&](const std::string& s) { return s.find(text) != std::string::npos; },
                        seconds);
    }
    ~TmuxSession() { tmux("kill-server"); }
};

/// A fresh directory under /tmp, removed with the value.
struct TempDir {
    std::string path;
    explicit TempDir(const std::string& stem = "termpool-test") {
        std::string pattern = "/tmp/" + stem + "-XXXXXX";
        path = mkdtemp(pattern.data()) ? pattern : "/tmp";
    }
    ~TempDir() {
        // A game that just got its hangup may still be writing its save: try a few times.
        for (int i = 0; i < 20 && path != "/tmp"; ++i) {
            if (std::system(("rm -rf '" + path + "' 2>/dev/null").c_str()) == 0)
                return;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    }
};

/// A file's whole text ("" when it cannot be read).
inline std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace termpool::test
