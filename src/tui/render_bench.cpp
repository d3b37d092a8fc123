// time_render: how long render takes for a typical animation frame.

#include "tui/render_bench.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "tui/break_scene.hpp"

namespace termpool::tui {
namespace {

double thread_cpu_us() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) / 1e3;
}

} // namespace

RenderTime time_render(int width, int height, int frames) {
    const BreakScene scene;
    const View view = scene.view(static_cast<int>(0.3 * animation_fps));
    const Capabilities caps = BreakScene::caps;
    frames = std::max(frames, 1);
    std::size_t sink = 0; // keeps the work from being optimised away
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_us();
    for (int i = 0; i < frames; ++i) {
        const Layout layout = make_layout(*view.table, width, height);
        const Grid grid = render(view, layout, caps, width, height);
        sink += grid.cells.size() + (grid.cells.empty() ? 1 : grid.cells.back().glyph.size());
    }
    const double cpu = thread_cpu_us() - cpu_start;
    const auto end = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double, std::micro>(end - start).count();
    if (sink == 0)
        return {};
    return {wall / frames, cpu / frames};
}

} // namespace termpool::tui
