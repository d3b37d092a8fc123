#pragma once
// Practice at the table: no referee. The shots are the practice table's; `m` picks balls up and
// puts them down (keys or mouse), `r` takes the last shot again, `t` sets up a new rack.

#include <termpool/match.hpp>
#include <termpool/practice.hpp>

#include "player/options.hpp"
#include "tui/table_driver.hpp"

namespace termpool::tui {

/// The App's table in practice.
class PracticeDriver : public TableDriver {
public:
    /// The rack a game of `options` would have, from `seed`.
    PracticeDriver(const GameOptions& options, std::uint64_t seed);

    const Match& match() const override { return players_; }
    const Game& game() const override { return game_; }
    PendingAction pending() const override { return {Pending::shoot, 1, BallInHand::none, {}}; }
    bool referee() const override { return false; }
    bool may_act() const override { return true; }
    bool calls_pocket(int) const override { return false; }
    std::vector<int> targets() const override;
    std::optional<TableNews> submit(const RecordedAction& action, std::string& refusal) override;
    const Upcoming* upcoming(Clock::time_point) override { return nullptr; }
    std::optional<TableNews> take() override { return std::nullopt; }
    bool may_rename() const override { return true; }
    MatchError rename(int player, const std::string& name) override;
    std::optional<DriverReply> handle(const Input& in, const Layout& layout,
                                      const ScreenFacts& screen) override;
    std::string table_words() const override;
    void compose(View& view, const ScreenFacts& screen) const override;
    std::string game_over_text(const std::string&) const override { return {}; }

private:
    void sync();
    DriverReply hold(int id);
    DriverReply put_down(Vec2 spot);
    std::optional<DriverReply> handle_moving(const Input& in, const Layout& layout);

    Table table_;
    PhysicsParams params_;
    std::uint64_t seed_;
    Match players_; // the player's name
    PracticeTable practice_;
    Game game_; // the table read as a Game without referee state
    Strike last_strike_;
    bool moving_ = false; // `m`: balls are being moved
    int held_ = -1;       // the ball held, -1: none
    Vec2 held_at_;
};

} // namespace termpool::tui
