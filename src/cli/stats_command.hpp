#pragma once
// `termpool stats`: every player's totals from the stats file, as a table per game type.

#include <string>
#include <vector>

#include "player/stats_file.hpp"

namespace termpool::cli {

/// The totals as a section per game type played (8-ball, ..., snooker, then a version 1 file's
/// mixed totals), each a title line and an aligned table of that game's figures (names padded
/// by their display width; one line per player, in the store's order) and a blank line; then a
/// short legend per kind of figures shown.
std::string stats_table(const StatsStore& store);

/// `termpool stats [--reset NAME] [--help]`: prints the table, or removes one player's
/// totals.
/// @param args the command-line arguments after `stats`.
/// @return 0 ok (no file yet included), 1 the file could not be read or written or NAME has
///         no totals, 2 bad usage or a damaged file.
int stats_command(const std::vector<std::string>& args);

} // namespace termpool::cli
