#pragma once
// The one owner of the terminal (like htop's CRT): it starts and restores curses, turns mouse
// reporting on and off, maps colour roles to what the terminal has, copies a Grid to the
// screen and reads keys, mouse events and resizes. No other file touches curses.

#include <memory>
#include <string>

#include "tui/view.hpp"

struct screen; // curses' SCREEN, kept opaque so that this header does not pull in curses

namespace termpool::tui {

/// One input event.
struct Input {
    enum class Kind { none, key, text, mouse, resize, signal, watched };
    Kind kind = Kind::none; ///< what happened
    int key = 0;            ///< Kind::key: a control character or one of the key_ codes below
    std::string text;       ///< Kind::text: one printable character, UTF-8
    int x = 0, y = 0;       ///< Kind::mouse: the cell
    bool pressed = false;   ///< button 1 went down
    bool released = false;  ///< button 1 went up
    bool clicked = false;   ///< button 1 clicked (down and up in one report)
    bool moved = false;     ///< the pointer moved (with or without a button)
};

/// Keys as Input::key gives them: control characters as they are (Enter is '\n', Backspace
/// 127 or 8), the others as these codes. terminal.cpp maps curses' codes to them, so the rest
/// of the front end needs no curses.
inline constexpr int key_enter = '\n';
inline constexpr int key_escape = 27;
inline constexpr int key_backspace = 127;
inline constexpr int key_left = 0x1000;        ///< arrow left
inline constexpr int key_right = 0x1001;       ///< arrow right
inline constexpr int key_up = 0x1002;          ///< arrow up
inline constexpr int key_down = 0x1003;        ///< arrow down
inline constexpr int key_shift_left = 0x1004;  ///< Shift+left
inline constexpr int key_shift_right = 0x1005; ///< Shift+right
inline constexpr int key_page_up = 0x1006;     ///< Page Up
inline constexpr int key_page_down = 0x1007;   ///< Page Down
inline constexpr int key_other = 0x10FF;       ///< any other function key

/// How a colour role is shown: an xterm-256 index and the 8-colour fallback (a curses colour
/// number 0..7, COLOR_BLACK..COLOR_WHITE); -1 for the terminal's default in both.
struct Palette {
    short c256; ///< with 256 colours
    short c8;   ///< with 8 colours
};

/// The colours of a role.
Palette palette(Colour role);

/// Curses colour pairs, made on first use for each (foreground, background) colour pair.
class ColourPairs {
public:
    /// The pair for a style's colours; 0 (the default pair) in monochrome or when out of pairs.
    short pair_for(const Style& style, int colours);
    /// The pair for a blank cell of background `bg`: the foreground, which a blank does not
    /// show, is colour 0, whose escape is the shortest (see paint).
    short blank_pair_for(Colour bg, int colours);

private:
    short pair_of(short fg, short bg);
    std::vector<std::pair<int, short>> pairs_; // (fg, bg) colour numbers -> pair number
};

/// Copies a grid into curses' screen with erase, one full draw and one doupdate: curses then
/// sends only the cells that changed, and the blanks of the cloth go in the way that costs the
/// fewest bytes (see blank_cells.hpp). Terminal::draw and the byte benchmark share it.
void paint(const Grid& grid, const Capabilities& caps, ColourPairs& pairs);

/// Sets the current curses screen up the way the game draws on it: keys unbuffered and not
/// echoed, Enter as typed, function keys decoded, the cursor hidden (and then left where the
/// last change put it); with `colour`, colours over the terminal's own default. Terminal's
/// constructor and the byte benchmark share it, so that the benchmark's bytes are the game's.
/// Returns whether the cursor could be hidden.
bool set_drawing_modes(bool colour);

/// The terminal, for as long as the value lives.
class Terminal {
public:
    /// Starts curses. `ascii` and `no_colour` force the plain versions. Throws
    /// std::runtime_error when there is no usable terminal.
    Terminal(bool ascii, bool no_colour);
    /// Restores the terminal: mouse reporting off, cursor visible, curses ended; where there
    /// is no alternate screen to return from, the screen is cleared.
    ~Terminal();
    Terminal(const Terminal&) = delete;
    Terminal& operator=(const Terminal&) = delete;

    /// What the terminal can show.
    const Capabilities& caps() const { return caps_; }
    /// Current size in cells.
    int width() const;
    /// Current size in cells.
    int height() const;
    /// Copies the grid to the screen and updates it with one doupdate; curses sends only the
    /// cells that changed.
    void draw(const Grid& grid);
    /// Waits up to `timeout_ms` (negative: until something happens) for one input event.
    /// A terminal that hung up reads as SIGHUP (Input::Kind::signal). Mouse reports and other
    /// control sequences curses cannot decode give Kind::none, never keys. With a
    /// `watched_fd` (the hall's socket), that descriptor becoming readable (or closed) ends
    /// the wait too, as Kind::watched: one loop serves the keyboard and the network.
    Input read(int timeout_ms, int watched_fd = -1);
    /// True once SIGINT, SIGTERM or SIGHUP arrived, or the terminal hung up; the caller should
    /// leave.
    static bool signalled();
    /// The signal that arrived, 0 for none.
    static int signal_number();

private:
    Capabilities caps_;
    bool alternate_screen_ = false; // terminfo has smcup: the screen comes back on exit
    ::screen* screen_ = nullptr;
    ColourPairs pairs_;
};

/// Restores mouse reporting and the cursor from anywhere (used at exit paths); writes nothing
/// when no Terminal changed them.
void restore_terminal_modes();

} // namespace termpool::tui
