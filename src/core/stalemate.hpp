#pragma once
// Pool's stalemate rule, kept by the 8-ball and the rotation referees: after many turns without
// a ball dropping a stalemate is declared, each player has three more turns, and then the
// original breaker breaks a new rack.

#include <termpool/referee.hpp>
#include <termpool/rules.hpp>

namespace termpool {

struct Stalemate {
    int turns_without_progress = 0; // turns in a row that pocketed no object ball
    int turns_left = -1;            // turns before the re-rack once declared, -1 before

    // Counts the turn that left the game at `s`, `progress` when it pocketed an object ball.
    // True when the rack must be re-broken now.
    bool after_turn(const GameState& s, bool progress) {
        if (s.winner != 0 || s.chooser != 0)
            return false;
        turns_without_progress = progress ? 0 : turns_without_progress + 1;
        if (progress)
            turns_left = -1;
        else if (turns_left > 0)
            return --turns_left == 0;
        else if (turns_without_progress >= Game::stalemate_warning_turns)
            turns_left = 6;
        return false;
    }
};

// A pool referee that keeps the stalemate rule: each shot is judged by judge_shot, then the
// turn is counted, and the original breaker breaks a new rack when the rule says so. (Its
// new_rack forgets the count: `stalemate_ = {}`.)
class StalemateReferee : public Referee {
public:
    Verdict judge(GameState& s, const ShotCall& call, const ShotFacts& facts) final {
        Verdict v = judge_shot(s, call, facts);
        if (stalemate_.after_turn(s, facts.object_ball_dropped())) {
            rerack(s, s.breaker);
            v.stalemate_rerack = true;
        }
        return v;
    }

protected:
    // What the game's own rules make of the shot.
    virtual Verdict judge_shot(GameState& s, const ShotCall& call, const ShotFacts& facts) = 0;

    Stalemate stalemate_;
};

} // namespace termpool
