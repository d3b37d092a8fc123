#pragma once
// A table in the hall: the server owns the match. What the player here does goes to the server
// as an action; what the server applied comes back and is taken on this copy in the server's
// order, its state hash checked. The other seat's aim turns that seat's cue here; the table's
// chat shows in the panel. The hall session feeds it the server's news.

#include <deque>
#include <optional>
#include <termpool/match.hpp>
#include <utility>
#include <vector>

#include "tui/table_driver.hpp"
#include "tui/table_link.hpp"
#include "tui/text_entry.hpp"

namespace termpool::tui {

/// The App's table while it plays in the hall.
class HallDriver : public TableDriver {
public:
    /// The hall's table at `match`, played from `link.seat` (0: watching).
    HallDriver(Match match, TableLink link);

    // The server's news, from the hall session.
    /// The whole table again, from the server's record (after a mismatch or a reconnect).
    void record(Match match);
    /// The server applied `action` as the table's action `seq`, giving state `hash`.
    void action(std::size_t seq, std::uint64_t hash, const RecordedAction& action);
    /// The shooter in `seat` aims so.
    void aim(int seat, const Strike& strike);
    /// A chat line at the table.
    void chat(const std::string& name, const std::string& text);
    /// Who sits in `seat` (1 or 2) now.
    void seat(int seat, const HallSeat& who);
    /// The server refused what this terminal sent.
    void refused(const std::string& why);
    /// A word on the connection, shown first until the table is back.
    void set_notice(const std::string& text) { notice_ = text; }
    /// Once (then nothing) after this copy disagreed with the server's: where it stood.
    std::optional<CopyState> take_sync_request() { return std::exchange(sync_wanted_, {}); }

    const Match& match() const override { return match_; }
    bool may_act() const override;
    bool shows_call() const override { return may_act(); }
    bool watching() const override { return link_.seat == 0; }
    std::optional<TableNews> submit(const RecordedAction& action, std::string& refusal) override;
    const Upcoming* upcoming(Clock::time_point now) override;
    std::optional<TableNews> take() override;
    std::optional<DriverReply> handle(const Input& in, const Layout& layout,
                                      const ScreenFacts& screen) override;
    void aim_set(const Strike& strike) override;
    std::optional<SeatAim> take_seat_aim() override { return std::exchange(seat_aim_, {}); }
    bool take_reset() override { return std::exchange(reset_, false); }
    std::string table_words() const override;
    std::string take_message() override { return std::exchange(message_, {}); }
    std::string notice() const override { return notice_; }
    bool busy() const override { return !queue_.empty(); }
    void compose(View& view, const ScreenFacts& screen) const override;
    std::string game_over_text(const std::string& told) const override;
    std::string quit_question() const override { return "Leave the table?  y / n"; }

private:
    struct QueuedAction {
        std::size_t seq = 0;
        std::uint64_t hash = 0;
        RecordedAction action;
    };
    bool waits() const;

    Match match_;
    TableLink link_;
    std::deque<QueuedAction> queue_; // the server's actions not taken yet
    std::optional<Upcoming> upcoming_;
    bool awaiting_ = false; // an action of ours is on its way to the server
    std::optional<CopyState> sync_wanted_;
    bool resyncing_ = false; // the record was asked for: actions wait for it
    bool reset_ = false;     // the table was replaced: the App starts the turn again
    HallSeat seats_[2];
    std::vector<std::string> chat_;
    std::optional<TextEntry> chat_entry_;
    std::optional<Strike> aim_sent_;
    std::optional<SeatAim> seat_aim_;
    std::string message_; // the server's refusal, for the message line
    std::string notice_;  // the connection's state, first on the message line
};

} // namespace termpool::tui
