// Overlays: a centred, bordered box of text (questions, game over) and the help.

#include <algorithm>
#include <string>
#include <vector>

#include "tui/draw.hpp"
#include "tui/help_text.hpp"
#include "tui/text_width.hpp"

namespace termpool::tui {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (true) {
        const std::size_t nl = text.find('\n', start);
        lines.push_back(text.substr(start, nl == std::string::npos ? nl : nl - start));
        if (nl == std::string::npos)
            return lines;
        start = nl + 1;
    }
}

} // namespace

void draw_box(Painter& p, const std::string& text) {
    if (p.width() < 3 || p.height() < 3)
        return;
    std::vector<std::string> lines = split_lines(text);
    int inner = 0;
    for (const std::string& line : lines)
        inner = std::max(inner, display_width(line));
    // Border and one space either side; shrink to the screen and wrap what no longer fits.
    inner = std::min(inner, p.width() - 4);
    if (inner < 1)
        return;
    std::vector<std::string> wrapped;
    for (const std::string& line : lines) {
        // Lines that fit keep their spacing (the help lines up its columns with spaces).
        if (display_width(line) <= inner) {
            wrapped.push_back(line);
            continue;
        }
        for (std::string& piece : wrap_to_width(line, inner))
            wrapped.push_back(std::move(piece));
    }
    const int rows = std::min(static_cast<int>(wrapped.size()), p.height() - 2);
    const int w = inner + 4, h = rows + 2;
    const int x = (p.width() - w) / 2, y = (p.height() - h) / 2;
    const Style border{Colour::highlight, Colour::normal, true};
    const bool u = p.utf8();
    p.fill(x, y, w, h, {});
    for (int c = 1; c < w - 1; ++c) {
        p.put(x + c, y, u ? "\u2500" : "-", border);
        p.put(x + c, y + h - 1, u ? "\u2500" : "-", border);
    }
    for (int r = 1; r < h - 1; ++r) {
        p.put(x, y + r, u ? "\u2502" : "|", border);
        p.put(x + w - 1, y + r, u ? "\u2502" : "|", border);
    }
    p.put(x, y, u ? "\u256D" : "+", border);
    p.put(x + w - 1, y, u ? "\u256E" : "+", border);
    p.put(x, y + h - 1, u ? "\u2570" : "+", border);
    p.put(x + w - 1, y + h - 1, u ? "\u256F" : "+", border);
    for (int r = 0; r < rows; ++r)
        p.text(x + 2, y + 1 + r, wrapped[static_cast<std::size_t>(r)], {}, inner);
}

void draw_help(Painter& p) {
    draw_box(p, help_text());
}

} // namespace termpool::tui
