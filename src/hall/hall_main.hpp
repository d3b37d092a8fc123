#pragma once
/// \file
/// `termpool hall ...`: the hall's commands, dispatched from main.

#include <string>
#include <vector>

namespace termpool::hall {

/// Runs `termpool hall ARGS...` (`serve` so far); returns the exit status (2 for bad
/// arguments, with the usage on standard error).
int hall_command(const std::vector<std::string>& args);

} // namespace termpool::hall
