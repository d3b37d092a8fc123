// The panel: the game, both players (the one to shoot marked) with their groups and pocketed
// balls, the message, the spin diagram and a legend of the balls on the table. Beside the
// table it is a column; below it (narrow terminals) the players, the message and the spin
// diagram sit side by side.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tui/aim.hpp"
#include "tui/ball_style.hpp"
#include "tui/draw.hpp"
#include "tui/text_width.hpp"

namespace termpool::tui {
namespace {

// "solids 1 3 4", "open table", "pocketed 1 2" (9-ball has no groups).
std::string player_detail(const View& v, int player) {
    std::string s;
    const bool nine = v.game == GameType::nine_ball;
    if (!nine) {
        const Group g = v.groups[player - 1];
        s = g == Group::solids ? "solids" : g == Group::stripes ? "stripes" : "open table";
    }
    const std::vector<int>& balls = v.pocketed_by[player - 1];
    if (nine && !balls.empty())
        s = "pocketed";
    for (const int id : balls)
        s += " " + std::to_string(id);
    return s;
}

// Marker and name on one line; returns the columns used.
int draw_name(const Frame& f, int x, int y, int width, int player) {
    const View& v = f.view;
    const bool shooting = v.shooter == player;
    const Style mark{Colour::highlight, Colour::normal, true};
    int used = 0;
    if (shooting)
        used += f.paint.text(x, y, f.paint.utf8() ? "\u25B6 " : "> ", mark, width);
    else
        used += f.paint.text(x, y, "  ", {}, width);
    const std::string name = truncate_to_width(v.names[player - 1], 20);
    used += f.paint.text(x + used, y, name, shooting ? mark : Style{}, width - used);
    return used;
}

// The numbers of the balls on the table, each styled as on the table, after an "on table"
// label when there is room for it. Drawn only when it fits whole in `max_rows`: a cut legend
// would say balls are gone. Returns the rows used.
int draw_legend(const Frame& f, int x, int y, int width, int max_rows) {
    std::vector<int> ids;
    for (const Ball& b : f.view.balls)
        if (b.id > 0 && b.state != MotionState::pocketed)
            ids.push_back(b.id);
    std::sort(ids.begin(), ids.end());
    if (ids.empty() || max_rows <= 0 || width <= 2)
        return 0;
    const std::string label = "on table";
    // Lays the numbers out from column `start`; returns the rows needed, drawing if asked.
    auto lay_out = [&](int start, bool draw) {
        int row = 0, col = start;
        for (const int id : ids) {
            const std::string n = std::to_string(id);
            const int w = static_cast<int>(n.size());
            if (col > 0 && col + w > width)
                ++row, col = 0;
            if (draw)
                f.paint.text(x + col, y + row, n, ball_style(id, f.paint.colour()));
            col += w + 1;
        }
        return row + 1;
    };
    const int with_label = static_cast<int>(label.size()) + 1;
    if (lay_out(with_label, false) <= max_rows) {
        f.paint.text(x, y, label, {Colour::dim}, width);
        return lay_out(with_label, true);
    }
    if (lay_out(0, false) <= max_rows)
        return lay_out(0, true);
    return 0;
}

// The cue ball's face with a '+' where the tip will strike; the outermost cells are the
// +-0.5 R limit. Corners are left out so that the face reads as round.
void draw_spin_face(const Frame& f, int x, int y, int w, int h) {
    const View& v = f.view;
    Painter& p = f.paint;
    const bool colour = p.colour();
    const Style face{Colour::dim, Colour::white};
    const std::string dot = colour ? " " : (p.utf8() ? "\u00B7" : ".");
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const bool corner = (r == 0 || r == h - 1) && (c == 0 || c == w - 1);
            if (!corner)
                p.put(x + c, y + r, dot, face);
        }
    const int cx = x + w / 2, cy = y + h / 2;
    p.put(cx, cy, p.utf8() ? "\u00B7" : ".", face);
    const auto offset = [](double value, int half) {
        const double u = std::isfinite(value) ? std::clamp(value / max_spin, -1.0, 1.0) : 0.0;
        return static_cast<int>(std::lround(u * half));
    };
    const int mx = cx + offset(v.side, w / 2), my = cy - offset(v.follow, h / 2);
    p.put(mx, my, "+", {Colour::red, Colour::white, true, !colour});
}

void draw_side_panel(const Frame& f) {
    const View& v = f.view;
    const Layout& l = f.layout;
    Painter& p = f.paint;
    const int x = l.panel_x + 1, width = l.panel_width - 1;
    int y = l.panel_y;
    const int end = l.panel_y + l.panel_height;
    auto room = [&](int rows) { return y + rows <= end; };

    if (room(1))
        p.text(x, y++, game_title(v.game), {Colour::normal, Colour::normal, true}, width);
    ++y;
    for (int player = 1; player <= 2 && room(2); ++player) {
        draw_name(f, x, y++, width, player);
        p.text(x + 2, y++, player_detail(v, player), {Colour::dim}, width - 2);
    }
    ++y;
    // The message matters most after the players; leave the hint line free below it.
    if (!v.message.empty()) {
        for (const std::string& line : wrap_to_width(v.message, width)) {
            if (!room(2))
                break;
            p.text(x, y++, line, {}, width);
        }
        ++y;
    }
    if (v.aiming && !v.placing) {
        const int h = room(6) && end - y >= 12 ? 5 : 3, w = h == 5 ? 9 : 5;
        if (room(h + 1)) {
            draw_spin_face(f, x + 1, y, w, h);
            p.text(x + w + 3, y + h / 2 - 1, "spin", {Colour::dim}, width - w - 3);
            p.text(x + w + 3, y + h / 2, "side " + format_offset(v.side), {}, width - w - 3);
            p.text(x + w + 3, y + h / 2 + 1, "follow " + format_offset(v.follow), {},
                   width - w - 3);
            y += h + 1;
        }
    }
    // The legend keeps the last row free for the hint.
    if (room(2))
        y += draw_legend(f, x, y, width, end - 1 - y);
    if (y <= end - 1)
        p.text(x, end - 1, "? help  q quit", {Colour::dim}, width);
}

void draw_below_panel(const Frame& f) {
    const View& v = f.view;
    const Layout& l = f.layout;
    Painter& p = f.paint;
    const int end = l.panel_y + l.panel_height;
    const bool face = v.aiming && !v.placing && l.panel_width >= 40 && l.panel_height >= 3;
    const int face_w = 5, face_h = 3;
    const int right = l.panel_x + l.panel_width - (face ? face_w + 1 : 0);
    const int x = l.panel_x, pw = std::min(36, right - x);
    const int mid_x = x + pw + 1, mid_w = right - mid_x - 1;
    const bool message_beside = mid_w >= 16;
    const bool has_message = !v.message.empty();

    int y = l.panel_y;
    if (y < end && (message_beside || !has_message || l.panel_height >= 4))
        p.text(x, y++, game_title(v.game), {Colour::normal, Colour::normal, true}, pw);
    for (int player = 1; player <= 2 && y < end; ++player) {
        const int used = draw_name(f, x, y, pw, player);
        p.text(x + used + 2, y++, player_detail(v, player), {Colour::dim}, pw - used - 2);
    }
    if (has_message) {
        const bool beside = message_beside;
        int my = beside ? l.panel_y : y;
        const int mx = beside ? mid_x : x, mw = beside ? mid_w : right - x;
        for (const std::string& line : wrap_to_width(v.message, mw)) {
            if (my >= end)
                break;
            p.text(mx, my++, line, {}, mw);
        }
        if (!beside)
            y = my;
    }
    if (y < end)
        y += draw_legend(f, x, y, pw, end - y);
    if (y < end)
        p.text(x, end - 1, "? help  q quit", {Colour::dim}, pw);
    if (face)
        draw_spin_face(f, right + 1, l.panel_y, face_w, face_h);
}

} // namespace

void draw_panel(const Frame& f) {
    if (f.layout.panel_width <= 0 || f.layout.panel_height <= 0)
        return;
    if (f.layout.panel_below)
        draw_below_panel(f);
    else
        draw_side_panel(f);
}

} // namespace termpool::tui
