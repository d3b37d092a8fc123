#pragma once
// `termpool --resume` with several saves, in a terminal: the list, and a question on the
// command line (before any screen is drawn) for the one to continue; `d N` removes save N
// once the player has said yes.

#include <cstdio>
#include <ctime>
#include <optional>
#include <vector>

#include "player/save_list.hpp"

namespace termpool::tui {

/// Lists `saves` (the unfinished ones, newest first, as `unfinished_saves` gives them) on
/// `out` and asks on `in` which to continue: its number, Enter for the first (the newest),
/// `d N` (or `d`, then N) to remove save N after a y/n (it leaves `saves`), q or the end of
/// the input to leave. Answers are read a line at a time, each at most a few hundred bytes
/// (the rest of a longer line is skipped). `now` dates the saves.
/// @return the index in `saves` of the one to continue, or nothing when the player left (or
///         removed the last one).
std::optional<std::size_t> pick_save(std::vector<SlotSave>& saves, std::FILE* in, std::FILE* out,
                                     std::time_t now);

} // namespace termpool::tui
