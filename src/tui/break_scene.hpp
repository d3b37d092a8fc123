#pragma once
// The frames of a full-power 8-ball break as the game shows them, the same on every run: the
// benchmarks and the byte tests draw them.

#include <cstdint>
#include <termpool/params.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

#include "tui/aim_state.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// Frames per second the game draws while balls move (its loop waits 16 ms between frames).
inline constexpr int animation_fps = 60;

/// A seeded 8-ball break at full power (12 m/s) on the 9-foot table, from the head spot at the
/// target the game proposes first: frame 0 is the player aiming it (aim line, ghost ball, full
/// power bar, shoot button), frames 1..N the balls rolling at `animation_fps` until the last
/// one stops, with the panel and message the game shows meanwhile.
class BreakScene {
public:
    /// The terminal the frames are rendered for: UTF-8, 256 colours, mouse.
    static constexpr Capabilities caps{256, true, true};

    /// The break of the game of `seed` (the rack `termpool --seed SEED` plays).
    explicit BreakScene(std::uint64_t seed = 1);
    /// Frames: the aiming one and the animation's.
    int frames() const { return animation_frames_ + 1; }
    /// The view of frame `index` (0: aiming; clamped to the last frame).
    View view(int index) const;
    /// Frame `index` rendered at `width` x `height` for a UTF-8, 256-colour, mouse terminal.
    Grid grid(int index, int width, int height) const;

private:
    Table table_;
    PhysicsParams params_;
    std::vector<Ball> rack_;
    AimState aim_;
    Trajectory trajectory_;
    int animation_frames_ = 0;
};

} // namespace termpool::tui
