#include "tui/render_figures.hpp"

#include <chrono>
#include <cstdio>
#include <ncursesw/curses.h>
#include <sys/stat.h>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>

#include "tui/terminal.hpp"
#include "tui/view.hpp"

namespace termpool::tui {
namespace {

// curses writes straight to the file descriptor, so the bytes are counted by the file's size.
long bytes_written(FILE* out) {
    std::fflush(out);
    struct stat st {};
    return fstat(fileno(out), &st) == 0 ? static_cast<long>(st.st_size) : 0;
}

// A break and its recorded motion, the same for every measurement.
struct BreakShot {
    Table table = make_table(TableSize::nine_foot);
    PhysicsParams params;
    std::vector<Ball> rack = make_rack(table, params, RackType::eight_ball, 7);
    Trajectory trajectory{params, rack.size()};
    ShotResult result;
    BreakShot() { result = simulate_shot(table, params, rack, {12, 0, 0, 0}, &trajectory); }

    View view(double t) const {
        View v;
        v.table = &table;
        v.balls = trajectory.sample(t);
        v.message = "Player 1 breaks";
        return v;
    }
};

} // namespace

FrameBytes measure_break_bytes(int width, int height) {
    FrameBytes figures;
    const BreakShot shot;
    FILE* out = std::tmpfile();
    FILE* in = std::fopen("/dev/null", "r");
    if (!out || !in)
        return figures;
    SCREEN* screen = newterm("xterm-256color", out, in);
    if (!screen) {
        std::fclose(out);
        std::fclose(in);
        return figures;
    }
    resize_term(height, width);
    start_color();
    use_default_colors();
    const Capabilities caps{256, true};
    ColourPairs pairs;
    const Layout layout = make_layout(shot.table, width, height);

    const long start = bytes_written(out);
    paint(render(shot.view(0), layout, caps, width, height), caps.colours, pairs);
    const long first = bytes_written(out);
    figures.first_frame_bytes = static_cast<double>(first - start);
    for (double t = 1.0 / 60; t < shot.result.rest_time; t += 1.0 / 60) {
        paint(render(shot.view(t), layout, caps, width, height), caps.colours, pairs);
        ++figures.frames;
    }
    const long total = bytes_written(out) - first;
    figures.mean_bytes = figures.frames ? static_cast<double>(total) / figures.frames : 0;
    endwin();
    delscreen(screen);
    std::fclose(out);
    std::fclose(in);
    return figures;
}

} // namespace termpool::tui
