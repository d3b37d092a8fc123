#include "tui/terminal.hpp"

#include <clocale>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <langinfo.h>
#include <ncursesw/curses.h>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unistd.h>

#include "tui/blank_cells.hpp"

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

// What the constructor changed that restore_terminal_modes must undo, so that an exit path
// where curses never started prints nothing.
bool motion_tracking_on = false;
bool cursor_hidden = false;

// How long the rest of a control sequence may take once ESC [ has arrived.
constexpr int sequence_rest_ms = 50;

void write_raw(std::string_view s) {
    // Straight to the terminal: also used where stdio buffers may not be flushed any more.
    const ssize_t ignored = ::write(STDOUT_FILENO, s.data(), s.size());
    (void)ignored;
}

// True when terminfo has the string capability `name` (tigetstr: null when absent, -1 when
// `name` is no string capability).
bool has_string_capability(const char* name) {
    const char* value = tigetstr(name);
    return value != nullptr && value != reinterpret_cast<const char*>(-1) && *value != '\0';
}

// Clears the screen and homes the cursor with terminfo's clear (putp resolves its padding);
// for after endwin, which leaves the cursor on the bottom line.
void clear_screen_now() {
    if (has_string_capability("clear"))
        putp(tigetstr("clear"));
}

// True when the terminal's input has hung up or failed: curses then reports every read as a
// timeout, and the game would wait for keys forever.
bool input_gone() {
    pollfd fd{STDIN_FILENO, POLLIN, 0};
    return ::poll(&fd, 1, 0) == 1 && (fd.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

// The Escape key, or nothing for a control sequence curses did not know. Curses hands over
// ESC alone when what follows matches no key of the terminal's: a mouse report it cannot
// decode (ESC [ M b x y, ESC [ < b;x;y M) or another CSI. Those are swallowed whole, so that
// none of their bytes acts as a key (the button byte of a click is a Space).
Input after_escape() {
    Input escape;
    escape.kind = Input::Kind::key;
    escape.key = key_escape;
    timeout(0);
    wint_t c = 0;
    int status = get_wch(&c);
    if (status == ERR)
        return escape;
    if (status == KEY_CODE_YES || c != '[') {
        // Esc, then a key of its own: both count.
        if (status == KEY_CODE_YES)
            ungetch(static_cast<int>(c));
        else
            unget_wch(c);
        return escape;
    }
    timeout(sequence_rest_ms);
    auto next = [&] {
        status = get_wch(&c);
        if (status == KEY_CODE_YES)
            ungetch(static_cast<int>(c)); // a key after a cut-off sequence stays a key
        return status == OK;
    };
    Input nothing;
    if (!next())
        return nothing;
    if (c == 'M') {
        // X10 mouse report: three bytes of button, column and row follow. Read as bytes: from
        // column 96 on they are not UTF-8, and a wide read would leave the rest as keys.
        for (int i = 0; i < 3; ++i)
            if (getch() == ERR)
                break;
        return nothing;
    }
    // CSI: parameter and intermediate bytes (0x20..0x3F), then one final byte (0x40..0x7E).
    bool plain = true;
    for (int i = 0; i < 64 && c >= 0x20 && c <= 0x3F; ++i) {
        plain = false;
        if (!next())
            return nothing;
    }
    // ESC [ A..D are the arrows of terminals whose terminfo only knows ESC O A..D.
    if (plain && c >= 'A' && c <= 'D') {
        constexpr int arrows[4] = {key_up, key_down, key_right, key_left};
        Input arrow;
        arrow.kind = Input::Kind::key;
        arrow.key = arrows[c - 'A'];
        return arrow;
    }
    return nothing;
}

// The front end's code for a curses function key.
int key_from_curses(int code) {
    switch (code) {
    case KEY_LEFT:
        return key_left;
    case KEY_RIGHT:
        return key_right;
    case KEY_UP:
        return key_up;
    case KEY_DOWN:
        return key_down;
    case KEY_SLEFT:
        return key_shift_left;
    case KEY_SRIGHT:
        return key_shift_right;
    case KEY_PPAGE:
        return key_page_up;
    case KEY_NPAGE:
        return key_page_down;
    case KEY_ENTER:
        return key_enter;
    case KEY_BACKSPACE:
        return key_backspace;
    default:
        return key_other;
    }
}

} // namespace

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
    case Colour::ink:
        // Colour 0 rather than 16: a moving ball's digits are sent every frame, and "ESC [30m"
        // is half of "ESC [38;5;16m". Dark digits on a bright ball read in any palette.
        return {COLOR_BLACK, COLOR_BLACK};
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
        // Bright, so that the 6 stands out on the felt (28) and the cushion (22) and takes
        // black digits; with 8 colours green is the felt's, so cyan is the nearest free one.
        return {46, COLOR_CYAN};
    case Colour::maroon:
        return {88, COLOR_RED};
    case Colour::brown:
        // With 8 colours the nearest is red; the brown still reads by its 4.
        return {130, COLOR_RED};
    case Colour::pink:
        return {211, COLOR_MAGENTA};
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

bool set_drawing_modes(bool colour) {
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    if (colour) {
        start_color();
        use_default_colors();
    }
    const bool hidden = curs_set(0) != ERR;
    // A hidden cursor may stay where the last change left it: curses then sends no move to
    // park it after each frame (9 bytes a frame at 100x32). A visible one is parked, as before.
    leaveok(stdscr, hidden);
    return hidden;
}

void restore_terminal_modes() {
    if (motion_tracking_on)
        write_raw(mouse_motion_off);
    if (cursor_hidden)
        write_raw("\033[?25h");
    motion_tracking_on = cursor_hidden = false;
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
    // A terminal that cannot put the cursor where it is told (TERM=dumb, a printing terminal)
    // would get the frames written one after another, and the player would see nothing of use.
    if (!has_string_capability("cup")) {
        endwin();
        delscreen(screen_);
        screen_ = nullptr;
        const char* term = std::getenv("TERM");
        throw std::runtime_error(std::string("this terminal (TERM=") + (term ? term : "") +
                                 ") cannot move the cursor, which the game needs: run it in "
                                 "one that can (TERM=xterm-256color, screen, vt100, ...)");
    }
    if (!std::getenv("ESCDELAY"))
        set_escdelay(100);
    const bool colour_wanted = !no_colour && !std::getenv("NO_COLOR") && has_colors();
    cursor_hidden = set_drawing_modes(colour_wanted);
    // Tracking goes on only where curses decodes the reports: terminfo announces them (kmous;
    // vt100 has none) and mousemask finds support. Elsewhere a click would arrive as keys, its
    // button byte a Space that shoots.
    if (has_string_capability("kmous") &&
        mousemask(ALL_MOUSE_EVENTS | REPORT_MOUSE_POSITION, nullptr) != 0) {
        mouseinterval(0);
        write_raw(mouse_motion_on);
        motion_tracking_on = true;
    }
    caps_.mouse = motion_tracking_on;
    alternate_screen_ = has_string_capability("smcup");

    caps_.colours = !colour_wanted ? 0 : COLORS >= 256 ? 256 : 8;

    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (const int sig : {SIGINT, SIGTERM, SIGHUP})
        sigaction(sig, &action, nullptr);
    // A terminal that went away (ssh dropped, a pipe closed) must not kill the game before it
    // is saved: writes then fail with EPIPE instead, and the hangup is seen on the input.
    std::signal(SIGPIPE, SIG_IGN);
}

Terminal::~Terminal() {
    restore_terminal_modes();
    curs_set(1);
    endwin();
    // Without an alternate screen (vt100, linux) the last frame would stay behind the prompt.
    if (!alternate_screen_)
        clear_screen_now();
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

short ColourPairs::pair_of(short fg, short bg) {
    const int key = (fg + 1) << 16 | (bg + 1);
    for (const auto& [k, pair] : pairs_)
        if (k == key)
            return pair;
    const short next = static_cast<short>(pairs_.size() + 1);
    if (next >= COLOR_PAIRS)
        return 0;
    init_pair(next, fg, bg);
    pairs_.emplace_back(key, next);
    return next;
}

short ColourPairs::pair_for(const Style& style, int colours) {
    if (colours == 0)
        return 0;
    auto pick = [&](Colour c) { return colours == 256 ? palette(c).c256 : palette(c).c8; };
    return pair_of(pick(style.fg), pick(style.bg));
}

short ColourPairs::blank_pair_for(Colour bg, int colours) {
    if (colours == 0)
        return 0;
    return pair_of(0, colours == 256 ? palette(bg).c256 : palette(bg).c8);
}

void paint(const Grid& grid, const Capabilities& caps, ColourPairs& pairs) {
    // Most of what a terminal receives during a shot is colour and attribute changes: a moving
    // ball is two changed cells, the cloth where it was and its label where it is, and curses
    // sends both colours of each new pair, and resets all attributes before switching bold on
    // or off. A blank of the cloth is therefore sent bold, as the labels are, with foreground
    // colour 0, which has the shortest escape; a blank shows neither (blank_cells.hpp).
    //
    // curses also takes rows of the same characters (it compares characters only) for rows
    // that moved: where three or more line up it scrolls that region of the terminal and then
    // redraws whole the row it uncovered, hundreds of bytes for a ball that moved a row among
    // the cloth's identical rows. So that no two rows are alike, one blank of each row of cloth
    // is sent as a no-break space, at a column of the row's own (with UTF-8 only).
    erase();
    const int rows = std::min(grid.height, LINES), cols = std::min(grid.width, COLS);
    for (int y = 0; y < rows; ++y) {
        const int signature_x = caps.utf8 ? signature_column(grid, y) : -1;
        for (int x = 0; x < cols; ++x) {
            // The bottom-right cell would scroll some terminals: leave it alone.
            if (y == LINES - 1 && x == COLS - 1)
                continue;
            const Cell& cell = grid.at(x, y);
            const bool blank = coloured_blank(cell);
            attr_t attrs = A_NORMAL;
            if (cell.style.bold || blank)
                attrs |= A_BOLD;
            if (cell.style.reverse)
                attrs |= A_REVERSE;
            const short pair = blank ? pairs.blank_pair_for(cell.style.bg, caps.colours)
                                     : pairs.pair_for(cell.style, caps.colours);
            attr_set(attrs, pair, nullptr);
            mvaddstr(y, x, x == signature_x ? no_break_space : cell.glyph.c_str());
        }
    }
    attr_set(A_NORMAL, 0, nullptr);
    wnoutrefresh(stdscr);
    doupdate();
}

void Terminal::draw(const Grid& grid) {
    paint(grid, caps_, pairs_);
}

Input Terminal::read(int timeout_ms, int watched_fd) {
    Input in;
    if (pending_signal) {
        in.kind = Input::Kind::signal;
        return in;
    }
    if (watched_fd >= 0) {
        // What curses has read ahead is not on the descriptor any more: take that first, then
        // wait for either side.
        timeout(0);
        if (Input queued = read(0); queued.kind != Input::Kind::none)
            return queued;
        pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {watched_fd, POLLIN, 0}};
        if (::poll(fds, 2, timeout_ms) > 0 && fds[1].revents != 0 && fds[0].revents == 0) {
            in.kind = Input::Kind::watched;
            return in;
        }
        timeout_ms = 0;
    }
    timeout(timeout_ms);
    wint_t ch = 0;
    const int status = get_wch(&ch);
    if (status == ERR) {
        // The terminal hung up without a SIGHUP reaching us (the parent ignores it, or the
        // game is no session leader): leave as SIGHUP would.
        if (!pending_signal && input_gone())
            pending_signal = SIGHUP;
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
        in.key = key_from_curses(static_cast<int>(ch));
        return in;
    }
    if (ch == key_escape)
        return after_escape();
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
