#pragma once
// Files that are never left half written: a temporary file in the same folder, fsync, rename
// over the old one, fsync of the folder. The game's saves, the statistics and the hall's tables
// are all written this way.

#include <cstddef>
#include <optional>
#include <string>

namespace termpool {

/// Creates `dir` and its parents (mode 0700) where they are missing. "" when all is well, else
/// why not ("DIR: strerror").
std::string make_directories(const std::string& dir);

/// Writes `text` to `path` atomically, creating its folder: PATH.tmp is written, synced and
/// renamed over PATH, so a reader sees the old file or the new one, never part of either. The
/// caller makes sure PATH has one writer at a time (a lock). False (with `error` naming the
/// file and the problem) on failure, the temporary file removed.
bool write_atomically(const std::string& path, const std::string& text, std::string& error);

/// Largest file read_whole_file reads by default, bytes: far above any config, stats, token or
/// hall state file, so a file this large is damaged or not ours.
inline constexpr std::size_t max_read_bytes = 16 * 1024 * 1024;

/// The whole file, or nothing (with `error`) when it cannot be read or holds more than
/// `max_bytes`; a missing file gives nothing with an empty error.
std::optional<std::string> read_whole_file(const std::string& path, std::string& error,
                                           std::size_t max_bytes = max_read_bytes);

} // namespace termpool
