#pragma once
/// \file
/// `termpool hall ...`: the hall's commands, dispatched from main.

#include <string>
#include <vector>

namespace termpool::hall {

/// Runs `termpool hall serve|bench ARGS...`; returns the exit status (2 for bad arguments,
/// with the usage on standard error).
int hall_command(const std::vector<std::string>& args);

/// The usage of `termpool hall serve` and `termpool hall bench`, for the hall's own usage text.
const char* hall_usage();

} // namespace termpool::hall
