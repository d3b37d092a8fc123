// The marks of a snooker table: the baulk line, the D behind it and the six colour spots, at
// the same scale as everything else on the table. In UTF-8 the line and the D are Braille dots
// (one dot wide, so that they stay fine at any size); in ASCII the line is '|' and the D is
// drawn with the glyph nearest its direction in each cell it crosses ('-', '/', '(', '\').
// The balls are drawn afterwards and cover them; a spot under a ball is not drawn at all, as
// a dot beside the ball's cell would look like a spot left free.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <termpool/snooker_layout.hpp>
#include <vector>

#include "tui/braille.hpp"
#include "tui/draw.hpp"

namespace termpool::tui {
namespace {

const Style faint{Colour::dim, Colour::felt};

// Angles of the D's arc: the half of the circle behind the baulk line (towards x = 0), from
// its end at the top of the screen (larger y) round to the one at the bottom.
constexpr double arc_from = std::numbers::pi / 2, arc_to = 3 * std::numbers::pi / 2;

void draw_dotted(const Frame& f, const Table& table) {
    DotCanvas canvas(f.felt_w, f.felt_h);
    const double W = table.width;
    // Dots through to_cell, as the aim's: two per column, four per row, the same cells as the
    // balls' labels even on a cell's edge.
    double col, row;
    to_cell(f.layout, W, snooker_d_centre(table), col, row);
    const double cx = (col - f.felt_x) * 2, cy = (row - f.felt_y) * 4;
    const int line_x = static_cast<int>(std::floor(cx));
    for (int y = 0; y < 4 * f.felt_h; ++y)
        canvas.plot(line_x, y, Colour::dim);
    canvas.arc(cx, cy, snooker_d_radius_on(table) * 2 * f.layout.cells_per_metre, arc_from, arc_to,
               Colour::dim);
    for (int r = 0; r < f.felt_h; ++r)
        for (int c = 0; c < f.felt_w; ++c)
            if (const std::uint8_t mask = canvas.mask(c, r))
                f.paint.put(f.felt_x + c, f.felt_y + r, braille_glyph(mask), faint);
}

void draw_plain(const Frame& f, const Table& table) {
    int line_x, line_y;
    if (!f.cell_of(snooker_d_centre(table), line_x, line_y))
        return;
    for (int y = f.felt_y; y < f.felt_y + f.felt_h; ++y)
        if (f.on_felt(line_x, y))
            f.paint.put(line_x, y, "|", faint);
    // Each cell the arc crosses takes the glyph of the point of the arc nearest its centre.
    struct Mark {
        int x, y;
        double distance;
        const char* glyph;
    };
    std::vector<Mark> marks;
    const Vec2 centre = snooker_d_centre(table);
    const double r = snooker_d_radius_on(table);
    const double c = f.layout.cells_per_metre;
    // Eight points per column of arc; a broken scale must not make the loop endless.
    const double samples = std::numbers::pi * r * c * 8;
    if (!(samples < 1e6))
        return;
    const int n = std::max(8, static_cast<int>(std::ceil(samples)));
    static const char* const glyphs[4] = {"-", "/", "(", "\\"};
    for (int k = 0; k <= n; ++k) {
        const double a = arc_from + (arc_to - arc_from) * k / n;
        const Vec2 p = centre + Vec2{std::cos(a), std::sin(a)} * r;
        int x, y;
        if (!f.cell_of(p, x, y) || x == line_x || !f.on_felt(x, y))
            continue;
        double pc, pr;
        to_cell(f.layout, table.width, p, pc, pr);
        // Screen distance, a row being two columns tall.
        const double d = std::hypot(pc - (x + 0.5), 2 * (pr - (y + 0.5)));
        // The tangent is a quarter turn from the radius; its angle on the screen is the
        // table's, as a row holds twice the metres of a column. A '/' joins the corners of a
        // cell twice as tall as wide (63.4 degrees): each glyph takes the angles nearest its own.
        const double tangent = std::fmod(a * 180 / std::numbers::pi + 90, 180.0);
        const int sector = tangent < 31.7    ? 0
                           : tangent < 76.7  ? 1
                           : tangent < 103.3 ? 2
                           : tangent < 148.3 ? 3
                                             : 0;
        bool found = false;
        for (Mark& m : marks)
            if (m.x == x && m.y == y) {
                found = true;
                if (d < m.distance)
                    m.distance = d, m.glyph = glyphs[sector];
            }
        if (!found)
            marks.push_back({x, y, d, glyphs[sector]});
    }
    for (const Mark& m : marks)
        f.paint.put(m.x, m.y, m.glyph, faint);
}

} // namespace

void draw_snooker_marks(const Frame& f) {
    const Table& table = *f.view.table;
    if (f.paint.utf8())
        draw_dotted(f, table);
    else
        draw_plain(f, table);
    for (int colour = snooker_yellow; colour <= snooker_black; ++colour) {
        int x, y;
        const Vec2 spot = snooker_spot(table, colour);
        if (!under_a_ball(f.view, spot) && f.cell_of(spot, x, y) && f.on_felt(x, y))
            f.paint.put(x, y, f.paint.utf8() ? "\u00B7" : "+", faint);
    }
}

} // namespace termpool::tui
