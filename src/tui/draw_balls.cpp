// The balls: one glyph each, in the cell that holds its centre. On a small table several balls
// can share a cell (a rack is about 7 x 4 cells at 80x24); a ball whose cell is taken goes to
// the free neighbouring cell nearest its centre instead, so that no ball is ever hidden. The
// cue ball is placed first and always sits exactly.

#include <algorithm>
#include <cmath>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/draw.hpp"

namespace termpool::tui {
namespace {

struct Placed {
    int x, y;
};

bool taken(const std::vector<Placed>& placed, int x, int y) {
    return std::any_of(placed.begin(), placed.end(),
                       [&](const Placed& p) { return p.x == x && p.y == y; });
}

// The cell for a ball centred at fractional cell position (col, row).
bool choose_cell(const Frame& f, const std::vector<Placed>& placed, double col, double row, int& x,
                 int& y) {
    x = static_cast<int>(std::floor(col));
    y = static_cast<int>(std::floor(row));
    if (!taken(placed, x, y))
        return f.on_felt(x, y);
    double best = 1e300;
    int bx = 0, by = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int cx = x + dx, cy = y + dy;
            if (!f.on_felt(cx, cy) || taken(placed, cx, cy))
                continue;
            // Distance on screen, a row being two columns tall.
            const double ex = cx + 0.5 - col, ey = 2 * (cy + 0.5 - row);
            const double d = ex * ex + ey * ey;
            if (d < best)
                best = d, bx = cx, by = cy;
        }
    if (best == 1e300)
        return false;
    x = bx, y = by;
    return true;
}

void draw_ball(const Frame& f, const Ball& b, std::vector<Placed>& placed) {
    double col, row;
    to_cell(f.layout, f.table_width(), b.position, col, row);
    if (!(std::fabs(col) < 1e6) || !(std::fabs(row) < 1e6))
        return;
    int x, y;
    if (!choose_cell(f, placed, col, row, x, y))
        return;
    placed.push_back({x, y});
    const bool colour = f.paint.colour();
    Style style = ball_style(b.id, colour);
    if (b.id == 0) {
        const bool refused = f.view.placing && !f.view.placement_legal;
        style = {refused ? Colour::red : Colour::white, Colour::felt, true};
        // Without colour a refused spot shows as a reversed cue ball.
        style.reverse = refused && !colour;
    }
    f.paint.put(x, y, ball_glyph(b.id, f.paint.utf8()), style);
}

} // namespace

void draw_balls(const Frame& f) {
    std::vector<const Ball*> order;
    for (const Ball& b : f.view.balls)
        if (b.state != MotionState::pocketed)
            order.push_back(&b);
    std::stable_sort(order.begin(), order.end(),
                     [](const Ball* a, const Ball* b) { return a->id < b->id; });
    std::vector<Placed> placed;
    for (const Ball* b : order)
        draw_ball(f, *b, placed);
}

} // namespace termpool::tui
