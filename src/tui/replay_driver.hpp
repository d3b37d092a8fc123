#pragma once
// A saved game played back: the Match replays the record up to any action, and each action
// comes as the table's next, each shot shown as it was played with its verdict. Space pauses,
// Left/Right step a whole shot.

#include <termpool/match.hpp>
#include <utility>

#include "tui/table_driver.hpp"

namespace termpool::tui {

/// The App's table while it plays a record back.
class ReplayDriver : public TableDriver {
public:
    /// Plays `record` back from its start.
    explicit ReplayDriver(GameRecord record);

    const Match& match() const override { return match_; }
    bool may_act() const override { return false; }
    bool watching() const override { return true; }
    std::optional<TableNews> submit(const RecordedAction& action, std::string& refusal) override;
    const Upcoming* upcoming(Clock::time_point now) override;
    std::optional<TableNews> take() override;
    std::optional<DriverReply> handle(const Input& in, const Layout& layout,
                                      const ScreenFacts& screen) override;
    bool take_reset() override { return std::exchange(reset_, false); }
    std::string table_words() const override;
    std::string take_message() override { return std::exchange(message_, {}); }
    bool busy() const override { return !paused_; }
    std::string game_over_text(const std::string&) const override { return {}; }
    std::string quit_question() const override { return {}; }

private:
    void rewind_to(std::size_t action);
    /// "Replay, shot 3 of 12 (keys)": where the replay stands, `which` naming the shot.
    std::string shot_words(const std::string& which) const;

    GameRecord record_;
    Match match_;
    std::size_t next_ = 0; // the next action of record_ to show
    std::optional<Upcoming> upcoming_;
    bool paused_ = false;
    bool reset_ = false;
    std::string message_;
};

} // namespace termpool::tui
