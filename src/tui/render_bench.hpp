#pragma once
// Timing of the renderer alone, for `termpool bench --render`.

namespace termpool::tui {

/// Renders the same mid-break frame (a seeded 8-ball break 0.3 s after the strike, colour and
/// UTF-8, with the panel and a message) `frames` times at `width` x `height` and returns the
/// mean microseconds per frame, layout included.
double time_render_us(int width, int height, int frames);

} // namespace termpool::tui
