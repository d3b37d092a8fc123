#pragma once
// Reading a whole file, always bounded: the size is checked before the first byte is read,
// and again while reading (a file can grow), so that no file makes the program read more than
// the bound its kind states (files/file_limits.hpp).

#include <cstddef>
#include <optional>
#include <string>

namespace termpool {

/// Whether the last part of a path may be a symbolic link.
enum class Links {
    follow,   ///< a link is read through (the player's own config or save, which they may link)
    no_follow ///< a link is refused: where the program alone writes (the hall's files, tokens)
};

/// "FILE: N bytes, more than the M allowed", the one message for a file over its bound.
std::string too_large_message(const std::string& file, unsigned long long bytes,
                              std::size_t max_bytes);

/// All of the open file `fd` (a file, a pipe, a terminal), named `name` in messages, or
/// nothing (with `error`) when it cannot be read or holds more than `max_bytes`. A regular
/// file over the bound is refused from its size alone; anything else is read up to the bound.
std::optional<std::string> read_bounded(int fd, const std::string& name, std::size_t max_bytes,
                                        std::string& error);

/// The whole regular file at `path`, or nothing (with `error`) when it cannot be read, is not
/// a regular file, or holds more than `max_bytes` (too_large_message); a missing file (or one
/// whose folder is a file) gives nothing with an empty error. Opened without blocking, so that a
/// FIFO in a file's place cannot hang the reader; with Links::no_follow a link at `path` is refused
/// (ELOOP).
std::optional<std::string> read_whole_file(const std::string& path, std::string& error,
                                           std::size_t max_bytes, Links links = Links::follow);

} // namespace termpool
