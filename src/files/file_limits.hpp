#pragma once
// The largest file of each kind the program reads, in one place: a file over its bound is
// damaged or not ours, and reading it all would cost memory and time for nothing (a 300 MB
// table file took 530 MB to restore, a 400 MB save 21 s to list). read_whole_file refuses one
// with "FILE: N bytes, more than the M allowed" before reading a byte.

#include <cstddef>

namespace termpool {

/// A game's save or a hall's table file, bytes. The largest record the hall keeps has 5000
/// actions (hall::Server::Options::max_actions); with every shot at its longest (spin,
/// elevation, a call, numbers of 17 digits) such a record is 0.66 MB, and an ordinary
/// one of that length about 0.25 MB, so 4 MiB leaves a margin of six times the worst (a test
/// measures it).
inline constexpr std::size_t max_save_bytes = 4 * 1024 * 1024;

/// The statistics file, bytes: an entry per name and game is about 60 bytes (350 at the
/// worst), so this holds thousands of names.
inline constexpr std::size_t max_stats_bytes = 1024 * 1024;

/// The config file, bytes: a dozen short settings and their comments.
inline constexpr std::size_t max_config_bytes = 64 * 1024;

/// A hall seat token file, bytes: 32 hex digits and a newline.
inline constexpr std::size_t max_token_bytes = 4 * 1024;

/// A scenario for `termpool simulate`, bytes: a table of 22 balls and a strike.
inline constexpr std::size_t max_scenario_bytes = 1024 * 1024;

/// A file of /proc (a process's stat or status), bytes: a few hundred to a few thousand.
inline constexpr std::size_t max_proc_file_bytes = 64 * 1024;

/// A hall's log read back by `termpool hall bench` for the server's figures, bytes: a bench's
/// server writes a few kilobytes (its lines of a client are rate-limited).
inline constexpr std::size_t max_bench_log_bytes = 16 * 1024 * 1024;

} // namespace termpool
