#pragma once
// Writing into a Grid safely: every write is clipped to the grid, wide characters take two
// cells, and in monochrome the colour roles are dropped so that only bold and reverse remain.

#include <climits>
#include <string_view>

#include "tui/view.hpp"

namespace termpool::tui {

/// Clipped, capability-aware writes into a grid.
class Painter {
public:
    /// Paints into `grid` for a terminal with `caps`.
    Painter(Grid& grid, const Capabilities& caps);

    /// Columns of the grid.
    int width() const { return grid_.width; }
    /// Rows of the grid.
    int height() const { return grid_.height; }
    /// True when (x, y) is inside the grid.
    bool inside(int x, int y) const { return grid_.inside(x, y); }
    /// True for a colour terminal (colour roles are kept).
    bool colour() const { return colour_; }
    /// True for a UTF-8 terminal.
    bool utf8() const { return utf8_; }
    /// The cell at (x, y), or nothing outside.
    const Cell* cell(int x, int y) const { return inside(x, y) ? &grid_.at(x, y) : nullptr; }

    /// Writes a glyph of width 1 at (x, y); nothing outside the grid.
    void put(int x, int y, std::string_view glyph, Style style);
    /// Fills a rectangle with spaces in `style` (clipped).
    void fill(int x, int y, int w, int h, Style style);
    /// Writes UTF-8 text from (x, y), at most `max_columns` columns and never past the grid's
    /// right edge; control characters are skipped and invalid bytes shown as U+FFFD ('?' in
    /// ASCII mode). Returns the columns used.
    int text(int x, int y, std::string_view s, Style style, int max_columns = INT_MAX);

private:
    Style adapt(Style style) const;
    void write(int x, int y, std::string_view glyph, Style style);

    Grid& grid_;
    bool colour_;
    bool utf8_;
};

} // namespace termpool::tui
