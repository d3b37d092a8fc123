#pragma once
// Where the game is saved, and writing it so that a dropped connection never leaves half a
// file: a temporary file, fsync, then rename over the old save.

#include <optional>
#include <string>

namespace termpool::tui {

/// $XDG_STATE_HOME/termpool, or ~/.local/state/termpool: where games are saved.
std::string save_dir();

/// Creates `dir` and its parents (mode 0700) where they are missing.
void make_directories(const std::string& dir);

/// Writes `text` to `path` atomically, creating the directory. False (with `error`) on failure.
bool write_atomically(const std::string& path, const std::string& text, std::string& error);

/// The whole file, or nothing (with `error`) when it cannot be read; a missing file gives
/// nothing with an empty error.
std::optional<std::string> read_whole_file(const std::string& path, std::string& error);

} // namespace termpool::tui
