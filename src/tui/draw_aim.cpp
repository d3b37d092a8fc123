// The aim: the cue behind the cue ball, the aim line or the aiming aid (path to the ghost ball,
// ghost ball, object ball and cue ball directions) in Braille dots, and the pointer's marker.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "tui/braille.hpp"
#include "tui/draw.hpp"

namespace termpool::tui {
namespace {

const Ball* find_cue_ball(const View& view) {
    for (const Ball& b : view.balls)
        if (b.id == 0 && b.state != MotionState::pocketed)
            return &b;
    return nullptr;
}

// Table point to canvas dots: two dots per column, four per row (2 cells_per_metre dots per
// metre both ways). Going through to_cell keeps dots and ball glyphs in the same cells even
// for points exactly on a cell edge, such as the head spot.
struct Dots {
    const Frame& f;
    double x(Vec2 p) const {
        double col, row;
        to_cell(f.layout, f.table_width(), p, col, row);
        return (col - f.felt_x) * 2;
    }
    double y(Vec2 p) const {
        double col, row;
        to_cell(f.layout, f.table_width(), p, col, row);
        return (row - f.felt_y) * 4;
    }
    double per_metre() const { return 2 * f.layout.cells_per_metre; }
};

void polyline(DotCanvas& canvas, const Dots& d, const std::vector<Vec2>& points, Colour role,
              bool dashed) {
    for (std::size_t i = 1; i < points.size(); ++i)
        canvas.line(d.x(points[i - 1]), d.y(points[i - 1]), d.x(points[i]), d.y(points[i]), role,
                    dashed);
}

// The lines on the felt: dots in UTF-8, '.' in ASCII, never on the rails.
void draw_lines(const Frame& f, const Ball& cue) {
    const View& v = f.view;
    DotCanvas canvas(f.felt_w, f.felt_h);
    const Dots d{f};
    const double R = v.ball_radius;
    const bool aid = v.show_aid && v.cue_path.size() >= 2;
    if (aid) {
        // The cue ball's own path first, so that where paths cross it keeps its colour.
        polyline(canvas, d, v.cue_path, Colour::aim, false);
        polyline(canvas, d, v.object_path, Colour::ghost, true);
        polyline(canvas, d, v.deflect_path, Colour::ghost, true);
        if (v.has_ghost && f.paint.utf8() && R * d.per_metre() >= 2)
            canvas.circle(d.x(v.ghost), d.y(v.ghost), R * d.per_metre(), Colour::ghost);
    } else {
        // A plain aim line across the table: the clipping stops it at the felt's edge.
        const double a = v.aim_deg * std::numbers::pi / 180;
        const double reach = 2 * (v.table->length + v.table->width);
        const Vec2 end = cue.position + Vec2{std::cos(a), std::sin(a)} * reach;
        canvas.line(d.x(cue.position), d.y(cue.position), d.x(end), d.y(end), Colour::aim);
    }
    for (int row = 0; row < f.felt_h; ++row)
        for (int col = 0; col < f.felt_w; ++col) {
            const std::uint8_t mask = canvas.mask(col, row);
            if (mask == 0)
                continue;
            const std::string glyph = f.paint.utf8() ? braille_glyph(mask) : std::string(".");
            f.paint.put(f.felt_x + col, f.felt_y + row, glyph,
                        {canvas.role(col, row), Colour::felt});
        }
    // A ghost ball smaller than a Braille circle can show: one glyph.
    int gx, gy;
    if (aid && v.has_ghost && (!f.paint.utf8() || R * d.per_metre() < 2) &&
        f.cell_of(v.ghost, gx, gy) && f.on_felt(gx, gy))
        f.paint.put(gx, gy, f.paint.utf8() ? "\u25CC" : "O", {Colour::ghost, Colour::felt});
}

// The cue: a run of cells behind the cue ball, opposite the aim, drawn with the line glyph
// nearest its direction. Its angle on screen is the table angle: a row holds twice the metres
// of a column and is twice as tall as a column is wide, so screen distance is proportional to
// table distance both ways.
void draw_cue(const Frame& f, const Ball& cue) {
    const View& v = f.view;
    const double c = f.layout.cells_per_metre;
    const double a = v.aim_deg * std::numbers::pi / 180;
    const Vec2 back{-std::cos(a), -std::sin(a)};
    double deg = std::fmod(v.aim_deg, 180.0);
    if (deg < 0)
        deg += 180;
    const int sector = static_cast<int>(std::floor((deg + 22.5) / 45)) % 4;
    static const char* const ascii[4] = {"-", "/", "|", "\\"};
    static const char* const utf8[4] = {"\u2500", "\u2571", "\u2502", "\u2572"};
    const std::string glyph = f.paint.utf8() ? utf8[sector] : ascii[sector];

    int cue_x, cue_y;
    if (!f.cell_of(cue.position, cue_x, cue_y))
        return;
    const double start = v.ball_radius + 0.75 / c;
    const double length = std::max(8.0 / c, 0.35);
    int last_x = cue_x, last_y = cue_y;
    // Quarter-cell steps, counted so that a huge or broken radius cannot stall the loop.
    const double step = 0.25 / c;
    const int steps = static_cast<int>(length / step);
    for (int k = 0; k <= steps; ++k) {
        const double s = start + k * step;
        int x, y;
        if (!f.cell_of(cue.position + back * s, x, y))
            return;
        if ((x == last_x && y == last_y) || !f.on_frame(x, y))
            continue;
        last_x = x, last_y = y;
        const Cell* under = f.paint.cell(x, y);
        if (!under)
            continue;
        Style style = under->style;
        style.fg = Colour::aim;
        style.bold = true;
        style.reverse = false;
        f.paint.put(x, y, glyph, style);
    }
}

} // namespace

void draw_aim(const Frame& f) {
    const View& v = f.view;
    const Ball* cue = find_cue_ball(v);
    if (v.aiming && cue && !v.placing) {
        draw_lines(f, *cue);
        draw_cue(f, *cue);
    }
    int mx, my;
    if (v.show_marker && f.cell_of(v.marker, mx, my) && f.on_frame(mx, my)) {
        const Cell* under = f.paint.cell(mx, my);
        f.paint.put(mx, my, "+",
                    {Colour::highlight, under ? under->style.bg : Colour::normal, true});
    }
}

} // namespace termpool::tui
