#pragma once
/// \file
/// A referee: the rules of one game type. The Game keeps what every game shares (GameState:
/// the balls, whose turn it is, the choice owed, the winner) and asks its referee what a shot
/// means, which balls may be hit, what a choice does; the referee keeps its own state (groups,
/// fouls in a row, a frame's points). A game type's referee is made by its row of the registry
/// (game_registry.hpp): adding a game is one file with its referee and one row.

#include <memory>
#include <termpool/rules.hpp>
#include <termpool/shot_facts.hpp>
#include <vector>

namespace termpool {

class StateDigest;

/// The rules of one game type, and the state they keep. A Game owns one and copies it with
/// `clone` (a Game is a value: the computer copies games to try shots), so a referee's state
/// should be cheap to copy.
class Referee {
public:
    virtual ~Referee() = default;

    /// A copy of this referee with its state.
    virtual std::unique_ptr<Referee> clone() const = 0;

    /// The balls of `s` were racked anew: the referee forgets the last rack.
    virtual void new_rack(const GameState& s) = 0;
    /// A game set up in the middle (`Game::from_position`): the referee takes up its part of
    /// `sheet`, as if it had written it.
    virtual void set_up(const GameState& s, const ScoreSheet& sheet) = 0;

    /// The balls the shooter may legally hit first now.
    virtual std::vector<int> legal_targets(const GameState& s) const = 0;
    /// The balls on before any nomination; the legal targets where nothing is nominated.
    virtual std::vector<int> balls_on(const GameState& s) const { return legal_targets(s); }
    /// The balls the shot declared by `call` may hit first: the legal targets, narrowed by a
    /// nomination where the game has them.
    virtual std::vector<int> shot_targets(const GameState& s, const ShotCall& /*call*/) const {
        return legal_targets(s);
    }
    /// True when a shot at `ball` must name its pocket (the break is the Game's to except).
    virtual bool pocket_must_be_called(const GameState& s, int ball) const = 0;
    /// True when the shooter names the ball on with the shot's `Call.ball` (snooker's colour
    /// after a red).
    virtual bool nomination_owed(const GameState& /*s*/) const { return false; }

    /// Hears that a shot is about to be judged, the balls of `s` still as they were before it:
    /// what the judgement needs of them is the referee's to remember.
    virtual void before_shot(const GameState& /*s*/) {}
    /// Judges the shot of `call` whose `facts` are given, the balls of `s` already where the
    /// shot left them (balls that left the table pocketed, ball in hand none), and moves `s`
    /// on: turn, ball in hand, choices, winner. Returns the verdict's rule-specific part: the
    /// fouls (any order), the break's legality, what was re-spotted; the Game fills in the
    /// rest from `s` and the facts.
    virtual Verdict judge(GameState& s, const ShotCall& call, const ShotFacts& facts) = 0;
    /// Does what `choice`, made by `who`, means (the Game has checked it was offered and
    /// cleared the choice owed).
    virtual void choose(GameState& s, int who, Choice choice) = 0;
    /// `player` concedes: true when the game allows it, `s` then ended. The Game has checked
    /// the game is on and the player is 1 or 2.
    virtual bool concede(GameState& /*s*/, int /*player*/) { return false; }

    /// What the referee has written down (see ScoreSheet).
    virtual ScoreSheet score_sheet(const GameState& s) const = 0;
    /// Adds to `digest` what the referee keeps beyond its score sheet's groups, push-out and
    /// fouls (which Match::state_hash adds for every game), for a match's state hash.
    virtual void add_to_digest(StateDigest& /*digest*/) const {}

protected:
    /// Racks the balls of `s` anew with `breaker` to break, and forgets this rack.
    void rerack(GameState& s, int breaker) {
        s.rerack(breaker);
        new_rack(s);
    }
};

/// The Referee of `Self` with its clone: `class X final : public RefereeOf<X>`.
template <class Self> class RefereeOf : public Referee {
public:
    /// A copy of this referee with its state.
    std::unique_ptr<Referee> clone() const override {
        return std::make_unique<Self>(static_cast<const Self&>(*this));
    }
};

} // namespace termpool
