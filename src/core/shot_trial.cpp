#include "shot_trial.hpp"

namespace termpool {

ShotTrial::ShotTrial(const Game& game)
    : game_(&game), base_(game.table(), game.params(), game.balls()), scratch_(base_),
      after_(game) {}

void ShotTrial::rebase(const Game& game) {
    game_ = &game;
    planned_call_.reset();
    base_.reset(game.balls());
}

World& ShotTrial::fresh_world() {
    scratch_ = base_;
    return scratch_;
}

Verdict ShotTrial::play(const Strike& strike, const ShotCall& call) {
    simulate_shot(fresh_world(), strike, result_);
    // A shot's set-up (copying the world, judging it) costs about as much as eight events.
    work_ += result_.events.size() + 8;
    if (planned_call_ != call) {
        plan_ = game_->plan(call);
        planned_call_ = call;
    }
    after_ = *game_;
    return after_.apply(call, result_, plan_);
}

} // namespace termpool
