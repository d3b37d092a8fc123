#pragma once
// Timing of the renderer alone, for `termpool bench --render`.

namespace termpool::tui {

/// Mean time to compose one frame, layout included.
struct RenderTime {
    double wall_us = 0; ///< wall-clock microseconds per frame
    double cpu_us = 0;  ///< CPU microseconds per frame (this thread's)
};

/// Renders the same frame of BreakScene (0.3 s into the break: colour and UTF-8, with the
/// panel and its message) `frames` times at `width` x `height`.
RenderTime time_render(int width, int height, int frames);

} // namespace termpool::tui
