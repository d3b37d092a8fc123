// render: a View and a Layout to a Grid, part by part (see draw.hpp).

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "tui/draw.hpp"
#include <termpool/text_width.hpp>

namespace termpool::tui {
namespace {

// "Please enlarge the terminal (need 40x14)", centred, or nothing when even that does not fit.
void draw_too_small(Painter& paint, const Layout& layout) {
    const std::string text = "Please enlarge the terminal (need " +
                             std::to_string(layout.min_width) + "x" +
                             std::to_string(layout.min_height) + ")";
    // A word cut in pieces is unreadable: then the screen stays blank.
    for (const std::string& word : wrap_to_width(text, 1000))
        for (std::size_t start = 0; start < word.size();) {
            const std::size_t end = std::min(word.find(' ', start), word.size());
            if (static_cast<int>(end - start) > paint.width())
                return;
            start = end + 1;
        }
    const std::vector<std::string> lines = wrap_to_width(text, paint.width());
    if (static_cast<int>(lines.size()) > paint.height())
        return;
    const int top = (paint.height() - static_cast<int>(lines.size())) / 2;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int w = display_width(lines[i]);
        paint.text((paint.width() - w) / 2, top + static_cast<int>(i), lines[i], {});
    }
}

} // namespace

Frame::Frame(const View& v, const Layout& l, Painter& p) : view(v), layout(l), paint(p) {
    felt_x = static_cast<int>(std::lround(l.table_left));
    felt_y = static_cast<int>(std::lround(l.table_top));
    felt_w = l.felt_cols;
    felt_h = l.felt_rows;
    frame_x = felt_x - rail_cols;
    frame_y = felt_y - rail_rows;
    frame_w = felt_w + 2 * rail_cols;
    frame_h = felt_h + 2 * rail_rows;
}

bool Frame::cell_of(Vec2 p, int& x, int& y) const {
    double col, row;
    to_cell(layout, table_width(), p, col, row);
    // Far-off or broken positions must not reach an int conversion.
    if (!(std::fabs(col) < 1e6) || !(std::fabs(row) < 1e6))
        return false;
    x = static_cast<int>(std::floor(col));
    y = static_cast<int>(std::floor(row));
    return true;
}

Grid render(const View& view, const Layout& layout, const Capabilities& caps, int width,
            int height) {
    Grid grid(width, height);
    Painter paint(grid, caps);
    if (!layout.fits || !(layout.cells_per_metre > 0)) {
        draw_too_small(paint, layout);
        return grid;
    }
    const Frame frame(view, layout, paint);
    std::vector<std::pair<int, int>> ball_cells;
    if (view.table) {
        draw_table(frame);
        draw_aim(frame);
        ball_cells = draw_balls(frame);
        draw_pocket_labels(frame);
        draw_close_up(frame);
        draw_status(frame);
    }
    draw_panel(frame);
    if (!view.overlay.empty())
        draw_box(frame, view.overlay, ball_cells);
    if (view.help)
        draw_help(paint, view.help_page);
    return grid;
}

} // namespace termpool::tui
