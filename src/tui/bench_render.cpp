#include "tui/bench_render.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <utility>

#include "tui/break_scene.hpp"
#include "tui/render_bench.hpp"

namespace termpool::tui {
namespace {

constexpr std::pair<int, int> sizes[] = {{80, 24}, {100, 32}, {200, 60}};

double mean_of(const std::vector<double>& values) {
    return values.empty() ? 0 : std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

} // namespace

BreakBytes break_figures(const PtyCapture& capture) {
    BreakBytes figures;
    figures.error = capture.error;
    if (!capture.error.empty() || capture.sent.size() < 2)
        return figures;
    figures.aim_frame = static_cast<long>(capture.sent[0].size());
    std::vector<long> bytes;
    for (std::size_t i = 1; i < capture.sent.size(); ++i)
        bytes.push_back(static_cast<long>(capture.sent[i].size()));
    figures.frames = static_cast<int>(bytes.size());
    const long total = std::accumulate(bytes.begin(), bytes.end(), 0L);
    figures.frames_sent =
        static_cast<int>(std::count_if(bytes.begin(), bytes.end(), [](long b) { return b > 0; }));
    figures.mean = static_cast<double>(total) / figures.frames;
    figures.mean_sent = figures.frames_sent ? static_cast<double>(total) / figures.frames_sent : 0;
    std::sort(bytes.begin(), bytes.end());
    // The nearest-rank 95th percentile.
    figures.p95 = bytes[(bytes.size() * 95 + 99) / 100 - 1];
    figures.max = bytes.back();
    figures.draw_wall_us = mean_of(capture.draw_wall_us);
    figures.draw_cpu_us = mean_of(capture.draw_cpu_us);
    return figures;
}

BreakBytes measure_break_bytes(int width, int height, const std::string& term) {
    const BreakScene scene;
    return break_figures(capture_through_pty(
        width, height, scene.frames(), [&](int i) { return scene.grid(i, width, height); }, term));
}

int bench_render(const std::string& cpu) {
    std::printf("termpool bench --render: one core of: %s\n\n", cpu.c_str());
    std::printf("frame composition (render alone)   wall us/frame   CPU us/frame\n");
    for (const auto& [w, h] : sizes) {
        const RenderTime t = time_render(w, h, 400);
        std::printf("  %3dx%-3d %39.1f %14.1f\n", w, h, t.wall_us, t.cpu_us);
    }
    std::printf("\nbytes a terminal receives through a pty (terminfo %s, UTF-8) for an 8-ball\n"
                "break at 12 m/s (the game's with --seed 1) drawn at %d frames a second:\n",
                bench_terminal, animation_fps);
    std::printf("  %-7s %7s %7s %7s %6s %6s %6s %10s %8s %7s\n", "size", "aiming", "frames", "mean",
                "p95", "max", "sent", "mean/sent", "wall us", "CPU us");
    int status = 0;
    for (const auto& [w, h] : sizes) {
        const BreakBytes b = measure_break_bytes(w, h, bench_terminal);
        if (!b.error.empty()) {
            std::printf("  %3dx%-3d %s\n", w, h, b.error.c_str());
            status = 1;
            continue;
        }
        std::printf("  %3dx%-3d %7ld %7d %7.1f %6ld %6ld %6d %10.1f %8.1f %7.1f\n", w, h,
                    b.aim_frame, b.frames, b.mean, b.p95, b.max, b.frames_sent, b.mean_sent,
                    b.draw_wall_us, b.draw_cpu_us);
    }
    std::printf("aiming: the first full screen (the player aiming; curses' start included). mean,\n"
                "p95, max: bytes a frame over the frames drawn. sent: the frames that sent\n"
                "anything; mean/sent: their mean. wall us, CPU us: curses' work a frame.\n");
    return status;
}

} // namespace termpool::tui
