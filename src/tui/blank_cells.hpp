#pragma once
// Blank cells on a coloured background (the cloth, the rails): a blank shows only its
// background, so paint may send its foreground, its boldness and even its character as it
// likes, as long as the cell looks the same. terminal.cpp's paint uses that to send fewer
// bytes; nothing here knows curses.

#include "tui/view.hpp"

namespace termpool::tui {

/// The no-break space paint sends for a coloured blank at a row's signature column (UTF-8).
inline constexpr const char* no_break_space = "\u00a0";

/// True for a space with a background other than the terminal's own and no reverse video:
/// neither its foreground colour nor bold shows.
bool coloured_blank(const Cell& cell);

/// The column of row `y` where paint sends a coloured blank as a no-break space, so that no two
/// rows of cloth have the same characters: the row's first coloured blank, `y` columns on, when
/// that cell is a coloured blank too; -1 when there is none.
int signature_column(const Grid& grid, int y);

} // namespace termpool::tui
