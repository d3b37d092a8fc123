// The status rows under the table while aiming:
//   power [██████▌   ········] 3.4 m/s                 [ shoot ]
//   spin: side +0.2 follow -0.3 elev 30°         distance
// (the spin line shorter where the rows are narrow: "spin +0.2 -0.3 elev 30°"). The bar is a
// scale of speed up to the break's max_break_speed; in any other shot the part past
// max_shot_speed, which it cannot reach, is dotted, so a full-power shot is seen to be slower
// than a full-power break.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tui/aim.hpp"
#include "tui/draw.hpp"
#include <termpool/text_width.hpp>

namespace termpool::tui {
namespace {

// The bar's cells: whole blocks, one partial block in eighths (UTF-8), then blanks up to
// `reach` (a fraction of the bar, as `filled` is), then dots.
void draw_bar(Painter& p, int x, int y, int cells, double filled, double reach, Style fill) {
    const auto fraction = [](double v) { return std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0); };
    const double full = fraction(filled) * cells;
    // A cell the reach ends in is still reachable: the bar's last eighths show there.
    const int reachable = static_cast<int>(std::ceil(fraction(reach) * cells - 1e-9));
    static const char* const eighths[8] = {" ",      "\u258F", "\u258E", "\u258D",
                                           "\u258C", "\u258B", "\u258A", "\u2589"};
    const Style beyond{Colour::dim, Colour::normal};
    for (int i = 0; i < cells; ++i) {
        const double part = std::clamp(full - i, 0.0, 1.0);
        if (i >= reachable && part <= 0) {
            p.put(x + i, y, p.utf8() ? "\u00B7" : ".", beyond);
        } else if (p.utf8()) {
            const int e = static_cast<int>(std::floor(part * 8));
            p.put(x + i, y, e >= 8 ? "\u2588" : eighths[e], fill);
        } else {
            const bool on = part >= 0.5;
            p.put(x + i, y, on ? "#" : "-", on ? fill : Style{});
        }
    }
}

} // namespace

std::string format_offset(double value) {
    if (!std::isfinite(value) || std::fabs(value) < 0.005)
        return "0.0";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%+.2f", value);
    std::string s = buffer;
    if (s.back() == '0')
        s.pop_back();
    return s;
}

Style elevation_style(const View& v, const Painter& p) {
    return v.strike_refused ? Style{Colour::highlight, Colour::normal, true, !p.colour()} : Style{};
}

std::string format_elevation(double deg, bool utf8) {
    const double tenths = std::isfinite(deg) ? std::round(std::clamp(deg, -999.0, 999.0) * 10) : 0;
    char buffer[32];
    if (std::fmod(tenths, 10) == 0)
        std::snprintf(buffer, sizeof buffer, "%.0f", tenths / 10 + 0.0); // + 0.0: no "-0"
    else
        std::snprintf(buffer, sizeof buffer, "%.1f", tenths / 10);
    return std::string("elev ") + buffer + (utf8 ? "\u00B0" : "deg");
}

void draw_status(const Frame& f) {
    const View& v = f.view;
    const Layout& l = f.layout;
    if (!v.aiming || v.placing)
        return;
    Painter& p = f.paint;
    const int x0 = l.status_x, width = l.status_width, y = l.status_y;
    const Style red{Colour::red, Colour::normal, true};

    char speed[32];
    std::snprintf(speed, sizeof speed, " %.1f m/s",
                  std::isfinite(v.speed) ? std::clamp(v.speed, 0.0, 99.9) : 0.0);
    const int button = l.button_width > 0 ? l.button_width + 1 : 0;
    const int fixed = 7 + 1 + static_cast<int>(std::string(speed).size()) + button;
    const int bar = std::min(30, width - fixed);
    if (bar >= 3) {
        int x = x0 + p.text(x0, y, "power [", {});
        const double top = v.is_break ? max_break_speed : max_shot_speed;
        draw_bar(p, x, y, bar, v.speed / max_break_speed, top / max_break_speed, red);
        x += bar;
        x += p.text(x, y, "]", {});
        p.text(x, y, speed, {});
    }
    if (l.button_width > 0)
        p.text(l.button_x, l.button_y, "[ shoot ]",
               {Colour::black, Colour::highlight, true, !p.colour()}, l.button_width);

    // The longest form that fits: the narrowest status rows (28 columns) take the last whole.
    const std::string side = format_offset(v.side), follow = format_offset(v.follow),
                      elev = format_elevation(v.elevation_deg, p.utf8());
    const std::string forms[] = {"spin: side " + side + " follow " + follow + " ",
                                 "side " + side + " follow " + follow + " ",
                                 "spin " + side + " " + follow + " "};
    std::string spin = forms[2];
    for (const std::string& form : forms)
        if (display_width(form + elev) <= width) {
            spin = form;
            break;
        }
    int used = p.text(x0, y + 1, spin, {}, width);
    used += p.text(x0 + used, y + 1, elev, elevation_style(v, p), width - used);
    const std::string mode = v.time_power ? "timed" : "distance";
    const int mode_w = display_width(mode);
    if (used + 2 + mode_w <= width)
        p.text(x0 + width - mode_w, y + 1, mode, {Colour::dim});
}

} // namespace termpool::tui
