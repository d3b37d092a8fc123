// pocket_cells: the mouth of each pocket in rail cells.

#include "tui/pocket_cells.hpp"

#include <algorithm>
#include <cmath>

namespace termpool::tui {

PocketCells pocket_cells(const Table& table, const Layout& layout, int number) {
    PocketCells out;
    if (number < 1 || number > 6 || !layout.fits)
        return out;
    const Pocket& pocket = table.pockets[static_cast<std::size_t>(number - 1)];
    const Vec2 P = pocket.position;
    const double eps = 1e-9;
    const int felt_x = static_cast<int>(std::lround(layout.table_left));
    const int felt_y = static_cast<int>(std::lround(layout.table_top));
    const int left_rail = felt_x - rail_cols, right_rail = felt_x + layout.felt_cols;
    const bool bottom = P.y <= eps, top = P.y >= table.width - eps;
    const bool left = P.x <= eps, right = P.x >= table.length - eps;
    const int rail_row = bottom ? felt_y + layout.felt_rows : felt_y - 1;
    const int side_col = left ? left_rail : right_rail;

    // How far the mouth reaches along each rail: to the jaw points of this pocket.
    double reach_x = 0, reach_y = 0;
    for (std::size_t k = 0; k < table.jaw_points.size(); ++k) {
        if (table.jaw_point_pocket[k] != number)
            continue;
        const Vec2 j = table.jaw_points[k];
        if (std::fabs(j.y - P.y) < eps)
            reach_x = std::max(reach_x, std::fabs(j.x - P.x));
        if (std::fabs(j.x - P.x) < eps)
            reach_y = std::max(reach_y, std::fabs(j.y - P.y));
    }
    auto add = [&](int x, int y) {
        if (std::find(out.cells.begin(), out.cells.end(), std::pair{x, y}) == out.cells.end())
            out.cells.emplace_back(x, y);
    };
    const double c = layout.cells_per_metre;
    if (top || bottom) {
        for (int col = 0; col < layout.felt_cols; ++col) {
            const double x0 = col / c, x1 = (col + 1) / c, mid = (x0 + x1) / 2;
            const bool spans = !(left || right) && x0 <= P.x + eps && x1 >= P.x - eps;
            if (std::fabs(mid - P.x) <= reach_x || spans)
                add(felt_x + col, rail_row);
        }
    }
    if (left || right) {
        for (int row = 0; row < layout.felt_rows; ++row) {
            const double mid = table.width - (row + 0.5) / layout.rows_per_metre;
            if (std::fabs(mid - P.y) <= reach_y)
                for (int k = 0; k < rail_cols; ++k)
                    add(side_col + k, felt_y + row);
        }
        if (top || bottom)
            for (int k = 0; k < rail_cols; ++k)
                add(side_col + k, rail_row);
        // The number goes in the outer corner cell.
        out.label_x = left ? left_rail : right_rail + rail_cols - 1;
        out.label_y = rail_row;
    } else {
        // Side pocket: left of its centre line.
        out.label_x = felt_x + static_cast<int>(std::lround(P.x * c)) - 1;
        out.label_y = rail_row;
    }
    return out;
}

int pocket_at(const Table& table, const Layout& layout, int x, int y) {
    for (int n = 1; n <= 6; ++n) {
        const PocketCells p = pocket_cells(table, layout, n);
        if (std::find(p.cells.begin(), p.cells.end(), std::pair{x, y}) != p.cells.end())
            return n;
    }
    return 0;
}

const char* pocket_name(int number) {
    // Pocket 1 is at the table's origin, which the screen shows bottom left; the numbers go
    // counter-clockwise.
    static const char* const names[6] = {"bottom-left corner",  "bottom side pocket",
                                         "bottom-right corner", "top-right corner",
                                         "top side pocket",     "top-left corner"};
    return number >= 1 && number <= 6 ? names[number - 1] : "";
}

} // namespace termpool::tui
