#pragma once
// `termpool bench --render`: the terminal front end's figures. The bench command parses the
// options; main passes it this, so that the commands need not include the front end.

#include <string>
#include <vector>

#include "tui/render_figures.hpp"

namespace termpool::tui {

/// The bytes a terminal received per animation frame of the break (BreakScene), through a pty.
struct BreakBytes {
    std::string error;       ///< why nothing was measured; else ""
    long aim_frame = 0;      ///< the first full frame (the aiming player), with curses' start
    int frames = 0;          ///< animation frames drawn (60 a second)
    int frames_sent = 0;     ///< of those, the frames that sent anything
    double mean = 0;         ///< mean bytes per animation frame
    double mean_sent = 0;    ///< mean bytes per frame that sent anything
    long p95 = 0;            ///< 95th percentile of the animation frames' bytes
    long max = 0;            ///< the largest animation frame
    double draw_wall_us = 0; ///< mean wall time of curses' paint and doupdate per frame
    double draw_cpu_us = 0;  ///< the same, CPU time
};

/// The figures of a capture of BreakScene: frame 0 the aiming one, the others the animation.
BreakBytes break_figures(const PtyCapture& capture);

/// The break drawn at `width` x `height` through a pty with terminfo `term`.
BreakBytes measure_break_bytes(int width, int height, const std::string& term);

/// Prints on stdout the time to compose a frame and the bytes a terminal receives per
/// animation frame of a break, at 80x24, 100x32 and 200x60, under a heading naming `cpu`;
/// returns the exit status (0; 1 when the bytes could not be measured).
int bench_render(const std::string& cpu);

} // namespace termpool::tui
