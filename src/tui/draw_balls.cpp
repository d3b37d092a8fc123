// The balls: one label each ("3", "C" or, on a big table, "12"), on the cells that hold its
// centre. Two numbers never touch on a row, so that a 1 beside a 5 never reads as 15: a ball
// whose cells are taken, or whose number would touch another number, goes to the nearest free
// cells with a blank between the numbers (a rack is about 7 x 4 cells at 80x24, so some balls
// move a cell or two). A letter (10..15 on small tables) or the cue ball's round glyph never
// reads as part of a number, so they may touch anything. No ball is ever hidden while there is
// room. The cue ball is placed first and always sits exactly. A snooker set has no two-digit
// label ("1" a red, "2".."7" the colours, see ball_label), so its labels may touch anything.

#include <algorithm>
#include <cmath>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/draw.hpp"

namespace termpool::tui {
namespace {

struct Placed {
    int x, y, w;    // cells [x, x + w) of row y
    bool separated; // a number: keeps a blank column from the numbers beside it
};

// How far (cells) a label may move from its ball to find a free spot with gaps.
constexpr int reach_x = 3, reach_y = 2;

// True when a label on [x, x + w) of row y overlaps a placed label, or touches one where both
// are numbers.
bool blocked(const std::vector<Placed>& placed, int x, int y, int w, bool separated) {
    return std::any_of(placed.begin(), placed.end(), [&](const Placed& p) {
        if (p.y != y)
            return false;
        const int gap = separated && p.separated ? 1 : 0;
        return x < p.x + p.w + gap && p.x < x + w + gap;
    });
}

bool on_felt(const Frame& f, int x, int y, int w) {
    return f.on_felt(x, y) && f.on_felt(x + w - 1, y);
}

// The cells for a label of width w centred at fractional cell position (col, row): the
// exact ones when free, else the nearest free spot within `rx` x `ry` cells (screen distance,
// a row being two columns tall).
bool choose_cells(const Frame& f, const std::vector<Placed>& placed, double col, double row, int w,
                  bool separated, int rx, int ry, int& x, int& y) {
    const int x0 = static_cast<int>(std::floor(col - (w - 1) / 2.0));
    const int y0 = static_cast<int>(std::floor(row));
    if (on_felt(f, x0, y0, w) && !blocked(placed, x0, y0, w, separated)) {
        x = x0, y = y0;
        return true;
    }
    double best = 1e300;
    for (int dy = -ry; dy <= ry; ++dy)
        for (int dx = -rx; dx <= rx; ++dx) {
            const int cx = x0 + dx, cy = y0 + dy;
            if (!on_felt(f, cx, cy, w) || blocked(placed, cx, cy, w, separated))
                continue;
            const double ex = cx + w / 2.0 - col, ey = 2 * (cy + 0.5 - row);
            const double d = ex * ex + ey * ey;
            if (d < best)
                best = d, x = cx, y = cy;
        }
    return best < 1e300;
}

void draw_ball(const Frame& f, const Ball& b, bool wide, BallSet set, std::vector<Placed>& placed) {
    double col, row;
    to_cell(f.layout, f.table_width(), b.position, col, row);
    if (!(std::fabs(col) < 1e6) || !(std::fabs(row) < 1e6))
        return;
    const std::string label = ball_label(b.id, f.paint.utf8(), wide, set);
    const int w = static_cast<int>(label.size()) == 2 ? 2 : 1; // "●" is 3 bytes, 1 column
    const bool separated =
        set == BallSet::pool && label.find_first_of("0123456789") != std::string::npos;
    int x = 0, y = 0;
    // With gaps close by; failing that (a crowd against a cushion), touching but never hidden.
    if (!choose_cells(f, placed, col, row, w, separated, reach_x, reach_y, x, y) &&
        !choose_cells(f, placed, col, row, w, false, reach_x, reach_y, x, y))
        return;
    placed.push_back({x, y, w, separated});
    const bool colour = f.paint.colour();
    Style style = ball_style(b.id, colour, set);
    const std::vector<int>& dimmed = f.view.dimmed_balls;
    if (std::find(dimmed.begin(), dimmed.end(), b.id) != dimmed.end()) {
        // A ball the shooter may not hit first: its label faint on the cloth, still readable.
        style = {Colour::dim, Colour::felt, false, false};
    }
    if (b.id == 0) {
        const bool refused = f.view.placing && !f.view.placement_legal;
        style = {refused ? Colour::red : Colour::white, Colour::felt, true};
        // Without colour a refused spot shows as a reversed cue ball.
        style.reverse = refused && !colour;
    }
    if (w == 2) {
        f.paint.put(x, y, label.substr(0, 1), style);
        f.paint.put(x + 1, y, label.substr(1), style);
    } else {
        f.paint.put(x, y, label, style);
    }
}

} // namespace

bool labels_wide(const Frame& f) {
    return wide_labels(f.layout.cells_per_metre, f.view.ball_radius);
}

std::vector<std::pair<int, int>> draw_balls(const Frame& f) {
    std::vector<const Ball*> order;
    for (const Ball& b : f.view.balls)
        if (b.state != MotionState::pocketed)
            order.push_back(&b);
    std::stable_sort(order.begin(), order.end(),
                     [](const Ball* a, const Ball* b) { return a->id < b->id; });
    const bool wide = labels_wide(f);
    const BallSet set = ball_set(f.view);
    std::vector<Placed> placed;
    for (const Ball* b : order)
        draw_ball(f, *b, wide, set, placed);
    std::vector<std::pair<int, int>> cells;
    for (const Placed& p : placed)
        for (int k = 0; k < p.w; ++k)
            cells.emplace_back(p.x + k, p.y);
    return cells;
}

} // namespace termpool::tui
