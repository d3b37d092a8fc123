#include "tui/blank_cells.hpp"

namespace termpool::tui {

bool coloured_blank(const Cell& cell) {
    return cell.glyph == " " && cell.style.bg != Colour::normal && !cell.style.reverse;
}

int signature_column(const Grid& grid, int y) {
    if (y < 0 || y >= grid.height)
        return -1;
    for (int x = 0; x < grid.width; ++x) {
        if (!coloured_blank(grid.at(x, y)))
            continue;
        const int column = x + y;
        return column < grid.width && coloured_blank(grid.at(column, y)) ? column : -1;
    }
    return -1;
}

} // namespace termpool::tui
