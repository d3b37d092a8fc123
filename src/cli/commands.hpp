#pragma once

#include <string>
#include <vector>

namespace termpool::cli {

/// `termpool simulate [FILE]`: runs the event-based physics simulator.
/// @param args the command-line arguments after `simulate`.
/// @return the process exit status: 0 ok, 1 runtime error, 2 bad usage or bad input.
int simulate_command(const std::vector<std::string>& args);

/// `termpool bench [--breaks N] [--shots N] [--seed S]`: benchmarks the simulator.
/// @param args the command-line arguments after `bench`.
/// @return the process exit status: 0 ok, 1 runtime error, 2 bad usage or bad input.
int bench_command(const std::vector<std::string>& args);

} // namespace termpool::cli
