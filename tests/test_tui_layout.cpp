// Terminal layout: the table's size and place for several terminal sizes, the panel beside or
// below it, and the mapping between table metres and cells both ways.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <termpool/table.hpp>

#include "tui/view.hpp"

using namespace termpool;
using namespace termpool::tui;

namespace {

const Table table = make_table(TableSize::nine_foot);

struct Rect {
    int x, y, w, h;
    bool overlaps(const Rect& o) const {
        return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
    }
    bool inside(int width, int height) const {
        return x >= 0 && y >= 0 && x + w <= width && y + h <= height;
    }
};

Rect frame_of(const Layout& l) {
    return {static_cast<int>(l.table_left) - rail_cols, static_cast<int>(l.table_top) - rail_rows,
            l.felt_cols + 2 * rail_cols, l.felt_rows + 2 * rail_rows};
}

const std::pair<int, int> sizes[] = {{80, 24},  {100, 32}, {200, 60}, {40, 14},
                                     {300, 90}, {60, 40},  {120, 24}, {200, 40}};

} // namespace

TEST_CASE("the table, status rows and panel fit the terminal without overlapping", "[tui]") {
    for (const auto& [w, h] : sizes) {
        CAPTURE(w, h);
        const Layout l = make_layout(table, w, h);
        REQUIRE(l.fits);
        const Rect frame = frame_of(l);
        const Rect status{l.status_x, l.status_y, l.status_width, 2};
        const Rect panel{l.panel_x, l.panel_y, l.panel_width, l.panel_height};
        CHECK(frame.inside(w, h));
        CHECK(status.inside(w, h));
        CHECK(panel.inside(w, h));
        CHECK(panel.w > 0);
        CHECK(panel.h >= 3);
        CHECK_FALSE(frame.overlaps(panel));
        CHECK_FALSE(frame.overlaps(status));
        CHECK_FALSE(status.overlaps(panel));
        // The button sits on the first status row.
        CHECK(l.button_y == l.status_y);
        CHECK(l.button_x >= l.status_x);
        CHECK(l.button_x + l.button_width <= l.status_x + l.status_width);
        CHECK(on_shoot_button(l, l.button_x, l.button_y));
        CHECK_FALSE(on_shoot_button(l, l.button_x - 1, l.button_y));
    }
}

TEST_CASE("the table keeps its 2:1 shape with cells twice as tall as wide", "[tui]") {
    for (const auto& [w, h] : sizes) {
        CAPTURE(w, h);
        const Layout l = make_layout(table, w, h);
        // L c columns by W r rows, r about c / 2, and L = 2 W: 4 columns a row, stretched by
        // at most 2 columns over the length.
        CHECK(l.felt_cols == Approx(table.length * l.cells_per_metre));
        CHECK(l.felt_rows == Approx(table.width * l.rows_per_metre));
        CHECK(std::abs(l.felt_cols - 4 * l.felt_rows) <= 2);
    }
}

TEST_CASE("the long axis and the foot and head spots lie in the middle of cells", "[tui]") {
    // So that a rack drawn at its balls' own cells is symmetric, and its apex ball is on the
    // foot spot's cell rather than on either side of an edge by a tenth of a millimetre.
    for (const TableSize size :
         {TableSize::seven_foot, TableSize::eight_foot, TableSize::nine_foot, TableSize::snooker}) {
        const Table t = make_table(size);
        for (const auto& [w, h] : sizes) {
            CAPTURE(static_cast<int>(size), w, h);
            const Layout l = make_layout(t, w, h);
            REQUIRE(l.fits);
            CHECK(l.felt_rows % 2 == 1);
            CHECK(l.felt_cols % 4 == 2);
            for (const Vec2 spot : {t.foot_spot(), t.head_spot()}) {
                double col, row;
                to_cell(l, t.width, spot, col, row);
                CHECK(col - std::floor(col) == Approx(0.5));
                CHECK(row - std::floor(row) == Approx(0.5));
            }
        }
    }
}

TEST_CASE("the panel goes beside the table when that costs no table size", "[tui]") {
    CHECK(make_layout(table, 80, 24).panel_below);
    CHECK(make_layout(table, 100, 32).panel_below);
    CHECK(make_layout(table, 60, 40).panel_below);
    CHECK(make_layout(table, 40, 14).panel_below);
    CHECK_FALSE(make_layout(table, 120, 24).panel_below);
    CHECK_FALSE(make_layout(table, 200, 40).panel_below);
    const Layout side = make_layout(table, 120, 24);
    CHECK(side.panel_width == 26);
    CHECK(side.panel_x + side.panel_width == 120);
    CHECK(side.panel_height == 24);
}

TEST_CASE("the largest table that fits: bigger terminals never get smaller tables", "[tui]") {
    int previous = 0;
    for (int w = 40; w <= 300; w += 7) {
        const Layout l = make_layout(table, w, 40);
        CHECK(l.felt_rows >= previous);
        previous = l.felt_rows;
    }
    previous = 0;
    for (int h = 14; h <= 90; h += 3) {
        const Layout l = make_layout(table, 300, h);
        CHECK(l.felt_rows >= previous);
        previous = l.felt_rows;
    }
    // At 80x24 the surface is 62 x 15: 16 rows + 2 rails + 2 status rows + 4 panel rows (title,
    // players, and the legend with the help hint) = 24 would fit, but the rows are odd; 62
    // columns is 4 a row, and 2 more to put the spots in the middle of columns.
    const Layout l = make_layout(table, 80, 24);
    CHECK(l.felt_rows == 15);
    CHECK(l.felt_cols == 62);
}

TEST_CASE("below 40x14 the layout does not fit", "[tui]") {
    CHECK(make_layout(table, 40, 14).fits);
    CHECK_FALSE(make_layout(table, 39, 14).fits);
    CHECK_FALSE(make_layout(table, 40, 13).fits);
    CHECK_FALSE(make_layout(table, 1, 1).fits);
    CHECK_FALSE(make_layout(table, 0, 0).fits);
    CHECK_FALSE(make_layout(table, -5, 100).fits);
    const Layout l = make_layout(table, 10, 10);
    CHECK(l.min_width == 40);
    CHECK(l.min_height == 14);
}

TEST_CASE("table points and cells map both ways", "[tui]") {
    for (const auto& [w, h] : sizes) {
        CAPTURE(w, h);
        const Layout l = make_layout(table, w, h);
        const double W = table.width;
        double col, row;
        // The corners of the playing surface are the corners of the felt cells.
        to_cell(l, W, {0, 0}, col, row);
        CHECK(col == Approx(l.table_left));
        CHECK(row == Approx(l.table_top + l.felt_rows));
        to_cell(l, W, {table.length, W}, col, row);
        CHECK(col == Approx(l.table_left + l.felt_cols));
        CHECK(row == Approx(l.table_top));
        // y grows upward on the table and downward on the screen.
        double col2, row2;
        to_cell(l, W, {1, 0.2}, col, row);
        to_cell(l, W, {1, 0.9}, col2, row2);
        CHECK(row2 < row);
        // Table -> cell -> table.
        for (double x = 0.01; x < table.length; x += 0.173)
            for (double y = 0.01; y < W; y += 0.097) {
                to_cell(l, W, {x, y}, col, row);
                const Vec2 back = from_cell(l, W, col - 0.5, row - 0.5);
                CHECK(back.x == Approx(x).margin(1e-9));
                CHECK(back.y == Approx(y).margin(1e-9));
            }
        // Cell -> table -> cell: from_cell gives the centre of the cell.
        const int felt_x = static_cast<int>(l.table_left), felt_y = static_cast<int>(l.table_top);
        for (int cy = felt_y; cy < felt_y + l.felt_rows; cy += 3)
            for (int cx = felt_x; cx < felt_x + l.felt_cols; cx += 5) {
                const Vec2 p = from_cell(l, W, cx, cy);
                CHECK(p.x > 0);
                CHECK(p.x < table.length);
                CHECK(p.y > 0);
                CHECK(p.y < W);
                to_cell(l, W, p, col, row);
                CHECK(col == Approx(cx + 0.5));
                CHECK(row == Approx(cy + 0.5));
            }
    }
}

TEST_CASE("the 7ft and 8ft tables are laid out the same way", "[tui]") {
    for (const TableSize size : {TableSize::seven_foot, TableSize::eight_foot}) {
        const Table t = make_table(size);
        const Layout l = make_layout(t, 100, 32);
        REQUIRE(l.fits);
        CHECK(std::abs(l.felt_cols - 4 * l.felt_rows) <= 2);
        CHECK(frame_of(l).inside(100, 32));
    }
}
