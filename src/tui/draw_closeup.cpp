// The close-up (z): an inset in a corner of the table with the contact the aid predicts drawn
// about ten times larger than the table, so that a thin cut can be judged. Centred on the
// contact point (marked '+'): the cue ball at contact and the object ball as circles of
// Braille dots (in ASCII '.' cells) with their labels at their centres, the cue ball's line in,
// the object ball's line out, dashed. The border names the cut angle (between the cue ball's
// line and the line of centres) and the aim to a hundredth of a degree, so that every fine aim
// step shows, though at this scale a 0.01-degree turn moves the ghost ball by a fraction of a
// dot.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/braille.hpp"
#include "tui/draw.hpp"
#include <termpool/text_width.hpp>

namespace termpool::tui {
namespace {

constexpr double magnification = 10; // the balls' size over their size on the table

// "23.47°" ("23.47deg" in ASCII).
std::string degrees(double deg, bool utf8) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", std::isfinite(deg) ? deg : 0.0);
    return buffer + std::string(utf8 ? "\u00B0" : "deg");
}

bool inside(const CloseUpBox& box, int x, int y) {
    return x >= box.x && y >= box.y && x < box.x + box.w && y < box.y + box.h;
}

// The border with `title` on its top edge and `foot` on its bottom edge, and the inside
// cleared to felt.
void draw_border(const Frame& f, const CloseUpBox& box, const std::string& title,
                 const std::string& foot) {
    Painter& p = f.paint;
    const bool u = p.utf8();
    const Style edge{Colour::white, Colour::felt};
    p.fill(box.x + 1, box.y + 1, box.w - 2, box.h - 2, f.felt());
    for (int x = box.x + 1; x < box.x + box.w - 1; ++x) {
        p.put(x, box.y, u ? "\u2500" : "-", edge);
        p.put(x, box.y + box.h - 1, u ? "\u2500" : "-", edge);
    }
    for (int y = box.y + 1; y < box.y + box.h - 1; ++y) {
        p.put(box.x, y, u ? "\u2502" : "|", edge);
        p.put(box.x + box.w - 1, y, u ? "\u2502" : "|", edge);
    }
    p.put(box.x, box.y, u ? "\u250C" : "+", edge);
    p.put(box.x + box.w - 1, box.y, u ? "\u2510" : "+", edge);
    p.put(box.x, box.y + box.h - 1, u ? "\u2514" : "+", edge);
    p.put(box.x + box.w - 1, box.y + box.h - 1, u ? "\u2518" : "+", edge);
    const int room = box.w - 4;
    if (display_width(title) <= room)
        p.text(box.x + 2, box.y, title, edge);
    if (display_width(foot) <= room)
        p.text(box.x + box.w - 2 - display_width(foot), box.y + box.h - 1, foot, edge);
}

} // namespace

CloseUpBox close_up_box(const Frame& f) {
    const CloseUp& c = f.view.close_up;
    // About two fifths of the felt's width and half its height, within reason.
    const int w = std::clamp(f.felt_w * 2 / 5, 16, 48) + 2;
    const int lowest = 5 + 2, tallest = std::min(std::clamp(f.felt_h / 2, 5, 16) + 2, f.felt_h);
    if (w > f.felt_w || lowest > f.felt_h)
        return {};
    // Clear of the contact, the object ball and the cue ball where they lie on the table.
    int gx = f.felt_x + f.felt_w / 2, gy = f.felt_y + f.felt_h / 2;
    std::vector<Vec2> keep_points;
    if (c.ball >= 0)
        keep_points = {(c.cue + c.object) * 0.5, c.object};
    for (const Ball& b : f.view.balls)
        if (b.id == 0 && b.state != MotionState::pocketed)
            keep_points.push_back(b.position);
    std::vector<std::pair<int, int>> keep;
    for (const Vec2 p : keep_points) {
        int x, y;
        if (f.cell_of(p, x, y))
            keep.emplace_back(x, y);
    }
    if (c.ball >= 0 && !keep.empty())
        gx = keep.front().first, gy = keep.front().second;
    // Every ball on the table must stay in sight too: the corner whose box covers none of the
    // points above and the fewest balls (none at best, shrinking the box for it), the farthest
    // from the contact among equals; else the tallest box in the farthest corner.
    std::vector<std::pair<int, int>> ball_cells;
    for (const Ball& b : f.view.balls) {
        int x, y;
        if (b.state != MotionState::pocketed && f.cell_of(b.position, x, y))
            ball_cells.emplace_back(x, y);
    }
    struct Pick {
        CloseUpBox box;
        long covered = 0;
        double distance = -1;
    };
    CloseUpBox fallback;
    std::optional<Pick> fewest;
    for (int h = tallest; h >= lowest; --h) {
        std::optional<Pick> best;
        double far_distance = -1;
        for (const int right : {0, 1})
            for (const int bottom : {0, 1}) {
                const CloseUpBox at{right ? f.felt_x + f.felt_w - w : f.felt_x,
                                    bottom ? f.felt_y + f.felt_h - h : f.felt_y, w, h};
                const double distance =
                    std::hypot(at.x + at.w / 2.0 - gx, 2 * (at.y + at.h / 2.0 - gy));
                if (h == tallest && distance > far_distance)
                    far_distance = distance, fallback = at;
                const auto under = [&](const auto& k) { return inside(at, k.first, k.second); };
                if (std::any_of(keep.begin(), keep.end(), under))
                    continue;
                const long covered = std::count_if(ball_cells.begin(), ball_cells.end(), under);
                if (!best || covered < best->covered ||
                    (covered == best->covered && distance > best->distance))
                    best = Pick{at, covered, distance};
            }
        if (best && best->covered == 0)
            return best->box;
        if (best && (!fewest || best->covered < fewest->covered))
            fewest = best;
    }
    if (fewest)
        return fewest->box;
    return fallback;
}

double close_up_cut_deg(const CloseUp& c) {
    const Vec2 centres = c.object - c.cue;
    if (!(length(centres) > 0) || !(length(c.heading) > 0))
        return 0;
    const double cosine = std::clamp(dot(normalized(centres), normalized(c.heading)), -1.0, 1.0);
    return std::acos(cosine) * 180 / std::numbers::pi;
}

void draw_close_up(const Frame& f) {
    const View& v = f.view;
    const CloseUp& c = v.close_up;
    if (!c.shown || !v.aiming || v.placing || !v.table)
        return;
    const CloseUpBox box = close_up_box(f);
    if (box.w == 0)
        return;
    const bool u = f.paint.utf8();
    const std::string foot = " aim " + degrees(v.aim_deg, u) + " ";
    if (c.ball < 0) {
        draw_border(f, box, " close-up ", foot);
        const std::string none = "no ball in line";
        if (display_width(none) <= box.w - 2)
            f.paint.text(box.x + (box.w - display_width(none)) / 2, box.y + box.h / 2, none,
                         {Colour::dim, Colour::felt});
        return;
    }
    const std::string cut = "cut " + degrees(close_up_cut_deg(c), u);
    const std::string title = " close-up  " + cut + " ";
    draw_border(f, box, display_width(title) <= box.w - 4 ? title : " " + cut + " ", foot);

    // Dots of the inside, two a column and four a row, square; the contact point in the
    // middle; the balls magnified, but never so far that a centre leaves the inset.
    const int cols = box.w - 2, rows = box.h - 2;
    DotCanvas canvas(cols, rows);
    const double R = v.ball_radius;
    const double table_radius = R * 2 * f.layout.cells_per_metre; // dots, on the table
    const double radius = std::min(magnification * table_radius, std::min(cols, 2 * rows) - 2.0);
    if (!(radius > 1) || !(R > 0))
        return;
    const double scale = radius / R; // dots per metre
    const Vec2 contact = (c.cue + c.object) * 0.5;
    const auto dx = [&](Vec2 p) { return cols + (p.x - contact.x) * scale; };
    const auto dy = [&](Vec2 p) { return 2.0 * rows - (p.y - contact.y) * scale; };
    const double far = 4.0 * (cols + rows); // past every edge: the canvas clips
    canvas.circle(dx(c.cue), dy(c.cue), radius, Colour::white);
    const BallSet set = ball_set(v);
    canvas.circle(dx(c.object), dy(c.object), radius, ball_colour(c.ball, set));
    const Vec2 from = c.cue - c.heading * (far / scale);
    canvas.line(dx(from), dy(from), dx(c.cue), dy(c.cue), Colour::aim);
    if (length(c.departure) > 0) {
        const Vec2 to = c.object + c.departure * (far / scale);
        canvas.line(dx(c.object), dy(c.object), dx(to), dy(to), Colour::ghost, true);
    }
    for (int row = 0; row < rows; ++row)
        for (int col = 0; col < cols; ++col)
            if (const std::uint8_t mask = canvas.mask(col, row))
                f.paint.put(box.x + 1 + col, box.y + 1 + row, u ? braille_glyph(mask) : ".",
                            {canvas.role(col, row), Colour::felt});

    // The labels at the centres, the contact point over all.
    const auto cell = [&](Vec2 p) {
        return std::pair{box.x + 1 + static_cast<int>(std::floor(dx(p) / 2)),
                         box.y + 1 + static_cast<int>(std::floor(dy(p) / 4))};
    };
    const auto [cx, cy] = cell(c.cue);
    f.paint.put(cx, cy, ball_label(0, u, false, set), {Colour::white, Colour::felt, true});
    // On this scale a ball is always wide enough for "10".."15".
    const auto [ox, oy] = cell(c.object);
    const std::string label = ball_label(c.ball, u, true, set);
    const Style style = ball_style(c.ball, f.paint.colour(), set);
    if (label.size() == 2) {
        f.paint.put(ox, oy, label.substr(0, 1), style);
        f.paint.put(ox + 1, oy, label.substr(1), style);
    } else {
        f.paint.put(ox, oy, label, style);
    }
    const auto [kx, ky] = cell(contact);
    f.paint.put(kx, ky, "+", {Colour::highlight, Colour::felt, true, !f.paint.colour()});
}

} // namespace termpool::tui
