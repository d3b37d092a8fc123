#pragma once
// A game played at this terminal: the Match takes each action at once, the game is saved after
// each, the players' figures are kept when a game or match ends, and a seated computer decides
// its moves here.

#include <termpool/match.hpp>
#include <utility>

#include "player/options.hpp"
#include "tui/table_driver.hpp"

namespace termpool::tui {

/// The first game of `options`: its setup, race and names, player 1 to break from the rack
/// seeded `seed` (the computers' streams follow on from it).
Match first_match(const GameOptions& options, std::uint64_t seed);

/// The table of a game at this terminal, against a person or the computer.
class LocalDriver : public TableDriver {
public:
    /// A new match as `options` set it up, its first rack from `seed`; rematches take the
    /// seeds after it.
    LocalDriver(const GameOptions& options, std::uint64_t seed);
    /// Takes up a saved match where its record stands (its computers with new streams).
    void resume(Match match);

    const Match& match() const override { return match_; }
    bool may_act() const override { return !match_.computer_to_act(); }
    std::optional<TableNews> submit(const RecordedAction& action, std::string& refusal) override;
    const Upcoming* upcoming(Clock::time_point now) override;
    std::optional<TableNews> take() override;
    bool rematch(int breaker) override;
    bool may_rename() const override { return true; }
    MatchError rename(int player, const std::string& name) override;
    MatchError seat_computer(int player, Level level) override;
    MatchError set_race(int race_to) override;
    std::string problem() const override { return save_problem_; }
    std::string take_message() override { return std::exchange(message_, {}); }
    std::string game_over_text(const std::string& told) const override;
    void leave() override { save(); }

private:
    std::optional<TableNews> apply(const RecordedAction& action, std::string& refusal);
    void save();
    std::string keep_figures();

    GameOptions options_;
    std::uint64_t seed_;
    Match match_;
    std::optional<Upcoming> upcoming_; // the computer's move, asked once per decision
    Clock::time_point rack_over_at_;   // two computers: when the rack they played ended
    bool rack_over_seen_ = false;
    std::string save_problem_;      // why the last save failed, until one works
    bool computer_refused_ = false; // the Match refused the computer's move: it is not asked again
    std::string message_;           // that refusal, for the message line
};

} // namespace termpool::tui
