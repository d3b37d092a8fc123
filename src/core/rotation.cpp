// The rotation games, 9-ball and 10-ball (WPA rules): the lowest ball first, the break, the
// fouls, the push-out after the break and the three-foul rule are shared; 9-ball's 9 wins
// however it drops, while in 10-ball every shot after the break is called and the 10 wins
// only when called.
#include <algorithm>

#include "referees.hpp"
#include "stalemate.hpp"

namespace termpool {
namespace {

class RotationReferee : public StalemateReferee {
public:
    void new_rack(const GameState&) override {
        pusher_ = 0;
        push_out_allowed_ = false;
        fouls_in_a_row_[0] = fouls_in_a_row_[1] = 0;
        stalemate_ = {};
    }
    void set_up(const GameState& s, const ScoreSheet& sheet) override {
        new_rack(s);
        push_out_allowed_ = sheet.push_out_allowed;
        fouls_in_a_row_[0] = sheet.fouls_in_a_row[0];
        fouls_in_a_row_[1] = sheet.fouls_in_a_row[1];
    }
    std::vector<int> legal_targets(const GameState& s) const override {
        // The lowest ball on the table.
        int lowest = 0;
        for (const Ball& b : s.balls)
            if (b.id != 0 && b.state != MotionState::pocketed && (lowest == 0 || b.id < lowest))
                lowest = b.id;
        return lowest == 0 ? std::vector<int>{} : std::vector<int>{lowest};
    }
    void choose(GameState& s, int who, Choice choice) override {
        if (choice == Choice::shoot) {
            s.shooter = who;
            s.is_break = false;
        } else if (choice == Choice::pass_back) {
            s.shooter = pusher_;
        }
    }
    ScoreSheet score_sheet(const GameState&) const override {
        ScoreSheet sheet;
        sheet.push_out_allowed = push_out_allowed_;
        sheet.fouls_in_a_row[0] = fouls_in_a_row_[0];
        sheet.fouls_in_a_row[1] = fouls_in_a_row_[1];
        return sheet;
    }

protected:
    // The shared start (`start`); a foul or a push-out is judged there, the rest by the game.
    Verdict judge_shot(GameState& s, const ShotCall& shot, const ShotFacts& facts) final {
        Verdict v;
        const Start started = start(s, v, shot, facts);
        if (started.fouled)
            return v;
        if (started.push_out) {
            push_out(s, v, facts);
            return v;
        }
        judge_play(s, v, shot, facts, started.was_break);
        return v;
    }
    // What each game judges of a shot that was neither a foul nor a push-out, into `v`;
    // `was_break` when it was the break.
    virtual void judge_play(GameState& s, Verdict& v, const ShotCall& shot, const ShotFacts& facts,
                            bool was_break) = 0;

    // The start of judging a shot: the break and push-out flags move on, fouls are judged and
    // a foul's penalty paid.
    struct Start {
        bool was_break = false; // the shot was the break
        bool push_out = false;  // the shot was a push-out the rules allowed
        bool fouled = false;    // a foul: judged and penalised, the verdict is complete
    };
    Start start(GameState& s, Verdict& v, const ShotCall& shot, const ShotFacts& facts);
    // After a push-out the opponent chooses who shoots; the money ball comes back if it went.
    void push_out(GameState& s, Verdict& v, const ShotFacts& facts);
    // The incoming player takes the table as it is or hands it back to the shooter.
    void offer_table_back(GameState& s) {
        pusher_ = s.shooter;
        s.chooser = GameState::opponent(s.shooter);
        s.choices = {Choice::shoot, Choice::pass_back};
    }
    // The money ball is spotted when it went down (or off the table).
    void spot_if_down(GameState& s, Verdict& v, const ShotFacts& facts) const {
        if (facts.dropped(money_ball_) || facts.left_table(money_ball_)) {
            s.spot_on_foot_string(money_ball_);
            v.respotted.push_back(money_ball_);
        }
    }

    explicit RotationReferee(int money_ball) : money_ball_(money_ball) {}

private:
    void judge_fouls(Verdict& v, const ShotFacts& facts, bool was_break, bool push_out) const;
    void foul_penalty(GameState& s, Verdict& v, const ShotFacts& facts);

    int money_ball_; // the ball that wins the rack: 9 or 10
    int pusher_ = 0; // who played the push-out (or the uncalled pot) chosen on
    bool push_out_allowed_ = false;
    int fouls_in_a_row_[2] = {0, 0};
};

void RotationReferee::judge_fouls(Verdict& v, const ShotFacts& facts, bool was_break,
                                  bool push_out) const {
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

void RotationReferee::foul_penalty(GameState& s, Verdict& v, const ShotFacts& facts) {
    const int me = s.shooter, other = GameState::opponent(s.shooter);
    spot_if_down(s, v, facts);
    if (++fouls_in_a_row_[me - 1] >= 3) {
        s.win(other, WinReason::three_fouls);
        return;
    }
    s.shooter = other;
    s.ball_in_hand = BallInHand::anywhere;
}

void RotationReferee::push_out(GameState& s, Verdict& v, const ShotFacts& facts) {
    spot_if_down(s, v, facts);
    offer_table_back(s);
}

RotationReferee::Start RotationReferee::start(GameState& s, Verdict& v, const ShotCall& shot,
                                              const ShotFacts& facts) {
    Start start;
    start.was_break = s.is_break;
    start.push_out = shot.push_out && push_out_allowed_;
    s.is_break = false;
    // The push-out is allowed only on the shot right after the break.
    push_out_allowed_ = start.was_break;
    judge_fouls(v, facts, start.was_break, start.push_out);
    start.fouled = !v.fouls.empty();
    if (start.fouled)
        foul_penalty(s, v, facts);
    else
        fouls_in_a_row_[s.shooter - 1] = 0;
    return start;
}

// 9-ball: the 9 wins however it drops; any ball down keeps the table.
class NineBallReferee final : public RotationReferee {
public:
    NineBallReferee() : RotationReferee(9) {}
    std::unique_ptr<Referee> clone() const override {
        return std::make_unique<NineBallReferee>(*this);
    }
    bool pocket_must_be_called(const GameState&, int) const override { return false; }

private:
    void judge_play(GameState& s, Verdict&, const ShotCall&, const ShotFacts& facts,
                    bool) override {
        if (facts.dropped(9)) {
            s.win(s.shooter, WinReason::nine_pocketed);
            return;
        }
        if (!facts.object_ball_dropped())
            s.shooter = GameState::opponent(s.shooter);
    }
};

// 10-ball: every shot after the break is called; the 10 wins only when called.
class TenBallReferee final : public RotationReferee {
public:
    TenBallReferee() : RotationReferee(10) {}
    std::unique_ptr<Referee> clone() const override {
        return std::make_unique<TenBallReferee>(*this);
    }
    bool pocket_must_be_called(const GameState&, int) const override { return true; }

private:
    void judge_play(GameState& s, Verdict& v, const ShotCall& shot, const ShotFacts& facts,
                    bool was_break) override;
};

void TenBallReferee::judge_play(GameState& s, Verdict& v, const ShotCall& shot,
                                const ShotFacts& facts, bool was_break) {
    const int me = s.shooter, other = GameState::opponent(s.shooter);
    if (was_break) {
        // Nothing is called on the break: what drops stays down but the 10, which is spotted,
        // and any ball down keeps the table.
        spot_if_down(s, v, facts);
        if (!facts.object_ball_dropped())
            s.shooter = other;
        return;
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
        s.win(me, WinReason::ten_pocketed);
        return;
    }
    // The 10 down any other way comes back; the other balls stay down.
    spot_if_down(s, v, facts);
    if (called_in)
        return; // the shooter plays on
    if (call.safety || !facts.object_ball_dropped()) {
        s.shooter = other;
        return;
    }
    // A ball down that was not called: the incoming player takes the table or hands it back.
    offer_table_back(s);
}

} // namespace

std::unique_ptr<Referee> make_nine_ball_referee() {
    return std::make_unique<NineBallReferee>();
}

std::unique_ptr<Referee> make_ten_ball_referee() {
    return std::make_unique<TenBallReferee>();
}

} // namespace termpool
