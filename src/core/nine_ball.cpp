// 9-ball: WPA rules.
#include <algorithm>

#include "shot_facts.hpp"

namespace termpool {

Verdict Game::judge_nine(const ShotCall& shot, const Facts& facts) {
    Verdict v;
    const int me = shooter_, other = opponent(shooter_);
    const bool was_break = is_break_;
    const bool push_out = shot.push_out && push_out_allowed_;
    is_break_ = false;
    // The push-out is allowed only on the shot right after the break.
    push_out_allowed_ = was_break;

    if (push_out) {
        // Anything goes but the cue ball leaving the table; the opponent then chooses.
        if (facts.dropped(0))
            v.fouls.push_back(Foul::scratch);
        if (facts.left_table(0))
            v.fouls.push_back(Foul::cue_off_table);
        if (std::ranges::any_of(facts.off_table, [](int id) { return id != 0; }))
            v.fouls.push_back(Foul::off_table);
    } else {
        v.fouls = facts.common_fouls();
        if (was_break && !facts.object_ball_dropped() && facts.balls_to_rail < 4) {
            v.fouls.push_back(Foul::bad_break);
            v.legal_break = false;
        }
    }
    const bool foul = !v.fouls.empty();

    if (foul) {
        if (facts.dropped(9) || facts.left_table(9)) {
            spot_ball(9);
            v.respotted.push_back(9);
        }
        if (++fouls_in_a_row_[me - 1] >= 3) {
            winner_ = other;
            reason_ = WinReason::three_fouls;
            return v;
        }
        shooter_ = other;
        ball_in_hand_ = BallInHand::anywhere;
        return v;
    }
    fouls_in_a_row_[me - 1] = 0;

    if (push_out) {
        if (facts.dropped(9)) {
            spot_ball(9);
            v.respotted.push_back(9);
        }
        pusher_ = me;
        chooser_ = other;
        choices_ = {Choice::shoot, Choice::pass_back};
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
