#pragma once
/// \file
/// `termpool hall who`: what a running hall holds (its tables, the people at them, the
/// connections), printed for the host's admin. It asks the hall over its socket, trusting it
/// only as a player's terminal does (hall/socket_trust.hpp), and never starts one.

#include <string>
#include <vector>

namespace termpool::hall {

/// Runs `termpool hall who [--socket PATH]` (`args` from "who" on): prints the hall's answer,
/// one line each, and returns 0; 1 when no hall answers or it cannot be trusted; 2 for a bad
/// argument.
int hall_who_command(const std::vector<std::string>& args);

} // namespace termpool::hall
