#pragma once
// What the Python module's shot functions share: the shot object handed to Python, and the
// checks that turn a bad layout or strike into the words `termpool simulate` uses.

#include <termpool/termpool.hpp>

#include <optional>
#include <string>
#include <vector>

namespace termpool::python {

/// A simulated shot as Python sees it: what the simulator produced, and its recorded motion
/// when it was asked for.
struct Shot {
    ShotResult result;
    std::optional<Trajectory> trajectory;
};

/// Why `balls` cannot be set out on `table` with `physics`, in simulate's words ("ball 3 at
/// (0.1, 0.2) is off the table", "ball 2 at (...) overlaps ball 1"), or nothing.
std::optional<std::string> layout_text(const Table& table, const PhysicsParams& physics,
                                       const std::vector<Ball>& balls);

/// Raises ValueError when `balls` cannot be set out or hold no cue ball (id 0) on the table.
void check_layout(const Table& table, const PhysicsParams& physics, const std::vector<Ball>& balls);

/// Raises ValueError when `strike` cannot be played under `physics` (strike_problem).
void check_strike(const PhysicsParams& physics, const Strike& strike);

/// Simulates each strike from its layout (`layouts` holds one, shared by all, or one per
/// strike) on up to `threads` threads (0: one per core), without recording trajectories.
/// Inputs are checked by the caller; the GIL is not touched.
std::vector<Shot> simulate_batch(const Table& table, const PhysicsParams& physics,
                                 const std::vector<std::vector<Ball>>& layouts,
                                 const std::vector<Strike>& strikes, unsigned threads);

} // namespace termpool::python
