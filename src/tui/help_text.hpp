#pragma once
// The text of the help overlay ('?'), kept apart so that it is easy to keep in step with the
// game loop's keys.

#include <string>

namespace termpool::tui {

/// Every key and mouse action, one per line ('\n' separated), for the help overlay.
const std::string& help_text();

} // namespace termpool::tui
