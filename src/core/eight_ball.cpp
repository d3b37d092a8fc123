// 8-ball: WPA rules and the bar-rules variant.
#include <algorithm>

#include "referees.hpp"
#include "stalemate.hpp"

namespace termpool {
namespace {

Group group_of_ball(int id) {
    return id >= 1 && id <= 7 ? Group::solids : id >= 9 && id <= 15 ? Group::stripes : Group::open;
}

Group other_group(Group g) {
    return g == Group::solids ? Group::stripes : Group::solids;
}

class EightBallReferee final : public StalemateReferee {
public:
    explicit EightBallReferee(bool bar) : bar_(bar) {}
    std::unique_ptr<Referee> clone() const override {
        return std::make_unique<EightBallReferee>(*this);
    }

    void new_rack(const GameState&) override {
        player1_group_ = Group::open;
        stalemate_ = {};
    }
    void set_up(const GameState&, const ScoreSheet& sheet) override {
        player1_group_ = sheet.player1_group;
        stalemate_ = {};
    }
    std::vector<int> legal_targets(const GameState& s) const override;
    bool pocket_must_be_called(const GameState&, int ball) const override {
        return !bar_ || ball == 8; // bar rules call only the 8
    }
    void before_shot(const GameState& s) override {
        const Group group = group_of(s.shooter);
        group_cleared_ = group != Group::open && std::ranges::none_of(s.balls, [&](const Ball& b) {
                             return in_group(group, b.id) && b.state != MotionState::pocketed;
                         });
    }
    void choose(GameState& s, int who, Choice choice) override;
    ScoreSheet score_sheet(const GameState&) const override {
        ScoreSheet sheet;
        sheet.player1_group = player1_group_;
        return sheet;
    }

private:
    Group group_of(int player) const {
        if (player1_group_ == Group::open || player == 1)
            return player1_group_;
        return other_group(player1_group_);
    }
    // `player` takes group `g`, the opponent the other.
    void assign(int player, Group g) { player1_group_ = player == 1 ? g : other_group(g); }
    Verdict judge_shot(GameState& s, const ShotCall& call, const ShotFacts& facts) override;
    Verdict judge_break(GameState& s, const ShotFacts& facts);

    bool bar_ = false;
    Group player1_group_ = Group::open;
    bool group_cleared_ = false; // the shooter's group was all down before the shot
};

std::vector<int> EightBallReferee::legal_targets(const GameState& s) const {
    // One pass and one vector: the computer asks this of every table it weighs.
    const Group group = group_of(s.shooter);
    std::vector<int> targets;
    targets.reserve(s.balls.size()); // one allocation, not one for each doubling
    bool any_on_table = false;
    for (const Ball& b : s.balls) {
        if (b.id == 0 || b.state == MotionState::pocketed)
            continue;
        any_on_table = true;
        if (group == Group::open ? b.id != 8 : in_group(group, b.id))
            targets.push_back(b.id);
    }
    if (!any_on_table)
        return targets;
    // None of the shooter's own: the 8, whether the group is cleared or only the 8 is left on
    // an open table.
    if (targets.empty())
        targets.push_back(8);
    std::ranges::sort(targets);
    return targets;
}

void EightBallReferee::choose(GameState& s, int who, Choice choice) {
    switch (choice) {
    case Choice::play_on:
        s.shooter = who;
        s.is_break = false;
        break;
    case Choice::re_rack:
        rerack(s, who);
        break;
    case Choice::re_break:
        rerack(s, s.breaker);
        break;
    case Choice::spot_eight:
        s.spot_on_foot_string(8);
        s.shooter = who;
        s.is_break = false;
        break;
    case Choice::take_solids:
    case Choice::take_stripes:
        assign(who, choice == Choice::take_solids ? Group::solids : Group::stripes);
        s.shooter = who;
        break;
    default:
        break; // never offered
    }
}

Verdict EightBallReferee::judge_break(GameState& s, const ShotFacts& facts) {
    Verdict v;
    const int me = s.shooter, other = GameState::opponent(s.shooter);
    auto pass_turn = [&](BallInHand bih) {
        s.shooter = other;
        s.ball_in_hand = bih;
    };
    s.is_break = false;
    v.fouls = {facts.dropped(0) ? Foul::scratch : Foul::none,
               facts.left_table(0) ? Foul::cue_off_table : Foul::none};
    for (const int id : facts.off_table)
        if (id != 0)
            v.fouls.push_back(Foul::off_table);
    const bool foul = std::ranges::any_of(v.fouls, [](Foul f) { return f != Foul::none; });
    const bool scratch = facts.dropped(0) || facts.left_table(0);
    v.legal_break = facts.object_ball_dropped() || facts.balls_to_rail >= 4;

    if (facts.dropped(8) || facts.left_table(8)) {
        if (bar_) {
            // Bar rules: the 8 on the break wins, unless the cue ball went with it.
            s.win(scratch ? other : me,
                  scratch ? WinReason::eight_on_foul : WinReason::eight_on_break);
            return v;
        }
        if (scratch) {
            s.spot_on_foot_string(8);
            v.respotted.push_back(8);
            pass_turn(BallInHand::kitchen);
        } else {
            s.chooser = me;
            s.choices = {Choice::spot_eight, Choice::re_break};
        }
        return v;
    }
    if (foul) {
        pass_turn(BallInHand::kitchen);
        return v;
    }
    if (!v.legal_break) {
        s.shooter = other;
        s.chooser = other;
        s.choices = {Choice::play_on, Choice::re_rack, Choice::re_break};
        return v;
    }
    if (!facts.object_ball_dropped()) {
        pass_turn(BallInHand::none);
        return v;
    }
    if (bar_) {
        // The groups that fell on the break decide; both fell: the breaker chooses.
        bool solid = false, stripe = false;
        for (const int id : facts.pocketed) {
            solid = solid || group_of_ball(id) == Group::solids;
            stripe = stripe || group_of_ball(id) == Group::stripes;
        }
        if (solid && stripe) {
            s.chooser = me;
            s.choices = {Choice::take_solids, Choice::take_stripes};
        } else {
            assign(me, solid ? Group::solids : Group::stripes);
            v.groups_assigned = true;
        }
    }
    return v; // the breaker shoots again
}

Verdict EightBallReferee::judge_shot(GameState& s, const ShotCall& shot, const ShotFacts& facts) {
    if (s.is_break)
        return judge_break(s, facts);
    Verdict v;
    const int me = s.shooter, other = GameState::opponent(s.shooter);
    auto pass_turn = [&](BallInHand bih) {
        s.shooter = other;
        s.ball_in_hand = bih;
    };
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
            s.win(other, WinReason::eight_off_table);
        else if (!group_cleared_)
            s.win(other, WinReason::eight_early);
        else if (foul || (bar_ && scratch))
            s.win(other, WinReason::eight_on_foul);
        else if (call.safety || call.ball != 8 || call.pocket != facts.pocket_of(8))
            s.win(other, WinReason::eight_wrong_pocket);
        else
            s.win(me, WinReason::eight_pocketed);
        return v;
    }

    if (foul) {
        pass_turn(bar_ ? BallInHand::kitchen : BallInHand::anywhere);
        return v;
    }
    if (call.safety) {
        pass_turn(BallInHand::none);
        return v;
    }

    const Group mine = group_of(me);
    bool keeps_turn = false;
    if (bar_) {
        // Only the 8 is called: any ball of the shooter's group keeps the turn; on an open
        // table the first object ball to drop decides the groups.
        if (mine == Group::open) {
            const auto first = std::ranges::find_if(facts.pocketed, [](int id) { return id != 0; });
            if (first != facts.pocketed.end()) {
                assign(me, group_of_ball(*first));
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
            assign(me, group_of_ball(call.ball));
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

} // namespace

std::unique_ptr<Referee> make_eight_ball_referee() {
    return std::make_unique<EightBallReferee>(false);
}

std::unique_ptr<Referee> make_bar_eight_ball_referee() {
    return std::make_unique<EightBallReferee>(true);
}

} // namespace termpool
