// 8-ball: WPA rules and the bar-rules variant.
#include <algorithm>

#include "shot_facts.hpp"

namespace termpool {
namespace {

Group group_of_ball(int id) {
    return id >= 1 && id <= 7 ? Group::solids : id >= 9 && id <= 15 ? Group::stripes : Group::open;
}

} // namespace

Verdict Game::judge_eight(const ShotCall& shot, const Facts& facts) {
    Verdict v;
    const bool bar = type_ == GameType::eight_ball_bar;
    const int me = shooter_, other = opponent(shooter_);
    const BallInHand foul_bih = bar ? BallInHand::kitchen : BallInHand::anywhere;
    auto lose = [&](WinReason why) {
        winner_ = other;
        reason_ = why;
    };
    auto pass_turn = [&](BallInHand bih) {
        shooter_ = other;
        ball_in_hand_ = bih;
    };

    if (is_break_) {
        is_break_ = false;
        v.fouls = {facts.dropped(0) ? Foul::scratch : Foul::none,
                   facts.left_table(0) ? Foul::cue_off_table : Foul::none};
        for (const int id : facts.off_table)
            if (id != 0)
                v.fouls.push_back(Foul::off_table);
        const bool foul = std::ranges::any_of(v.fouls, [](Foul f) { return f != Foul::none; });
        const bool scratch = facts.dropped(0) || facts.left_table(0);
        v.legal_break = facts.object_ball_dropped() || facts.balls_to_rail >= 4;

        if (facts.dropped(8) || facts.left_table(8)) {
            if (bar) {
                // Bar rules: the 8 on the break wins, unless the cue ball went with it.
                if (scratch) {
                    lose(WinReason::eight_on_foul);
                } else {
                    winner_ = me;
                    reason_ = WinReason::eight_on_break;
                }
                return v;
            }
            if (scratch) {
                spot_ball(8);
                v.respotted.push_back(8);
                pass_turn(BallInHand::kitchen);
            } else {
                chooser_ = me;
                choices_ = {Choice::spot_eight, Choice::re_break};
            }
            return v;
        }
        if (foul) {
            pass_turn(BallInHand::kitchen);
            return v;
        }
        if (!v.legal_break) {
            shooter_ = other;
            chooser_ = other;
            choices_ = {Choice::play_on, Choice::re_rack, Choice::re_break};
            return v;
        }
        if (!facts.object_ball_dropped()) {
            pass_turn(BallInHand::none);
            return v;
        }
        if (bar) {
            // The groups that fell on the break decide; both fell: the breaker chooses.
            bool solid = false, stripe = false;
            for (const int id : facts.pocketed) {
                solid = solid || group_of_ball(id) == Group::solids;
                stripe = stripe || group_of_ball(id) == Group::stripes;
            }
            if (solid && stripe) {
                chooser_ = me;
                choices_ = {Choice::take_solids, Choice::take_stripes};
            } else {
                const Group g = solid ? Group::solids : Group::stripes;
                player1_group_ =
                    me == 1 ? g : (g == Group::solids ? Group::stripes : Group::solids);
                v.groups_assigned = true;
            }
        }
        return v; // the breaker shoots again
    }

    v.fouls = facts.common_fouls();
    const bool foul = !v.fouls.empty();
    const bool scratch = facts.dropped(0) || facts.left_table(0);

    // The called ball and pocket. Without a call the referee calls the obvious shot: the first
    // ball hit, into whichever pocket it drops in.
    Call call = shot.call;
    if (!call.safety && call.ball == 0 && facts.first_contact > 0) {
        call.ball = facts.first_contact;
        call.pocket = facts.pocket_of(facts.first_contact);
    }

    if (facts.dropped(8) || facts.left_table(8)) {
        // When several apply, the plainest reason is given: early before foul.
        if (facts.left_table(8))
            lose(WinReason::eight_off_table);
        else if (!facts.group_cleared)
            lose(WinReason::eight_early);
        else if (foul || (bar && scratch))
            lose(WinReason::eight_on_foul);
        else if (call.safety || call.ball != 8 || call.pocket != facts.pocket_of(8))
            lose(WinReason::eight_wrong_pocket);
        else {
            winner_ = me;
            reason_ = WinReason::eight_pocketed;
        }
        return v;
    }

    if (foul) {
        pass_turn(foul_bih);
        return v;
    }
    if (call.safety) {
        pass_turn(BallInHand::none);
        return v;
    }

    const Group mine = group_of(me);
    bool keeps_turn = false;
    if (bar) {
        // Only the 8 is called: any ball of the shooter's group keeps the turn; on an open
        // table the first object ball to drop decides the groups.
        if (mine == Group::open) {
            const auto first = std::ranges::find_if(facts.pocketed, [](int id) { return id != 0; });
            if (first != facts.pocketed.end()) {
                const Group g = group_of_ball(*first);
                player1_group_ =
                    me == 1 ? g : (g == Group::solids ? Group::stripes : Group::solids);
                v.groups_assigned = true;
            }
        }
        const Group now_mine = group_of(me);
        keeps_turn = std::ranges::any_of(
            facts.pocketed, [&](int id) { return id != 0 && group_of_ball(id) == now_mine; });
    } else {
        const bool called_ball_in =
            call.ball > 0 && call.pocket == facts.pocket_of(call.ball) && call.pocket != 0;
        if (called_ball_in && mine == Group::open) {
            const Group g = group_of_ball(call.ball);
            player1_group_ = me == 1 ? g : (g == Group::solids ? Group::stripes : Group::solids);
            v.groups_assigned = true;
            keeps_turn = true;
        } else if (called_ball_in) {
            keeps_turn = group_of_ball(call.ball) == mine;
        }
    }
    if (!keeps_turn)
        pass_turn(BallInHand::none);
    return v;
}

} // namespace termpool
