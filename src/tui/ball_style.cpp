// Ball colours, glyphs and styles.

#include "tui/ball_style.hpp"

#include <algorithm>
#include <cmath>
#include <termpool/snooker_layout.hpp>

namespace termpool::tui {

BallSet ball_set(const View& v) {
    const bool colours = std::any_of(v.balls.begin(), v.balls.end(),
                                     [](const Ball& b) { return is_snooker_colour(b.id); });
    return colours ? BallSet::snooker : BallSet::pool;
}

Colour ball_colour(int id, BallSet set) {
    if (id <= 0)
        return Colour::white;
    if (set == BallSet::snooker) {
        if (is_snooker_red(id))
            return Colour::red;
        constexpr Colour colours[6] = {Colour::yellow, Colour::green, Colour::brown,
                                       Colour::blue,   Colour::pink,  Colour::black};
        return is_snooker_colour(id) ? colours[id - snooker_yellow] : Colour::white;
    }
    constexpr Colour colours[8] = {Colour::yellow, Colour::blue,  Colour::red,    Colour::purple,
                                   Colour::orange, Colour::green, Colour::maroon, Colour::black};
    return colours[(id - 1) % 8];
}

bool is_stripe(int id) {
    return id >= 9 && id <= 15;
}

bool wide_labels(double cells_per_metre, double ball_radius) {
    const double across = 2 * ball_radius * cells_per_metre;
    return std::isfinite(across) && across >= 3;
}

std::string ball_label(int id, bool utf8, bool wide, BallSet set) {
    if (id == 0)
        return utf8 ? "\u25CF" : "o";
    if (set == BallSet::snooker) {
        const int value = snooker_value(id);
        return value > 0 ? std::string(1, static_cast<char>('0' + value)) : "?";
    }
    if (id >= 10 && id <= 15)
        return wide ? std::to_string(id) : std::string(1, static_cast<char>('A' + id - 10));
    if (id >= 1 && id <= 9)
        return std::string(1, static_cast<char>('0' + id));
    return "?";
}

std::string ball_mark(bool utf8) {
    return utf8 ? "\u2022" : "*";
}

Style ball_style(int id, bool colour, BallSet set) {
    Style s;
    if (set == BallSet::snooker) {
        // The labels already tell every ball apart; in monochrome the bold sets the colours
        // off from the pack of reds.
        s.bold = colour || is_snooker_colour(id);
        s.reverse = !colour;
        if (colour) {
            s.bg = ball_colour(id, set);
            s.fg = id == snooker_black ? Colour::white : Colour::ink;
        }
        return s;
    }
    if (!colour) {
        // Without colour the only marks are reverse and bold: solids are "filled", stripes
        // "marked", and the 8 both, so that the 8 never looks like a 1..7 or 9..15.
        s.reverse = !is_stripe(id);
        s.bold = is_stripe(id) || id == 8;
        return s;
    }
    s.bold = true;
    if (id == 8) {
        s.fg = Colour::white;
        s.bg = Colour::black;
    } else if (is_stripe(id)) {
        s.fg = ball_colour(id);
        s.bg = Colour::white;
    } else {
        s.fg = Colour::ink;
        s.bg = ball_colour(id);
    }
    return s;
}

const char* game_title(GameType type) {
    return game_row(type).title;
}

} // namespace termpool::tui
