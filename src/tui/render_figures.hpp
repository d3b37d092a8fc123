#pragma once
// What a terminal receives from the game's drawing, for `termpool bench --render` and the byte
// tests; no curses in this header.

#include <functional>
#include <string>
#include <vector>

#include "tui/view.hpp"

namespace termpool::tui {

/// The terminal the byte figures are measured for by default: what xterm, VTE terminals and
/// most SSH clients announce.
inline constexpr const char* bench_terminal = "xterm-256color";

/// What went through the pty, frame by frame.
struct PtyCapture {
    std::string error;                ///< why nothing was measured (no pty, no terminfo); else ""
    std::vector<std::string> sent;    ///< the bytes the terminal received for each frame
    std::vector<double> draw_wall_us; ///< wall time of each frame's paint and doupdate
    std::vector<double> draw_cpu_us;  ///< CPU time of the same (this thread's)
};

/// Opens a pseudo-terminal of `width` x `height`, starts curses on its slave side with the
/// terminfo entry `term` and the game's drawing modes (set_drawing_modes, 256 colours when the
/// entry has them), draws `frames` grids from `frame(0)` on with paint() as the game does, and
/// returns the bytes read from the master side for each frame. Frame 0 includes what curses
/// sends to start; what endwin sends is not counted. A missing terminfo entry or pty gives only
/// `error`.
PtyCapture capture_through_pty(int width, int height, int frames,
                               const std::function<Grid(int index)>& frame,
                               const std::string& term = bench_terminal);

} // namespace termpool::tui
