#pragma once
/// \file
/// A scripted snooker opponent, to measure the computer against the tables a careful person
/// leaves: it pots a ball only when the pot is easy, and otherwise plays a safety (the cue
/// ball rolled away from the balls on, to a cushion, to baulk, or behind a colour). It plays
/// legal snooker: it nominates the colour it plays at, places the cue ball in the D and makes
/// the choices a foul gives it. `termpool selfplay --p2 safe` seats it.

#include <cstdint>
#include <termpool/computer.hpp>
#include <termpool/rules.hpp>

namespace termpool {

/// The scripted safe player. Its decisions depend only on the game and its own seeded stream.
class SafePlayer {
public:
    /// A player whose execution noise comes from `seed`.
    explicit SafePlayer(std::uint64_t seed);
    /// Where to put the cue ball in the D: where it has an easy pot, else near the brown spot
    /// (for the break-off: between the yellow and the brown).
    Vec2 place_cue_ball(const Game& game);
    /// The option to take when a foul owes it a choice: judged by the easiest pot
    /// (`pot_ease`) each leaves, good when it shoots next, bad when the opponent does.
    Choice choose(const Game& game) const;
    /// True when it should concede: behind by more than remains, three reds or fewer left.
    bool concedes(const Game& game) const;
    /// The next shot: the easy pot if there is one (called, the colour nominated), else the
    /// safety that leaves the opponent the least; the break-off is thin off the pack's end red.
    /// `planned` is the shot before its noise (as hard's: aim and pace, no side or screw).
    ComputerShot shot(const Game& game);

    /// How often, of four strokes under its noise, a pot must drop to count as easy.
    static constexpr int easy_of_four = 3;

private:
    // The player's own random stream (a SplitMix64 state: support/random.hpp, not part of the
    // library's interface), from its seed.
    std::uint64_t stream_;
};

} // namespace termpool
