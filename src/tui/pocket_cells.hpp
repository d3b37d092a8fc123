#pragma once
// Which rail cells show each pocket: the table drawing darkens them, the labels go on them, and
// the game loop can find the pocket under a mouse click.

#include <utility>
#include <vector>

#include "tui/view.hpp"

namespace termpool::tui {

/// The cells of one pocket on the rails, and the cell for its number.
struct PocketCells {
    std::vector<std::pair<int, int>> cells; ///< (column, row) of each rail cell of the mouth
    int label_x = 0, label_y = 0;           ///< where its number goes
};

/// The rail cells of pocket `number` (1..6): the corner cells for a corner pocket, plus every
/// rail cell whose centre lies within the mouth (between the jaw points), so pockets grow with
/// the table; a side pocket has at least the two cells either side of its centre line.
PocketCells pocket_cells(const Table& table, const Layout& layout, int number);

/// The pocket (1..6) whose rail cells include (x, y), or 0.
int pocket_at(const Table& table, const Layout& layout, int x, int y);

/// Pocket `number` (1..6) named as a player sees it on the screen, the head string on the
/// left: "bottom-left corner", "bottom side pocket", ..., "top-left corner"; "" for others.
const char* pocket_name(int number);

} // namespace termpool::tui
