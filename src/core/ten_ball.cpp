// 10-ball: WPA rules. The break, the fouls, the push-out and the three-foul rule are 9-ball's
// (nine_ball.cpp); what differs is that every shot after the break is called and that the
// 10 wins only when called.
#include <algorithm>

#include "shot_facts.hpp"

namespace termpool {

Verdict Game::judge_ten(const ShotCall& shot, const Facts& facts) {
    Verdict v;
    const int me = shooter_, other = opponent(shooter_);
    const RotationStart start = rotation_start(v, shot, facts, 10);
    if (start.fouled)
        return v;
    const bool was_break = start.was_break, push_out = start.push_out;

    if (push_out) {
        rotation_push_out(v, facts, 10);
        return v;
    }
    if (was_break) {
        // Nothing is called on the break: what drops stays down but the 10, which is spotted,
        // and any ball down keeps the table.
        spot_if_down(v, facts, 10);
        if (!facts.object_ball_dropped())
            shooter_ = other;
        return v;
    }

    // Without a call the referee calls the obvious shot, as in 8-ball: the first ball hit,
    // into whichever pocket it drops in.
    Call call = shot.call;
    if (!call.safety && call.ball == 0 && facts.first_contact > 0) {
        call.ball = facts.first_contact;
        call.pocket = facts.pocket_of(facts.first_contact);
    }
    const bool called_in = !call.safety && call.ball > 0 && call.pocket != 0 &&
                           call.pocket == facts.pocket_of(call.ball);
    if (called_in && call.ball == 10) {
        winner_ = me;
        reason_ = WinReason::ten_pocketed;
        return v;
    }
    // The 10 down any other way comes back; the other balls stay down.
    spot_if_down(v, facts, 10);
    if (called_in)
        return v; // the shooter plays on
    if (call.safety || !facts.object_ball_dropped()) {
        shooter_ = other;
        return v;
    }
    // A ball down that was not called: the incoming player takes the table or hands it back.
    pusher_ = me;
    chooser_ = other;
    choices_ = {Choice::shoot, Choice::pass_back};
    return v;
}

} // namespace termpool
