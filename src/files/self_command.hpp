#pragma once
// How a message names this program, so that the command it suggests works where the player is.

#include <string>

namespace termpool {

/// `termpool` when a search of $PATH for that name finds this very program (the same file);
/// otherwise the absolute path of the running program (a build run from its tree, as by `make
/// run`), which works from any folder. "termpool" when the program's file cannot be read.
std::string self_command();

} // namespace termpool
