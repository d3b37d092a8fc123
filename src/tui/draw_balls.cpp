// The balls: each on the cell that holds its centre, never moved to make room, so that a rack
// looks like a rack and a ball's cell says where it is. Where labels would clash the label
// gives way, not the ball:
//  - two centres in one cell: the ball drawn first keeps the cell and covers the other;
//  - a number beside another number on a row would read as one ("1" "5" as 15): the later
//    ball shows a plain mark (ball_mark) in its own style instead, which the legend's styles
//    tell apart;
//  - a two-cell number ("12" on a big table) takes its centre cell and the neighbour nearer
//    its centre, else the other neighbour, else it shrinks to the mark.
// A letter (10..15 on small tables), the cue ball's glyph and snooker's values (no two-digit
// one, see ball_label) never read as part of a number, so they may touch anything. The order
// decides who gives way: the cue ball first, then the ball the game turns on (the 8, 9 or 10;
// snooker's colours), then the rest by number, lowest (the ball on in 9- and 10-ball) first.

#include <algorithm>
#include <cmath>
#include <termpool/game_registry.hpp>
#include <termpool/snooker_layout.hpp>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/draw.hpp"

namespace termpool::tui {
namespace {

struct Placed {
    int x, y, w; // cells [x, x + w) of row y
    bool number; // a pool number: no other number may touch it on its row
};

bool taken(const std::vector<Placed>& placed, int x, int y, int w) {
    return std::any_of(placed.begin(), placed.end(),
                       [&](const Placed& p) { return p.y == y && x < p.x + p.w && p.x < x + w; });
}

// True when a number on [x, x + w) of row y would touch a placed number.
bool touches_number(const std::vector<Placed>& placed, int x, int y, int w) {
    return std::any_of(placed.begin(), placed.end(), [&](const Placed& p) {
        return p.number && p.y == y && x <= p.x + p.w && p.x <= x + w;
    });
}

bool on_frame(const Frame& f, int x, int y, int w) {
    return f.on_frame(x, y) && f.on_frame(x + w - 1, y);
}

// Lower draws first (see the file comment).
int draw_rank(const Ball& b, const View& v, BallSet set) {
    if (b.id == 0)
        return 0;
    if (set == BallSet::snooker)
        return (is_snooker_colour(b.id) ? 100 : 200) + b.id;
    // The game's deciding ball (its row's, 0 for none) is drawn right after the cue ball.
    return b.id == game_row(v.game).deciding_ball ? 1 : 100 + b.id;
}

Style style_of(const Frame& f, const Ball& b, BallSet set) {
    const bool colour = f.paint.colour();
    const std::vector<int>& dimmed = f.view.dimmed_balls;
    if (b.id != 0 && std::find(dimmed.begin(), dimmed.end(), b.id) != dimmed.end())
        // A ball the shooter may not hit first: its label faint on the cloth, still readable.
        return {Colour::dim, Colour::felt, false, false};
    if (b.id != 0)
        return ball_style(b.id, colour, set);
    const bool refused = f.view.placing && !f.view.placement_legal;
    Style style{refused ? Colour::red : Colour::white, Colour::felt, true};
    // Without colour a refused spot shows as a reversed cue ball.
    style.reverse = refused && !colour;
    return style;
}

void draw_ball(const Frame& f, const Ball& b, bool wide, BallSet set, std::vector<Placed>& placed) {
    double col, row;
    to_cell(f.layout, f.table_width(), b.position, col, row);
    if (!(std::fabs(col) < 1e6) || !(std::fabs(row) < 1e6))
        return;
    const int x = static_cast<int>(std::floor(col)), y = static_cast<int>(std::floor(row));
    // Off the cloth and rails (a ball in flight past a pocket): not drawn. On a cell already
    // drawn: covered by that ball.
    if (!f.on_frame(x, y) || taken(placed, x, y, 1))
        return;
    std::string label = ball_label(b.id, f.paint.utf8(), wide, set);
    const bool number = set == BallSet::pool && b.id >= 1 && b.id <= 15 &&
                        label.find_first_not_of("0123456789") == std::string::npos;
    const Style style = style_of(f, b, set);
    if (number && label.size() == 2) {
        // The pair of cells centred nearer the ball's centre first.
        const int first = col - x < 0.5 ? x - 1 : x;
        for (const int left : {first, 2 * x - 1 - first})
            if (on_frame(f, left, y, 2) && !taken(placed, left, y, 2) &&
                !touches_number(placed, left, y, 2)) {
                placed.push_back({left, y, 2, true});
                f.paint.put(left, y, label.substr(0, 1), style);
                f.paint.put(left + 1, y, label.substr(1), style);
                return;
            }
    } else if (!number || !touches_number(placed, x, y, 1)) {
        placed.push_back({x, y, 1, number});
        f.paint.put(x, y, label, style);
        return;
    }
    placed.push_back({x, y, 1, false});
    f.paint.put(x, y, ball_mark(f.paint.utf8()), style);
}

} // namespace

bool labels_wide(const Frame& f) {
    return wide_labels(f.layout.cells_per_metre, f.view.ball_radius);
}

std::vector<std::pair<int, int>> draw_balls(const Frame& f) {
    const BallSet set = ball_set(f.view);
    std::vector<const Ball*> order;
    for (const Ball& b : f.view.balls)
        if (b.state != MotionState::pocketed)
            order.push_back(&b);
    std::stable_sort(order.begin(), order.end(), [&](const Ball* a, const Ball* b) {
        return draw_rank(*a, f.view, set) < draw_rank(*b, f.view, set);
    });
    const bool wide = labels_wide(f);
    std::vector<Placed> placed;
    for (const Ball* b : order)
        draw_ball(f, *b, wide, set, placed);
    std::vector<std::pair<int, int>> cells;
    for (const Placed& p : placed)
        for (int k = 0; k < p.w; ++k)
            cells.emplace_back(p.x + k, p.y);
    return cells;
}

bool under_a_ball(const View& v, Vec2 point) {
    return std::any_of(v.balls.begin(), v.balls.end(), [&](const Ball& b) {
        return b.state != MotionState::pocketed && length(b.position - point) < v.ball_radius;
    });
}

} // namespace termpool::tui
