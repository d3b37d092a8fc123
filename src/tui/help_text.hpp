#pragma once
// The text of the help overlay ('?') and how it is cut into pages, kept apart so that it is
// easy to keep in step with the game loop's keys, and so that the game loop knows how many
// pages the renderer shows.

#include <string>
#include <string_view>
#include <vector>

namespace termpool::tui {

/// Every key and mouse action, one per line ('\n' separated), for the help overlay.
const std::string& help_text();

/// The help as shown on a `width` x `height` screen: its lines wrapped to the box's width and
/// cut into pages (at a blank line where one is near), each page leaving two rows for a blank
/// and help_footer. Always at least one page.
std::vector<std::vector<std::string>> help_pages(int width, int height);

/// How many pages the help takes on a `width` x `height` screen (at least 1).
int help_page_count(int width, int height);

/// The help box's last line for page `page` (0-based) of `pages`, the longest form that fits
/// `width` columns: "page 1/2 — Space/PgDn more, Esc closes", "page 2/2 — PgUp back, Esc
/// closes", shorter forms on narrow screens, or "Esc closes" for a single page.
std::string help_footer(int page, int pages, bool utf8, int width);

/// `text` ('\n' between lines) as the lines of a box `columns` wide: a line that fits keeps its
/// spacing, a longer one is wrapped between words.
std::vector<std::string> box_lines(std::string_view text, int columns);

/// Columns of the help box's text on a screen `width` columns wide.
int help_width(int width);

} // namespace termpool::tui
