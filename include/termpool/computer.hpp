#pragma once
/// \file
/// A computer player: it picks shots by simulating candidate strikes on a copy of the game and
/// asking the referee what they would mean, then plays the chosen one with the execution noise
/// of its level.

#include <cstdint>
#include <optional>
#include <termpool/level.hpp>
#include <termpool/rules.hpp>

namespace termpool {

class Random;

/// A shot the computer decided on.
struct ComputerShot {
    Strike strike;    ///< what it will play (noise already added)
    ShotCall call;    ///< its call
    Strike planned;   ///< what it meant to play, before the noise
    double score = 0; ///< how good the referee found the planned shot
};

/// How easy the best pot is for the player on now, 0 (none in sight) to about 1: the legal
/// balls and pockets with clear lines, rated by the cut and the distances; in snooker each
/// ball weighted by what it is worth. The search counts it for position and, for the
/// opponent, against a safety.
double pot_ease(const Game& game);

/// One computer player. Its decisions depend only on the game and its own seeded stream.
class ComputerPlayer {
public:
    /// A player of `level` whose noise and choices come from `seed`.
    ComputerPlayer(Level level, std::uint64_t seed);
    /// The level.
    Level level() const { return level_; }
    /// Where to put the cue ball when the game gives it ball in hand. The shot it found from
    /// there is kept: `shot` of this same game with the cue ball placed there (as Match asks
    /// next) plays it, with fresh noise, rather than search the same position again.
    Vec2 place_cue_ball(const Game& game);
    /// The option to take when the game owes this player a choice.
    Choice choose(const Game& game);
    /// Snooker: true when the player to act (the chooser, else the shooter) should concede
    /// the frame: it is behind by more points than remain on the table, with three reds or
    /// fewer left. Always false in the other games.
    bool concedes(const Game& game) const;
    /// The next shot (the game must have no choice owed and the cue ball on the table).
    ComputerShot shot(const Game& game);
    /// Shots simulated so far by this player's searches.
    std::uint64_t simulations() const { return simulations_; }

private:
    ComputerShot search(const Game& game);
    ComputerShot snooker_search(const Game& game);
    Strike with_noise(const Strike& planned, const PhysicsParams& params);
    Strike noisy(const Strike& planned, const PhysicsParams& params, Random& rng) const;
    Strike break_strike(const Game& game, const Ball& cue) const;
    Strike snooker_break_strike(const Game& game) const;
    Vec2 place_break(const Game& game);
    // Pro's pool break: the pace and line that break best from where the cue ball is, and what
    // that break is worth (`value`).
    Strike searched_break(const Game& game, const Ball& cue, double& value);

    Level level_;
    // The player's own random stream (a SplitMix64 state: support/random.hpp, not part of the
    // library's interface), from its seed.
    std::uint64_t stream_;
    std::uint64_t simulations_ = 0;
    // Pro plays the leaves of its candidates out (two shots ahead) when it picks a shot, but not
    // while it compares spots for the cue ball or the options of a choice, each a whole search:
    // that keeps every decision within a second.
    bool plays_leaves_out_ = true;
    // The work of this player's searches so far (ShotTrial::work), and the work at which the
    // current decision's searches stop sampling (decision_budget).
    std::uint64_t work_ = 0;
    std::uint64_t budget_end_ = UINT64_MAX;
    // The search of the spot place_cue_ball chose, for the shot from there (the next decision
    // the game asks of this player), when it was searched as shot() would search it: in full,
    // within its budget, and not the quicker search pro makes of a spot at pool.
    struct Placed {
        // The game place_cue_ball was given, by its address (only compared: the referee keeps
        // what a position does not show, a pool rack's turns towards a stalemate, and only the
        // same game moved on by the placing alone is sure to hold what the search saw).
        std::uintptr_t source = 0;
        Game game; // a copy of it with the cue ball on the spot
        ComputerShot shot;
    };
    std::optional<Placed> placed_;
};

} // namespace termpool
