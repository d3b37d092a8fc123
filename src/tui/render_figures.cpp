// capture_through_pty: the game's frames drawn by curses into a pseudo-terminal, and the bytes
// its master side (what sshd or a terminal emulator reads) receives for each frame.

#include "tui/render_figures.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <clocale>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fcntl.h>
#include <memory>
#include <mutex>
#include <ncursesw/curses.h>
#include <poll.h>
#include <string_view>
#include <sys/ioctl.h>
#include <thread>
#include <unistd.h>

#include "tui/terminal.hpp"

namespace termpool::tui {
namespace {

// Written to the slave side after each frame and taken out of the stream by the reader: an
// APC string, which curses never sends, so the stream splits exactly between frames.
constexpr std::string_view frame_end = "\033_termpool-frame-end\033\\";

// How long the reader may take to catch up with the frames written; a stuck pty ends the
// measurement with an error instead of hanging.
constexpr auto catch_up_limit = std::chrono::seconds(20);

// A file descriptor closed when the value goes.
struct Fd {
    int fd = -1;
    explicit Fd(int f) : fd(f) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd >= 0)
            ::close(fd);
    }
};

// A stdio stream on a copy of a descriptor, closed when the value goes.
using Stream = std::unique_ptr<FILE, int (*)(FILE*)>;
Stream stream_on(int fd, const char* mode) {
    const int copy = fd >= 0 ? ::dup(fd) : -1;
    FILE* file = copy >= 0 ? ::fdopen(copy, mode) : nullptr;
    if (!file && copy >= 0)
        ::close(copy);
    return Stream(file, &std::fclose);
}

// A curses screen, ended and freed when the value goes (before its streams are closed).
struct Screen {
    SCREEN* screen;
    explicit Screen(SCREEN* s) : screen(s) {}
    Screen(const Screen&) = delete;
    Screen& operator=(const Screen&) = delete;
    ~Screen() {
        if (!screen)
            return;
        endwin();
        delscreen(screen);
    }
};

// Drains the master side on its own thread (a large frame would otherwise fill the pty and
// block curses' write) and cuts the stream into frames at each frame_end.
class MasterReader {
public:
    explicit MasterReader(int master) : master_(master), thread_([this] { run(); }) {}
    MasterReader(const MasterReader&) = delete;
    MasterReader& operator=(const MasterReader&) = delete;
    ~MasterReader() {
        stop_ = true;
        thread_.join();
    }

    // Waits until `frames` frames have arrived whole; false when they did not in time.
    bool wait_for(std::size_t frames) {
        std::unique_lock lock(mutex_);
        return arrived_.wait_for(lock, catch_up_limit, [&] { return frames_.size() >= frames; });
    }
    // The frames so far (after wait_for).
    std::vector<std::string> frames() {
        std::lock_guard lock(mutex_);
        return frames_;
    }

private:
    void run() {
        char buffer[65536];
        while (!stop_) {
            pollfd p{master_, POLLIN, 0};
            const int ready = ::poll(&p, 1, 50);
            if (ready < 0 && errno == EINTR)
                continue;
            if (ready <= 0)
                continue;
            const ssize_t n = ::read(master_, buffer, sizeof buffer);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                return; // EIO: the slave side was closed
            take(std::string_view(buffer, static_cast<std::size_t>(n)));
        }
    }

    // Appends bytes to the current frame; a complete frame_end closes it. A partial match that
    // fails was frame bytes after all.
    void take(std::string_view bytes) {
        for (const char c : bytes) {
            if (c == frame_end[matched_]) {
                if (++matched_ < frame_end.size())
                    continue;
                matched_ = 0;
                std::lock_guard lock(mutex_);
                frames_.push_back(std::move(current_));
                current_.clear();
                arrived_.notify_all();
                continue;
            }
            current_.append(frame_end.substr(0, matched_));
            matched_ = 0;
            if (c == frame_end[0])
                matched_ = 1;
            else
                current_.push_back(c);
        }
    }

    int master_;
    std::atomic<bool> stop_ = false;
    std::size_t matched_ = 0;
    std::string current_;
    std::mutex mutex_;
    std::condition_variable arrived_;
    std::vector<std::string> frames_;
    std::thread thread_; // last: it starts once the rest is ready
};

// curses writes UTF-8 only under a UTF-8 locale, which the game takes from the environment
// (Terminal's setlocale): the measurement uses C.UTF-8 whatever this process was given, and
// puts the locale back after.
class Utf8Locale {
public:
    Utf8Locale() {
        const char* current = std::setlocale(LC_CTYPE, nullptr);
        saved_ = current ? current : "C";
        ok_ = std::setlocale(LC_CTYPE, "C.UTF-8") || std::setlocale(LC_CTYPE, "en_US.UTF-8");
    }
    Utf8Locale(const Utf8Locale&) = delete;
    Utf8Locale& operator=(const Utf8Locale&) = delete;
    ~Utf8Locale() { std::setlocale(LC_CTYPE, saved_.c_str()); }
    bool ok() const { return ok_; }

private:
    std::string saved_;
    bool ok_ = false;
};

double thread_cpu_us() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) / 1e3;
}

// A pseudo-terminal pair of `width` x `height`: the master's descriptor and the slave's path.
bool open_pty(int width, int height, int& master, std::string& slave_path, std::string& error) {
    master = posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0 || !ptsname(master)) {
        error = "cannot open a pseudo-terminal (/dev/ptmx)";
        return false;
    }
    slave_path = ptsname(master);
    winsize size{};
    size.ws_row = static_cast<unsigned short>(height);
    size.ws_col = static_cast<unsigned short>(width);
    ioctl(master, TIOCSWINSZ, &size);
    return true;
}

} // namespace

PtyCapture capture_through_pty(int width, int height, int frames,
                               const std::function<Grid(int index)>& frame,
                               const std::string& term) {
    PtyCapture capture;
    const Utf8Locale locale;
    if (!locale.ok()) {
        capture.error = "no UTF-8 locale (C.UTF-8) to draw with";
        return capture;
    }
    int master_fd = -1;
    std::string slave_path;
    const bool opened = open_pty(width, height, master_fd, slave_path, capture.error);
    const Fd master(master_fd);
    if (!opened)
        return capture;
    const Fd slave(::open(slave_path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC));
    const Stream out = stream_on(slave.fd, "w");
    const Stream in = stream_on(slave.fd, "r");
    if (!out || !in) {
        capture.error = "cannot open the pseudo-terminal's slave side " + slave_path;
        return capture;
    }
    MasterReader reader(master.fd);
    const Screen screen(newterm(term.c_str(), out.get(), in.get()));
    if (!screen.screen) {
        capture.error = "no terminfo entry for " + term +
                        " (Debian and Ubuntu: xterm-256color is in the package ncurses-base, "
                        "most others in ncurses-term)";
        return capture;
    }
    // LINES and COLUMNS in the environment would override the pty's size.
    if (LINES != height || COLS != width)
        resize_term(height, width);
    set_drawing_modes(has_colors());
    Capabilities caps;
    caps.colours = !has_colors() ? 0 : COLORS >= 256 ? 256 : 8;
    ColourPairs pairs;
    for (int i = 0; i < frames; ++i) {
        const Grid grid = frame(i);
        const auto wall_start = std::chrono::steady_clock::now();
        const double cpu_start = thread_cpu_us();
        paint(grid, caps, pairs);
        std::fflush(out.get());
        capture.draw_cpu_us.push_back(thread_cpu_us() - cpu_start);
        capture.draw_wall_us.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - wall_start)
                .count());
        if (::write(slave.fd, frame_end.data(), frame_end.size()) !=
            static_cast<ssize_t>(frame_end.size())) {
            capture.error = "cannot write to the pseudo-terminal";
            break;
        }
    }
    if (capture.error.empty() && !reader.wait_for(static_cast<std::size_t>(frames)))
        capture.error = "the pseudo-terminal's output did not arrive";
    capture.sent = reader.frames();
    capture.sent.resize(std::min(capture.sent.size(), static_cast<std::size_t>(frames)));
    return capture;
}

} // namespace termpool::tui
