#pragma once
// Figures of the terminal front end for `termpool bench --render`; no curses in this header.

namespace termpool::tui {

/// Mean bytes curses writes to an xterm-256color terminal of `width` x `height` per animation
/// frame (60 per second) of a seeded 8-ball break, and the number of frames.
struct FrameBytes {
    double mean_bytes = 0;        ///< bytes per frame
    int frames = 0;               ///< animation frames counted
    double first_frame_bytes = 0; ///< the full first draw, before the shot
};

/// Draws a break at 60 frames per second into a curses screen whose output only counts bytes.
FrameBytes measure_break_bytes(int width, int height);

} // namespace termpool::tui
