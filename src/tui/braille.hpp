#pragma once
// Sub-cell drawing with Braille patterns: each cell holds 2 x 4 dots (U+2800 block), and the
// dots are square because a cell is twice as tall as wide. Lines keep their fractional end
// points, so a small change of angle moves the dots along a long line.

#include <cstdint>
#include <string>
#include <vector>

#include "tui/view.hpp"

namespace termpool::tui {

/// A grid of `cols` x `rows` cells of Braille dots, each cell with the colour role of the first
/// line that put a dot in it. Dot coordinates: x in [0, 2 cols), y in [0, 4 rows), y down.
class DotCanvas {
public:
    /// An empty canvas.
    DotCanvas(int cols, int rows);

    /// Columns (cells).
    int cols() const { return cols_; }
    /// Rows (cells).
    int rows() const { return rows_; }

    /// Sets the dot (x, y) if it is on the canvas.
    void plot(int x, int y, Colour role);
    /// A line between two points in dot coordinates, clipped to the canvas: one dot per step
    /// along the longer axis, the other coordinate rounded with a threshold that varies along
    /// the line, so that a shift of a fraction of a dot moves some of the dots (a 0.1-degree
    /// turn of a long aim line always shows). With `dashed`, every other dot is left out.
    void line(double x0, double y0, double x1, double y1, Colour role, bool dashed = false);
    /// The outline of a circle in dot coordinates.
    void circle(double cx, double cy, double radius, Colour role);
    /// Part of a circle's outline in dot coordinates: the angles from `from` to `to` radians,
    /// counted from +x towards -y (up on the screen, as on the table), ends included.
    void arc(double cx, double cy, double radius, double from, double to, Colour role);

    /// The dots of cell (col, row) as a Braille bit mask (0 for none).
    std::uint8_t mask(int col, int row) const { return cells_[index(col, row)].mask; }
    /// The colour role of cell (col, row).
    Colour role(int col, int row) const { return cells_[index(col, row)].role; }

private:
    struct Dots {
        std::uint8_t mask = 0;
        Colour role = Colour::normal;
    };
    std::size_t index(int col, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols_) +
               static_cast<std::size_t>(col);
    }

    int cols_, rows_;
    std::vector<Dots> cells_;
};

/// The UTF-8 Braille character with the dots of `mask` (U+2800 + mask).
std::string braille_glyph(std::uint8_t mask);

} // namespace termpool::tui
