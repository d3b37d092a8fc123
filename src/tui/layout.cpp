// make_layout: the largest table that fits the terminal, with the panel beside or below it.

#include <algorithm>
#include <cmath>

#include "tui/view.hpp"

namespace termpool::tui {
namespace {

constexpr int side_panel_cols = 26;  // names of up to 20 columns plus marker and indent
constexpr int panel_gap = 1;         // blank column between the table and a side panel
constexpr int status_rows = 2;       // power bar, spin line
constexpr int below_panel_rows = 4;  // title, two players, the legend and help hint
constexpr int shoot_button_cols = 9; // "[ shoot ]"
constexpr int min_status_cols = 28;  // "spin +0.25 -0.25 elev 80.5°", the spin line's shortest

// The playing surface for `cols` x `rows` cells available to it. Rows are worth two columns,
// so the scale is limited by whichever of L / cols and W / (2 rows) is tighter. Whole rows keep
// the cushion lines on cell edges. The rows are odd, so that the long axis (y = W / 2), where
// a rack's middle ball, the spots and the cue ball on the head spot lie, runs through the
// middle of a row and not along an edge where a tenth of a millimetre decides the row. The
// columns are 2 more than a multiple of 4, the nearest such to the 2:1 shape, for the same
// reason lengthwise: the foot and head spots (L / 4 from the ends) fall in the middle of a
// column. That stretches the table by at most 2 columns, under 4 % from 60 columns up.
struct Surface {
    double cols_per_metre = 0, rows_per_metre = 0;
    int cols = 0, rows = 0;
};

Surface fit_surface(const Table& table, int cols, int rows) {
    if (cols <= 0 || rows <= 0 || table.length <= 0 || table.width <= 0)
        return {};
    const double limit = std::min(cols / table.length, 2.0 * rows / table.width);
    Surface s;
    s.rows = static_cast<int>(std::floor(table.width * limit / 2 + 1e-9));
    if (s.rows % 2 == 0)
        --s.rows;
    if (s.rows < 1)
        return {};
    s.rows_per_metre = s.rows / table.width;
    const double shape = 2 * table.length * s.rows_per_metre; // the columns of the true shape
    s.cols = 4 * static_cast<int>(std::lround((shape - 2) / 4)) + 2;
    if (s.cols > cols)
        s.cols -= 4;
    if (s.cols < 2)
        return {};
    s.cols_per_metre = s.cols / table.length;
    return s;
}

} // namespace

Layout make_layout(const Table& table, int width, int height) {
    Layout l;
    if (width < l.min_width || height < l.min_height)
        return l;

    const int frame_extra_cols = 2 * rail_cols, frame_extra_rows = 2 * rail_rows;
    const Surface side = fit_surface(table, width - side_panel_cols - panel_gap - frame_extra_cols,
                                     height - frame_extra_rows - status_rows);
    const Surface below = fit_surface(table, width - frame_extra_cols,
                                      height - frame_extra_rows - status_rows - below_panel_rows);
    // Whichever gives the bigger table (rows, then columns); the side panel on a tie, as it
    // leaves the rows free, unless it leaves the status rows too narrow for the spin line.
    const bool side_room = width - side_panel_cols - panel_gap >= min_status_cols;
    l.panel_below =
        !side_room || below.rows > side.rows || (below.rows == side.rows && below.cols > side.cols);
    const Surface s = l.panel_below ? below : side;
    if (s.rows < 1)
        return l;

    const int frame_w = s.cols + frame_extra_cols, frame_h = s.rows + frame_extra_rows;
    const int area_w = l.panel_below ? width : width - side_panel_cols - panel_gap;
    const int frame_x = (area_w - frame_w) / 2;
    const int frame_y = 0;

    l.fits = true;
    l.cells_per_metre = s.cols_per_metre;
    l.rows_per_metre = s.rows_per_metre;
    l.felt_cols = s.cols;
    l.felt_rows = s.rows;
    l.table_left = frame_x + rail_cols;
    l.table_top = frame_y + rail_rows;
    l.status_y = frame_y + frame_h;
    l.status_x = 0;
    l.status_width = area_w;
    if (l.panel_below) {
        l.panel_x = 0;
        l.panel_y = l.status_y + status_rows;
        l.panel_width = width;
        l.panel_height = height - l.panel_y;
    } else {
        l.panel_x = width - side_panel_cols;
        l.panel_y = 0;
        l.panel_width = side_panel_cols;
        l.panel_height = height;
    }
    l.button_width = shoot_button_cols;
    l.button_x = l.status_x + l.status_width - shoot_button_cols;
    l.button_y = l.status_y;
    return l;
}

} // namespace termpool::tui
