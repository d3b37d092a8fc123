#pragma once
/// \file
/// `termpool hall bench`: tables of computer players through a real hall server.

#include <string>
#include <vector>

namespace termpool::hall {

/// Runs `termpool hall bench ARGS...` (ARGS[0] is "bench"): starts a server on a private socket,
/// plays `--tables N` tables of two computer players through it for `--seconds S`, prints the
/// actions a second, the action round trip (p50, p99), the server's CPU and peak memory, and
/// checks every table's record against the server's. 0 when every table agrees, 1 when not,
/// 2 for bad arguments.
int hall_bench_command(const std::vector<std::string>& args);

} // namespace termpool::hall
