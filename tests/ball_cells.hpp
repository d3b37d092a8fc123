#pragma once
// Where the balls should be on the screen: each on the cell holding its centre, as the
// layout maps it. A check of a screen (a rendered Grid, or tmux's text of the pane) against
// the balls' positions, shared by the renderer's tests and the racks' tests in tmux.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <termpool/ball.hpp>
#include <termpool/rack.hpp>
#include <termpool/table.hpp>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/view.hpp"

namespace termpool::test {

/// A screen as glyphs: rows of cells, each one glyph (a UTF-8 character).
using Glyphs = std::vector<std::vector<std::string>>;

/// The glyphs of a rendered grid.
inline Glyphs glyphs_of(const tui::Grid& g) {
    Glyphs rows(static_cast<std::size_t>(g.height));
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            rows[static_cast<std::size_t>(y)].push_back(g.at(x, y).glyph);
    return rows;
}

/// The glyphs of a pane's text (tmux capture-pane -p): one per UTF-8 character, which is one
/// cell for everything the game draws on the table.
inline Glyphs glyphs_of(const std::string& text) {
    Glyphs rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> row;
        for (std::size_t i = 0; i < line.size();) {
            std::size_t n = 1;
            while (i + n < line.size() && (static_cast<unsigned char>(line[i + n]) & 0xC0) == 0x80)
                ++n;
            row.push_back(line.substr(i, n));
            i += n;
        }
        rows.push_back(row);
    }
    return rows;
}

/// The cell holding table point `p`, as the game's renderer takes it.
inline std::pair<int, int> cell_at(const tui::Layout& l, double table_width, Vec2 p) {
    double col, row;
    tui::to_cell(l, table_width, p, col, row);
    return {static_cast<int>(std::floor(col)), static_cast<int>(std::floor(row))};
}

/// How a set of balls is drawn: the display's glyphs and the label forms.
struct BallLook {
    bool utf8 = true;                      ///< UTF-8 glyphs (else ASCII)
    bool wide = false;                     ///< "10".."15" in two cells (else letters)
    tui::BallSet set = tui::BallSet::pool; ///< pool numbers or snooker values
};

/// What is wrong with where `balls` are drawn on `screen` (empty when nothing is):
///  - each ball on the table shows on the cell of its centre: its label (a two-cell label
///    over that cell and a neighbour), the mark of a ball whose number gave way, or the
///    label or mark of another ball whose centre is in the same cell (it covers this one);
///  - a mark only beside a number (a one-cell label gives way to nothing else);
///  - on the felt a ball's glyph shows only on such a cell (the rails hold the pockets'
///    numbers while one is called);
///  - in a pool set no two numbers run together on a row: each run of digits is one label.
inline std::vector<std::string> misplaced_balls(const Glyphs& screen,
                                                const std::vector<Ball>& balls,
                                                const tui::Layout& l, double table_width,
                                                const BallLook& look) {
    const auto glyph = [&](int x, int y) -> std::string {
        if (y < 0 || y >= static_cast<int>(screen.size()) || x < 0 ||
            x >= static_cast<int>(screen[static_cast<std::size_t>(y)].size()))
            return " ";
        return screen[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
    };
    const std::string mark = tui::ball_mark(look.utf8);
    struct Drawn {
        int id, x, y;
        std::string label;
    };
    std::vector<Drawn> drawn;
    for (const Ball& b : balls)
        if (b.state != MotionState::pocketed) {
            const auto [x, y] = cell_at(l, table_width, b.position);
            drawn.push_back({b.id, x, y, tui::ball_label(b.id, look.utf8, look.wide, look.set)});
        }
    // True when the glyph at (x, y) is part of ball d's label as drawn there.
    const auto shows_label = [&](const Drawn& d) {
        if (d.label.size() == 2 && d.id != 0)
            return glyph(d.x - 1, d.y) + glyph(d.x, d.y) == d.label ||
                   glyph(d.x, d.y) + glyph(d.x + 1, d.y) == d.label;
        return glyph(d.x, d.y) == d.label;
    };
    std::vector<std::string> problems;
    for (const Drawn& d : drawn) {
        bool ok = shows_label(d) || glyph(d.x, d.y) == mark;
        for (const Drawn& other : drawn)
            if (&other != &d && other.x == d.x && other.y == d.y && shows_label(other))
                ok = true;
        if (!ok)
            problems.push_back("ball " + std::to_string(d.id) + " at cell (" + std::to_string(d.x) +
                               ", " + std::to_string(d.y) + ") shows '" + glyph(d.x, d.y) + "'");
    }
    // A mark only where a number gave way: beside another number (or, for a two-cell label,
    // with no two cells free around its centre).
    for (const Drawn& d : drawn) {
        const auto digit = [&](int x) {
            const std::string g = glyph(x, d.y);
            return g.size() == 1 && g[0] >= '0' && g[0] <= '9';
        };
        if (glyph(d.x, d.y) == mark && d.label.size() == 1 && !digit(d.x - 1) && !digit(d.x + 1))
            problems.push_back("ball " + std::to_string(d.id) + " at cell (" + std::to_string(d.x) +
                               ", " + std::to_string(d.y) + ") is a mark with no number beside it");
    }
    // Ball glyphs where no ball is.
    const int left = static_cast<int>(std::lround(l.table_left));
    const int top = static_cast<int>(std::lround(l.table_top));
    const auto ball_glyph = [&](const std::string& g) {
        if (g == mark || g == tui::ball_label(0, look.utf8, false))
            return true;
        if (g.size() != 1)
            return false;
        const char c = g[0];
        return (c >= '0' && c <= '9') ||
               (!look.wide && look.set == tui::BallSet::pool && c >= 'A' && c <= 'F');
    };
    const auto owned = [&](int x, int y) {
        for (const Drawn& d : drawn)
            if (d.y == y &&
                (d.x == x || (d.label.size() == 2 && d.id != 0 && std::abs(d.x - x) == 1)))
                return true;
        return false;
    };
    for (int y = top; y < top + l.felt_rows; ++y) {
        int run = 0;
        for (int x = left; x <= left + l.felt_cols; ++x) {
            const std::string g = x < left + l.felt_cols ? glyph(x, y) : " ";
            if (ball_glyph(g) && !owned(x, y))
                problems.push_back("'" + g + "' at cell (" + std::to_string(x) + ", " +
                                   std::to_string(y) + ") where no ball's centre is");
            const bool digit = g.size() == 1 && g[0] >= '0' && g[0] <= '9';
            if (digit) {
                ++run;
                continue;
            }
            // A run of two is one two-cell label only where one is drawn over those cells.
            bool one_label = run <= 1;
            if (run == 2)
                for (const Drawn& d : drawn)
                    if (d.label.size() == 2 && d.id != 0 && d.y == y &&
                        glyph(x - 2, y) + glyph(x - 1, y) == d.label &&
                        std::abs(d.x - (x - 1.5)) < 1)
                        one_label = true;
            if (look.set == tui::BallSet::pool && !one_label)
                problems.push_back("numbers run together before cell (" + std::to_string(x) + ", " +
                                   std::to_string(y) + ")");
            run = 0;
        }
    }
    return problems;
}

/// What is wrong with a rack as drawn on `screen` (empty when nothing is): every ball on its
/// own cell (misplaced_balls), no dot on the foot spot (the apex ball covers it), and for
/// 9-ball the 9 on the middle row of the diamond and inside its columns, for 10-ball the 1
/// on the foot spot's cell.
inline std::vector<std::string> misdrawn_rack(const Glyphs& screen, const std::vector<Ball>& balls,
                                              const tui::Layout& l, const Table& table,
                                              RackType type, const BallLook& look) {
    std::vector<std::string> problems = misplaced_balls(screen, balls, l, table.width, look);
    const auto glyph = [&](std::pair<int, int> c) -> std::string {
        const auto [x, y] = c;
        if (y < 0 || y >= static_cast<int>(screen.size()) || x < 0 ||
            x >= static_cast<int>(screen[static_cast<std::size_t>(y)].size()))
            return " ";
        return screen[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
    };
    const std::string spot_dot = look.utf8 ? "\u00B7" : ".";
    const int left = static_cast<int>(std::lround(l.table_left));
    const int top = static_cast<int>(std::lround(l.table_top));
    for (int y = top; y < top + l.felt_rows; ++y)
        for (int x = left; x < left + l.felt_cols; ++x)
            if (glyph({x, y}) == spot_dot)
                problems.push_back("a spot's dot at cell (" + std::to_string(x) + ", " +
                                   std::to_string(y) + ")");
    int min_x = 1 << 20, max_x = -(1 << 20), min_y = 1 << 20, max_y = -(1 << 20);
    std::pair<int, int> one{-1, -1}, nine{-1, -1};
    for (const Ball& b : balls) {
        if (b.id == 0)
            continue;
        const auto c = cell_at(l, table.width, b.position);
        min_x = std::min(min_x, c.first), max_x = std::max(max_x, c.first);
        min_y = std::min(min_y, c.second), max_y = std::max(max_y, c.second);
        if (b.id == 1)
            one = c;
        if (b.id == 9)
            nine = c;
    }
    if (type == RackType::nine_ball) {
        if (glyph(nine) != "9")
            problems.push_back("the 9's cell shows '" + glyph(nine) + "'");
        if (2 * nine.second != min_y + max_y)
            problems.push_back("the 9 on row " + std::to_string(nine.second) +
                               " of the diamond's rows " + std::to_string(min_y) + ".." +
                               std::to_string(max_y));
        if (nine.first <= min_x || nine.first >= max_x)
            problems.push_back("the 9 in column " + std::to_string(nine.first) +
                               " at the edge of the diamond's columns " + std::to_string(min_x) +
                               ".." + std::to_string(max_x));
    }
    if (type == RackType::ten_ball) {
        const auto foot = cell_at(l, table.width, table.foot_spot());
        if (one != foot)
            problems.push_back("the 1 at cell (" + std::to_string(one.first) + ", " +
                               std::to_string(one.second) + "), the foot spot at (" +
                               std::to_string(foot.first) + ", " + std::to_string(foot.second) +
                               ")");
        if (glyph(one) != "1")
            problems.push_back("the 1's cell shows '" + glyph(one) + "'");
    }
    return problems;
}

} // namespace termpool::test
