#pragma once
// `termpool saves`: the saved games that can be continued, newest first, numbered as
// `termpool --resume N` takes them; `--remove N` removes one.

#include <string>
#include <vector>

namespace termpool::cli {

/// `termpool saves [--remove N] [--help]`: lists the unfinished saves (the slot's number, the
/// players, the game, how far, how long ago), or removes save N.
/// @param args the command-line arguments after `saves`.
/// @return 0 ok (no save included), 1 the save is being played in another terminal or could
///         not be removed, 2 bad usage or an N that is not an unfinished save (nothing removed).
int saves_command(const std::vector<std::string>& args);

} // namespace termpool::cli
