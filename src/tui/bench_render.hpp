#pragma once
// `termpool bench --render`: the terminal front end's figures. The bench command parses the
// options; main passes it this, so that the commands need not include the front end.

#include <string>

namespace termpool::tui {

/// Prints on stdout the time to compose a frame at three sizes and the bytes curses sends per
/// animation frame of a break, under a heading naming `cpu`; returns the exit status (0).
int bench_render(const std::string& cpu);

} // namespace termpool::tui
