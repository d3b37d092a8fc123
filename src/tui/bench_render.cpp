#include "tui/bench_render.hpp"

#include <cstdio>
#include <utility>

#include "tui/render_bench.hpp"
#include "tui/render_figures.hpp"

namespace termpool::tui {

int bench_render(const std::string& cpu) {
    std::printf("termpool bench --render: one core of: %s\n\n", cpu.c_str());
    std::printf("%-28s %12s\n", "frame composition", "us/frame");
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}})
        std::printf("  %3dx%-3d %31.1f\n", w, h, time_render_us(w, h, 400));
    const FrameBytes bytes = measure_break_bytes(100, 32);
    std::printf("\nbytes to the terminal during an 8-ball break at 100x32, 60 frames/s "
                "(xterm-256color):\n");
    std::printf("  first full frame %10.0f bytes\n", bytes.first_frame_bytes);
    std::printf("  animation frames %10d\n", bytes.frames);
    std::printf("  mean per frame   %10.1f bytes\n", bytes.mean_bytes);
    return 0;
}

} // namespace termpool::tui
