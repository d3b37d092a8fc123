// The table: felt, rails with the cushion nose along their inner edge, pockets, head string and
// foot spot (snooker: baulk line, D and spots), and the pocket numbers while a pocket is being
// called.

#include <cmath>
#include <string>

#include "tui/ball_style.hpp"
#include "tui/braille.hpp"
#include "tui/draw.hpp"
#include "tui/pocket_cells.hpp"

namespace termpool::tui {
namespace {

void draw_rails(const Frame& f) {
    Painter& p = f.paint;
    const bool u = p.utf8();
    const Style wood{Colour::normal, Colour::rail};
    const Style nose{Colour::cushion, Colour::rail};
    // In UTF-8 a half block splits each rail cell into wood (outside) and cushion (inside):
    // one row of rail above and below, two columns at the sides, so the rail looks as thick
    // everywhere.
    const int top = f.frame_y, bottom = f.frame_y + f.frame_h - 1;
    for (int x = f.felt_x; x < f.felt_x + f.felt_w; ++x) {
        p.put(x, top, u ? "\u2584" : "=", nose);
        p.put(x, bottom, u ? "\u2580" : "=", nose);
    }
    for (int y = top; y <= bottom; ++y) {
        const bool corner = y == top || y == bottom;
        p.put(f.frame_x, y, " ", wood);
        p.put(f.frame_x + 1, y, corner ? " " : (u ? "\u2590" : "|"), corner ? wood : nose);
        p.put(f.frame_x + f.frame_w - 2, y, corner ? " " : (u ? "\u258C" : "|"),
              corner ? wood : nose);
        p.put(f.frame_x + f.frame_w - 1, y, " ", wood);
    }
}

void draw_pockets(const Frame& f) {
    const Style hole{Colour::normal, Colour::pocket};
    for (int n = 1; n <= 6; ++n)
        for (const auto& [x, y] : pocket_cells(*f.view.table, f.layout, n).cells)
            f.paint.put(x, y, " ", hole);
}

// A faint dotted line on the head string and a dot on the foot spot, unless a ball covers it
// (the dot beside a racked apex ball would look like the spot missed); on the snooker table its
// own marks instead, and the head string only while pool balls are played on it (their ball in
// hand goes behind it). The pink's spot is the foot spot.
void draw_markings(const Frame& f) {
    const Table& table = *f.view.table;
    const bool snooker = table.size == TableSize::snooker;
    if (snooker)
        draw_snooker_marks(f);
    if (snooker && ball_set(f.view) == BallSet::snooker)
        return;
    const Style faint{Colour::dim, Colour::felt};
    double col, row;
    to_cell(f.layout, table.width, {table.head_string_x(), 0}, col, row);
    const int x = static_cast<int>(std::floor(col));
    if (f.on_felt(x, f.felt_y)) {
        // Two dots in the Braille column nearer the line: a light dotted line down the table.
        const bool right_half = col - x >= 0.5;
        const std::string glyph =
            f.paint.utf8() ? braille_glyph(right_half ? 0x28 : 0x05) : std::string(":");
        for (int y = f.felt_y; y < f.felt_y + f.felt_h; ++y)
            f.paint.put(x, y, glyph, faint);
    }
    int fx, fy;
    if (!snooker && !under_a_ball(f.view, table.foot_spot()) &&
        f.cell_of(table.foot_spot(), fx, fy) && f.on_felt(fx, fy))
        f.paint.put(fx, fy, f.paint.utf8() ? "\u00B7" : ".", faint);
}

} // namespace

void draw_table(const Frame& f) {
    f.paint.fill(f.felt_x, f.felt_y, f.felt_w, f.felt_h, f.felt());
    draw_rails(f);
    draw_pockets(f);
    draw_markings(f);
}

void draw_pocket_labels(const Frame& f) {
    const int called = f.view.called_pocket;
    if (called < 1 || called > 6)
        return;
    for (int n = 1; n <= 6; ++n) {
        const PocketCells cells = pocket_cells(*f.view.table, f.layout, n);
        const bool chosen = n == called;
        if (chosen) {
            Style lit{Colour::normal, Colour::highlight};
            lit.reverse = !f.paint.colour(); // without colour, the called pocket is reversed
            for (const auto& [x, y] : cells.cells)
                f.paint.put(x, y, " ", lit);
        }
        Style label = chosen ? Style{Colour::black, Colour::highlight, true, !f.paint.colour()}
                             : Style{Colour::dim, Colour::pocket};
        const std::string digit(1, static_cast<char>('0' + n));
        f.paint.put(cells.label_x, cells.label_y, digit, label);
    }
}

} // namespace termpool::tui
