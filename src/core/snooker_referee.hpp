#pragma once
// Snooker's referee (snooker.cpp), seen by the Game for the accessors only snooker answers:
// the frame's score sheet, the ball the cue ball touches, a snooker, the points left.

#include <termpool/referee.hpp>

namespace termpool {

// Snooker's rules and its frame's score sheet; what a replace-and-replay puts back.
class SnookerReferee final : public RefereeOf<SnookerReferee> {
public:
    void new_rack(const GameState& s) override;
    void set_up(const GameState& s, const ScoreSheet& sheet) override;
    std::vector<int> legal_targets(const GameState& s) const override;
    std::vector<int> balls_on(const GameState& s) const override;
    std::vector<int> shot_targets(const GameState& s, const ShotCall& call) const override;
    bool pocket_must_be_called(const GameState& s, int ball) const override;
    bool nomination_owed(const GameState& s) const override;
    void before_shot(const GameState& s) override;
    Verdict judge(GameState& s, const ShotCall& call, const ShotFacts& facts) override;
    void choose(GameState& s, int who, Choice choice) override;
    bool concede(GameState& s, int player) override;
    ScoreSheet score_sheet(const GameState& s) const override;
    void add_to_digest(StateDigest& digest) const override;

    // The frame's score sheet.
    const SnookerState& frame() const { return frame_; }
    // The ball on that the cue ball rests touching, -1 for none.
    int touching_ball(const GameState& s) const;
    // True when the shooter is snookered on every ball on.
    bool shooter_snookered(const GameState& s) const;
    // True when the choice owed follows a foul that left the chooser snookered.
    bool free_ball_offered() const { return free_ball_offered_; }
    // The points still on the table for the player on now.
    int points_remaining(const GameState& s) const;

private:
    bool snookered_by(const GameState& s, int id) const;
    void respot_colours(GameState& s, std::vector<int> ids) const;
    void end_visit(const GameState& s);
    void end_frame(GameState& s, Verdict& v);

    SnookerState frame_;
    bool free_ball_offered_ = false; // the chooser is snookered: playing on takes a free ball
    // What a replace-and-replay puts back, and what the shot's judgement needs of the table
    // before it.
    struct BeforeShot {
        std::vector<Ball> balls;
        BallInHand ball_in_hand = BallInHand::none;
        SnookerState frame;
        int touching = -1;      // the ball on the cue ball rested against, or -1
        bool snookered = false; // the shooter was snookered
    };
    BeforeShot before_shot_;
};

} // namespace termpool
