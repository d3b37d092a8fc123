// 9-ball: WPA rules, and the parts of them 10-ball shares.
#include <algorithm>

#include "shot_facts.hpp"

namespace termpool {

void Game::rotation_fouls(Verdict& v, const Facts& facts, bool was_break, bool push_out) const {
    if (push_out) {
        // Anything goes but the cue ball leaving the table; the opponent then chooses.
        if (facts.dropped(0))
            v.fouls.push_back(Foul::scratch);
        if (facts.left_table(0))
            v.fouls.push_back(Foul::cue_off_table);
        if (std::ranges::any_of(facts.off_table, [](int id) { return id != 0; }))
            v.fouls.push_back(Foul::off_table);
        return;
    }
    v.fouls = facts.common_fouls();
    if (was_break && !facts.object_ball_dropped() && facts.balls_to_rail < 4) {
        v.fouls.push_back(Foul::bad_break);
        v.legal_break = false;
    }
}

void Game::spot_if_down(Verdict& v, const Facts& facts, int id) {
    if (facts.dropped(id) || facts.left_table(id)) {
        spot_ball(id);
        v.respotted.push_back(id);
    }
}

void Game::rotation_foul_penalty(Verdict& v, const Facts& facts, int money_ball) {
    const int me = shooter_, other = opponent(shooter_);
    spot_if_down(v, facts, money_ball);
    if (++fouls_in_a_row_[me - 1] >= 3) {
        winner_ = other;
        reason_ = WinReason::three_fouls;
        return;
    }
    shooter_ = other;
    ball_in_hand_ = BallInHand::anywhere;
}

void Game::rotation_push_out(Verdict& v, const Facts& facts, int money_ball) {
    spot_if_down(v, facts, money_ball);
    pusher_ = shooter_;
    chooser_ = opponent(shooter_);
    choices_ = {Choice::shoot, Choice::pass_back};
}

Game::RotationStart Game::rotation_start(Verdict& v, const ShotCall& shot, const Facts& facts,
                                         int money_ball) {
    RotationStart start;
    start.was_break = is_break_;
    start.push_out = shot.push_out && push_out_allowed_;
    is_break_ = false;
    // The push-out is allowed only on the shot right after the break.
    push_out_allowed_ = start.was_break;
    rotation_fouls(v, facts, start.was_break, start.push_out);
    start.fouled = !v.fouls.empty();
    if (start.fouled)
        rotation_foul_penalty(v, facts, money_ball);
    else
        fouls_in_a_row_[shooter_ - 1] = 0;
    return start;
}

Verdict Game::judge_nine(const ShotCall& shot, const Facts& facts) {
    Verdict v;
    const int me = shooter_, other = opponent(shooter_);
    const RotationStart start = rotation_start(v, shot, facts, 9);
    if (start.fouled)
        return v;

    if (start.push_out) {
        rotation_push_out(v, facts, 9);
        return v;
    }
    if (facts.dropped(9)) {
        winner_ = me;
        reason_ = WinReason::nine_pocketed;
        return v;
    }
    if (!facts.object_ball_dropped())
        shooter_ = other;
    return v;
}

} // namespace termpool
