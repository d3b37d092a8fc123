#pragma once
// A grid as plain text, for golden files and debugging: the glyphs, then one letter per cell
// naming its style, then the letters' legend.

#include <string>

#include "tui/view.hpp"

namespace termpool::tui {

/// Name of a colour role ("felt", "highlight", ...).
const char* colour_name(Colour c);

/// The grid as text:
///
///     grid WxH
///     |<row 0 glyphs>|          (H rows; wide characters leave their right cell out)
///     styles
///     |<row 0 letters>|         (H rows, one letter per cell)
///     legend
///     A fg=normal bg=normal     (one line per letter, in order of first use)
///
/// Letters are given in order of first use (A-Z, a-z, 0-9, then '?').
std::string dump_grid(const Grid& grid);

} // namespace termpool::tui
