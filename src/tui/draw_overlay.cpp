// Overlays: a bordered box of text (questions, game over) placed clear of the balls, and the
// help, a page at a time.

#include <algorithm>
#include <climits>
#include <string>
#include <vector>

#include "tui/draw.hpp"
#include "tui/help_text.hpp"
#include <termpool/text_width.hpp>

namespace termpool::tui {
namespace {

struct Box {
    int x, y, w, h;
    bool holds(int cx, int cy) const { return cx >= x && cy >= y && cx < x + w && cy < y + h; }
};

// What box `b` covers, as a cost: two for each cell of `keep`, one for row `row`. A box keeps
// off the row where it can, but never at the cost of a ball: one ball more costs more than the
// row, however near the place.
int covered_cells(const Box& b, const std::vector<std::pair<int, int>>& keep, int row) {
    const int on_row = b.y <= row && row < b.y + b.h ? 1 : 0;
    return on_row +
           2 * static_cast<int>(std::count_if(keep.begin(), keep.end(), [&](const auto& c) {
               return b.holds(c.first, c.second);
           }));
}

// Where a box of w x h goes: centred if that covers none of `keep`, else centred on the panel,
// else the place covering the fewest, nearest the centre. The last row, which holds the keys'
// hint (and the legend below a narrow table), is kept as a cell of `keep` is.
Box place_box(const Frame& f, int w, int h, const std::vector<std::pair<int, int>>& keep) {
    const Painter& p = f.paint;
    const int hint_row = p.height() - 1;
    const auto covered = [&](const Box& b) { return covered_cells(b, keep, hint_row); };
    // A box as wide as the screen keeps off the last row: the terminal's bottom-right cell is
    // never written (it would scroll some terminals), and the box's corner would be missing.
    const int lowest = p.height() - h - (w >= p.width() ? 1 : 0);
    const auto clamp_box = [&](int x, int y) {
        return Box{std::clamp(x, 0, std::max(0, p.width() - w)),
                   std::clamp(y, 0, std::max(0, lowest)), w, h};
    };
    const Box centred = clamp_box((p.width() - w) / 2, (p.height() - h) / 2);
    if (covered(centred) == 0)
        return centred;
    const Layout& l = f.layout;
    const Box panel = clamp_box(l.panel_x + (l.panel_width - w) / 2,
                                l.panel_below ? l.panel_y + l.panel_height - 1 - h
                                              : l.panel_y + (l.panel_height - h) / 2);
    if (covered(panel) == 0)
        return panel;
    Box best = centred;
    long best_cost = LONG_MAX;
    for (int y = 0; y <= lowest; ++y)
        for (int x = 0; x + w <= p.width(); ++x) {
            const Box b{x, y, w, h};
            // Distance in screen terms, a row being two columns tall.
            const long dx = x - centred.x, dy = 2L * (y - centred.y);
            const long cost = covered(b) * 1000000L + dx * dx + dy * dy;
            if (cost < best_cost)
                best_cost = cost, best = b;
        }
    return best;
}

void draw_frame(Painter& p, const Box& b) {
    const Style border{Colour::highlight, Colour::normal, true};
    const bool u = p.utf8();
    p.fill(b.x, b.y, b.w, b.h, {});
    for (int c = 1; c < b.w - 1; ++c) {
        p.put(b.x + c, b.y, u ? "\u2500" : "-", border);
        p.put(b.x + c, b.y + b.h - 1, u ? "\u2500" : "-", border);
    }
    for (int r = 1; r < b.h - 1; ++r) {
        p.put(b.x, b.y + r, u ? "\u2502" : "|", border);
        p.put(b.x + b.w - 1, b.y + r, u ? "\u2502" : "|", border);
    }
    p.put(b.x, b.y, u ? "\u256D" : "+", border);
    p.put(b.x + b.w - 1, b.y, u ? "\u256E" : "+", border);
    p.put(b.x, b.y + b.h - 1, u ? "\u2570" : "+", border);
    p.put(b.x + b.w - 1, b.y + b.h - 1, u ? "\u256F" : "+", border);
}

// The lines of `text` for a box on this screen, and the box's inner width.
std::vector<std::string> fitted(const Painter& p, const std::string& text, int& inner) {
    inner = 0;
    for (const std::string& line : box_lines(text, INT_MAX))
        inner = std::max(inner, display_width(line));
    // Border and one space either side; shrink to the screen and wrap what no longer fits.
    inner = std::min(inner, p.width() - 4);
    if (inner < 1)
        return {};
    std::vector<std::string> lines = box_lines(text, inner);
    lines.resize(std::min(lines.size(), static_cast<std::size_t>(std::max(0, p.height() - 2))));
    return lines;
}

} // namespace

void draw_box(const Frame& f, const std::string& text,
              const std::vector<std::pair<int, int>>& keep) {
    Painter& p = f.paint;
    if (p.width() < 5 || p.height() < 3)
        return;
    int inner = 0;
    const std::vector<std::string> lines = fitted(p, text, inner);
    if (lines.empty())
        return;
    const int rows = static_cast<int>(lines.size());
    const Box b = place_box(f, inner + 4, rows + 2, keep);
    draw_frame(p, b);
    for (int r = 0; r < rows; ++r)
        p.text(b.x + 2, b.y + 1 + r, lines[static_cast<std::size_t>(r)], {}, inner);
}

void draw_help(Painter& p, int page) {
    if (p.width() < 5 || p.height() < 5)
        return;
    const std::vector<std::vector<std::string>> pages = help_pages(p.width(), p.height());
    const int count = static_cast<int>(pages.size());
    page = std::clamp(page, 0, count - 1);
    const int inner = help_width(p.width());
    std::size_t tallest = 0;
    for (const auto& lines : pages)
        tallest = std::max(tallest, lines.size());
    const std::vector<std::string> footer =
        box_lines(help_footer(page, count, p.utf8(), inner), inner);
    // Every page gets the same box, so that turning pages does not move it.
    const int text_rows = static_cast<int>(tallest), footer_rows = static_cast<int>(footer.size());
    const int w = inner + 4, h = std::min(p.height(), text_rows + footer_rows + 3);
    const Box b{(p.width() - w) / 2, (p.height() - h) / 2, w, h};
    draw_frame(p, b);
    const std::vector<std::string>& lines = pages[static_cast<std::size_t>(page)];
    for (std::size_t r = 0; r < lines.size() && static_cast<int>(r) < h - 3 - footer_rows; ++r)
        p.text(b.x + 2, b.y + 1 + static_cast<int>(r), lines[r], {}, inner);
    for (int r = 0; r < footer_rows; ++r)
        p.text(b.x + 2, b.y + h - 1 - footer_rows + r, footer[static_cast<std::size_t>(r)],
               {Colour::highlight, Colour::normal, true}, inner);
}

} // namespace termpool::tui
