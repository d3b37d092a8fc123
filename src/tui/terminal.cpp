#include "tui/terminal.hpp"

#include <clocale>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <langinfo.h>
#include <ncursesw/curses.h>
#include <stdexcept>
#include <unistd.h>

namespace termpool::tui {
namespace {

volatile std::sig_atomic_t pending_signal = 0;

void on_signal(int sig) {
    pending_signal = sig;
}

// Any-motion mouse tracking: the pointer is reported while no button is held, so the cue
// follows the mouse. Terminals that do not know it ignore it, and clicks and drags still work.
constexpr char mouse_motion_on[] = "\033[?1003h";
constexpr char mouse_motion_off[] = "\033[?1003l\033[?1002l\033[?1000l";

void write_raw(const char* s) {
    // Straight to the terminal: also used where stdio buffers may not be flushed any more.
    const ssize_t ignored = ::write(STDOUT_FILENO, s, std::strlen(s));
    (void)ignored;
}

// xterm-256 indices and the 8-colour fallbacks of each role.
struct Palette {
    short c256;
    short c8;
};

Palette palette(Colour c) {
    switch (c) {
    case Colour::normal:
        return {-1, -1};
    case Colour::felt:
        return {28, COLOR_GREEN};
    case Colour::rail:
        return {94, COLOR_YELLOW};
    case Colour::cushion:
        return {22, COLOR_GREEN};
    case Colour::pocket:
        return {16, COLOR_BLACK};
    case Colour::white:
        return {231, COLOR_WHITE};
    case Colour::black:
        return {16, COLOR_BLACK};
    case Colour::yellow:
        return {220, COLOR_YELLOW};
    case Colour::blue:
        return {27, COLOR_BLUE};
    case Colour::red:
        return {196, COLOR_RED};
    case Colour::purple:
        return {93, COLOR_MAGENTA};
    case Colour::orange:
        return {208, COLOR_YELLOW};
    case Colour::green:
        return {34, COLOR_GREEN};
    case Colour::maroon:
        return {88, COLOR_RED};
    case Colour::aim:
        return {255, COLOR_WHITE};
    case Colour::ghost:
        return {250, COLOR_WHITE};
    case Colour::dim:
        return {245, COLOR_WHITE};
    case Colour::highlight:
        return {226, COLOR_YELLOW};
    }
    return {-1, -1};
}

} // namespace

const int key_left = KEY_LEFT, key_right = KEY_RIGHT, key_up = KEY_UP, key_down = KEY_DOWN;

void restore_terminal_modes() {
    write_raw(mouse_motion_off);
    write_raw("\033[?25h");
}

Terminal::Terminal(bool ascii, bool no_colour) {
    std::setlocale(LC_ALL, "");
    const char* codeset = nl_langinfo(CODESET);
    caps_.utf8 = !ascii && codeset && std::strcmp(codeset, "UTF-8") == 0;

    // Escape sequences from a slow link can arrive in pieces; keep the wait long enough that
    // arrow keys and mouse reports are not split (Esc is never the only way out anyway).
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO))
        throw std::runtime_error("the game needs a terminal (try termpool --help)");
    screen_ = newterm(nullptr, stdout, stdin);
    if (!screen_)
        throw std::runtime_error("cannot use this terminal (is TERM set?)");
    if (!std::getenv("ESCDELAY"))
        set_escdelay(100);
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    curs_set(0);
    mousemask(ALL_MOUSE_EVENTS | REPORT_MOUSE_POSITION, nullptr);
    mouseinterval(0);
    write_raw(mouse_motion_on);

    const bool colour_wanted = !no_colour && !std::getenv("NO_COLOR");
    if (colour_wanted && has_colors()) {
        start_color();
        use_default_colors();
        caps_.colours = COLORS >= 256 ? 256 : 8;
    } else {
        caps_.colours = 0;
    }

    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (const int sig : {SIGINT, SIGTERM, SIGHUP})
        sigaction(sig, &action, nullptr);
}

Terminal::~Terminal() {
    restore_terminal_modes();
    curs_set(1);
    endwin();
    delscreen(screen_);
}

int Terminal::width() const {
    return COLS;
}
int Terminal::height() const {
    return LINES;
}

bool Terminal::signalled() {
    return pending_signal != 0;
}
int Terminal::signal_number() {
    return pending_signal;
}

short ColourPairs::pair_for(const Style& style, int colours) {
    if (colours == 0)
        return 0;
    const int key = static_cast<int>(style.fg) << 8 | static_cast<int>(style.bg);
    for (const auto& [k, pair] : pairs_)
        if (k == key)
            return pair;
    const short next = static_cast<short>(pairs_.size() + 1);
    if (next >= COLOR_PAIRS)
        return 0;
    auto pick = [&](Colour c) { return colours == 256 ? palette(c).c256 : palette(c).c8; };
    init_pair(next, pick(style.fg), pick(style.bg));
    pairs_.emplace_back(key, next);
    return next;
}

void paint(const Grid& grid, int colours, ColourPairs& pairs) {
    erase();
    const int rows = std::min(grid.height, LINES), cols = std::min(grid.width, COLS);
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < cols; ++x) {
            // The bottom-right cell would scroll some terminals: leave it alone.
            if (y == LINES - 1 && x == COLS - 1)
                continue;
            const Cell& cell = grid.at(x, y);
            attr_t attrs = A_NORMAL;
            if (cell.style.bold)
                attrs |= A_BOLD;
            if (cell.style.reverse)
                attrs |= A_REVERSE;
            attr_set(attrs, pairs.pair_for(cell.style, colours), nullptr);
            mvaddstr(y, x, cell.glyph.c_str());
        }
    }
    attr_set(A_NORMAL, 0, nullptr);
    wnoutrefresh(stdscr);
    doupdate();
}

void Terminal::draw(const Grid& grid) {
    paint(grid, caps_.colours, pairs_);
}

Input Terminal::read(int timeout_ms) {
    Input in;
    if (pending_signal) {
        in.kind = Input::Kind::signal;
        return in;
    }
    timeout(timeout_ms);
    wint_t ch = 0;
    const int status = get_wch(&ch);
    if (status == ERR) {
        if (pending_signal)
            in.kind = Input::Kind::signal;
        return in;
    }
    if (status == KEY_CODE_YES) {
        if (ch == KEY_RESIZE) {
            in.kind = Input::Kind::resize;
            return in;
        }
        if (ch == KEY_MOUSE) {
            MEVENT ev;
            if (getmouse(&ev) != OK)
                return in;
            in.kind = Input::Kind::mouse;
            in.x = ev.x;
            in.y = ev.y;
            in.pressed = ev.bstate & BUTTON1_PRESSED;
            in.released = ev.bstate & BUTTON1_RELEASED;
            in.clicked = ev.bstate & (BUTTON1_CLICKED | BUTTON1_DOUBLE_CLICKED);
            in.moved = (ev.bstate & REPORT_MOUSE_POSITION) != 0;
            return in;
        }
        in.kind = Input::Kind::key;
        in.key = static_cast<int>(ch);
        return in;
    }
    // A character: control characters are keys, the rest is text (UTF-8 encoded).
    if (ch < 32 || ch == 127) {
        in.kind = Input::Kind::key;
        in.key = ch == '\r' ? key_enter : static_cast<int>(ch);
        return in;
    }
    in.kind = Input::Kind::text;
    char buffer[8] = {};
    const std::uint32_t c = ch;
    if (c < 0x80) {
        buffer[0] = static_cast<char>(c);
    } else if (c < 0x800) {
        buffer[0] = static_cast<char>(0xC0 | (c >> 6));
        buffer[1] = static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        buffer[0] = static_cast<char>(0xE0 | (c >> 12));
        buffer[1] = static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        buffer[2] = static_cast<char>(0x80 | (c & 0x3F));
    } else {
        buffer[0] = static_cast<char>(0xF0 | (c >> 18));
        buffer[1] = static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        buffer[2] = static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        buffer[3] = static_cast<char>(0x80 | (c & 0x3F));
    }
    in.text = buffer;
    in.key = static_cast<int>(ch);
    return in;
}

} // namespace termpool::tui
