#pragma once
// Shots played again and again from one game state, as the computer's searches play them: the
// world is set out once and each shot starts from a copy of it, into memory kept from the shot
// before, so that a search allocates nothing for the simulation of a sample.

#include <optional>
#include <termpool/rules.hpp>
#include <termpool/simulator.hpp>

namespace termpool {

/// Trials of shots from one game state.
class ShotTrial {
public:
    /// Trials from `game` as it stands; `game` must outlive the trials and not change.
    explicit ShotTrial(const Game& game);
    /// Trials from `game` from now on (on the same table, with the same physics).
    void rebase(const Game& game);

    /// `strike` with `call` played from the game as it was given (Game::play, to the bit); the
    /// game after it is after().
    Verdict play(const Strike& strike, const ShotCall& call);
    /// The game after the last play().
    const Game& after() const { return after_; }
    /// A world at the game's layout, not yet struck: a copy, to strike and step at will.
    World& fresh_world();
    /// The work of the shots played so far: their events, and a few for each shot's set-up (a
    /// measure of CPU time that is the same on every machine, for a search's budget).
    std::uint64_t work() const { return work_; }

private:
    const Game* game_;
    // The plan of the last call played (Game::plan): a search plays each call many times.
    std::optional<ShotCall> planned_call_;
    Game::ShotPlan plan_;
    World base_;
    World scratch_;
    ShotResult result_;
    Game after_;
    std::uint64_t work_ = 0;
};

} // namespace termpool
