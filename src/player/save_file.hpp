#pragma once
// Where the game is saved. The saves are written atomically (files/atomic_file.hpp), so that a
// dropped connection never leaves half a file.

#include <string>

#include "files/atomic_file.hpp"

namespace termpool {

/// $XDG_STATE_HOME/termpool, or ~/.local/state/termpool: where games are saved.
std::string save_dir();

} // namespace termpool
