// Painter: clipping, wide characters and monochrome styles for all drawing code.

#include "tui/painter.hpp"

#include <algorithm>
#include <string>

#include <termpool/text_width.hpp>

namespace termpool::tui {

namespace {

// The ASCII stand-in for a dash, quote or ellipsis, or nothing.
const char* ascii_punctuation(char32_t cp) {
    switch (cp) {
    case U'\u2013': // en dash
    case U'\u2014': // em dash
    case U'\u2212': // minus
        return "-";
    case U'\u2018':
    case U'\u2019':
        return "'";
    case U'\u201C':
    case U'\u201D':
        return "\"";
    case U'\u2026':
        return ".";
    default:
        return nullptr;
    }
}

} // namespace

Painter::Painter(Grid& grid, const Capabilities& caps)
    : grid_(grid), colour_(caps.colours > 0), utf8_(caps.utf8) {}

Style Painter::adapt(Style style) const {
    if (!colour_)
        style.fg = style.bg = Colour::normal;
    return style;
}

// Overwriting half of a wide character would leave the other half on screen: blank it.
void Painter::write(int x, int y, std::string_view glyph, Style style) {
    Cell& c = grid_.at(x, y);
    if (c.glyph.empty() && x > 0)
        grid_.at(x - 1, y).glyph = " ";
    if (!c.glyph.empty() && x + 1 < grid_.width && grid_.at(x + 1, y).glyph.empty())
        grid_.at(x + 1, y).glyph = " ";
    c.glyph.assign(glyph.data(), glyph.size());
    c.style = style;
}

void Painter::put(int x, int y, std::string_view glyph, Style style) {
    if (inside(x, y))
        write(x, y, glyph, adapt(style));
}

void Painter::fill(int x, int y, int w, int h, Style style) {
    const int x0 = std::max(x, 0), x1 = std::min(x + w, grid_.width);
    const int y0 = std::max(y, 0), y1 = std::min(y + h, grid_.height);
    style = adapt(style);
    for (int row = y0; row < y1; ++row)
        for (int col = x0; col < x1; ++col)
            write(col, row, " ", style);
}

int Painter::text(int x, int y, std::string_view s, Style style, int max_columns) {
    if (y < 0 || y >= grid_.height)
        return 0;
    style = adapt(style);
    const int limit = static_cast<int>(
        std::min<long>(static_cast<long>(x) + max_columns, static_cast<long>(grid_.width)));
    int col = x;
    int last = -1; // cell of the last character written, for combining marks
    std::string glyph;
    for (std::size_t i = 0; i < s.size() && col < limit;) {
        char32_t cp;
        glyph.clear();
        int w = 1;
        if (!decode_utf8(s, i, cp)) {
            glyph = utf8_ ? "\xEF\xBF\xBD" : "?";
        } else if (is_control(cp)) {
            continue;
        } else if (!utf8_ && cp >= 0x80) {
            // An ASCII terminal cannot show it: the punctuation the game's own words use in
            // its ASCII form, anything else one '?' per column it would take, and nothing for
            // a combining mark.
            w = codepoint_width(cp);
            if (w == 0)
                continue;
            if (col + w > limit)
                break;
            const char* plain = ascii_punctuation(cp);
            for (int k = 0; k < w; ++k)
                if (col + k >= 0)
                    write(col + k, y, plain ? plain : "?", style);
            last = col + w - 1;
            col += w;
            continue;
        } else {
            w = codepoint_width(cp);
            append_utf8(glyph, cp);
        }
        if (w == 0) {
            if (last >= 0 && last < grid_.width)
                grid_.at(last, y).glyph += glyph;
            continue;
        }
        if (col + w > limit)
            break;
        if (col >= 0) {
            write(col, y, glyph, style);
            if (w == 2) {
                // The right half: an empty glyph, and whatever it covered must not spill.
                if (col + 2 < grid_.width && grid_.at(col + 2, y).glyph.empty())
                    grid_.at(col + 2, y).glyph = " ";
                Cell& right = grid_.at(col + 1, y);
                right.glyph.clear();
                right.style = style;
            }
            last = col;
        } else if (col + w > 0) {
            // A wide character cut by the left edge: show its visible half as a space.
            write(0, y, " ", style);
        }
        col += w;
    }
    return std::max(0, col - x);
}

} // namespace termpool::tui
