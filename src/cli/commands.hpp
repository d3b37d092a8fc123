#pragma once

#include <string>
#include <vector>

namespace termpool::cli {

/// `termpool simulate [FILE]`: runs the event-based physics simulator.
/// @param args the command-line arguments after `simulate`.
/// @return the process exit status: 0 ok, 1 runtime error, 2 bad usage or bad input.
int simulate_command(const std::vector<std::string>& args);

/// What `termpool bench --render` runs: the terminal front end's figures, under a heading that
/// names `cpu`, the processor. The commands do not include the front end: main passes it in.
using RenderBench = int (*)(const std::string& cpu);

/// `termpool bench [--breaks N] [--shots N] [--seed S]`: benchmarks the simulator.
/// @param args the command-line arguments after `bench`.
/// @param render what `bench --render` runs, once the options are read.
/// @return the process exit status: 0 ok, 1 runtime error, 2 bad usage or bad input.
int bench_command(const std::vector<std::string>& args, RenderBench render);

/// `termpool selfplay --games N --p1 LEVEL --p2 LEVEL [--game G] [--seed S] [--jobs J]`:
/// computer against computer.
/// @param args the command-line arguments after `selfplay`.
/// @return 0 ok, 2 bad usage, 3 an invariant of the game was broken.
int selfplay_command(const std::vector<std::string>& args);

/// `termpool experiment friction|mass|throw [--table T] [--model M] [--csv]`: the seed report's
/// study, and throw against cut angle.
/// @param args the command-line arguments after `experiment`.
/// @return 0 ok, 2 bad usage.
int experiment_command(const std::vector<std::string>& args);

} // namespace termpool::cli
