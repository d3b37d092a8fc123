// time_render_us: how long render takes for a typical animation frame.

#include "tui/render_bench.hpp"

#include <algorithm>
#include <chrono>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>

#include "tui/view.hpp"

namespace termpool::tui {

double time_render_us(int width, int height, int frames) {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    const std::vector<Ball> rack = make_rack(table, params, RackType::eight_ball, 1);
    Trajectory trajectory(params, rack.size());
    simulate_shot(table, params, rack, {12.0, 0.3, 0, 0}, &trajectory);

    View view;
    view.table = &table;
    view.balls = trajectory.sample(0.3);
    view.ball_radius = params.ball_radius;
    view.names[0] = "Alice";
    view.names[1] = "Bob";
    view.message = "Alice breaks.";
    const Capabilities caps{256, true};

    frames = std::max(frames, 1);
    std::size_t sink = 0; // keeps the work from being optimised away
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        const Layout layout = make_layout(table, width, height);
        const Grid grid = render(view, layout, caps, width, height);
        sink += grid.cells.size() + (grid.cells.empty() ? 1 : grid.cells.back().glyph.size());
    }
    const auto end = std::chrono::steady_clock::now();
    const double us = std::chrono::duration<double, std::micro>(end - start).count();
    return sink > 0 ? us / frames : 0;
}

} // namespace termpool::tui
