#include "tui/hall_driver.hpp"

#include <algorithm>
#include <termpool/game_registry.hpp>
#include <termpool/name_characters.hpp>
#include <termpool/race.hpp>
#include <termpool/text_width.hpp>

#include "tui/messages.hpp"
#include "tui/table_news.hpp"

namespace termpool::tui {
namespace {

constexpr std::size_t chat_kept = 50; // lines of chat a table keeps on screen
constexpr std::size_t chat_chars = 200;
// Actions waiting to be shown beyond which shots are no longer rolled out: the terminal
// catches up with the table.
constexpr std::size_t far_behind = 12;

// Characters typed: code points (the server counts them so), an invalid byte as one.
std::size_t code_points(const std::string& text) {
    std::size_t count = 0;
    char32_t cp = 0;
    for (std::size_t i = 0; i < text.size(); ++count)
        decode_utf8(text, i, cp);
    return count;
}

bool same_strike(const Strike& a, const Strike& b) {
    return a.speed == b.speed && a.angle_deg == b.angle_deg && a.side == b.side &&
           a.follow == b.follow && a.elevation_deg == b.elevation_deg;
}

} // namespace

HallDriver::HallDriver(Match match, TableLink link)
    : match_(std::move(match)), link_(std::move(link)), reset_(true) {}

void HallDriver::record(Match match) {
    notice_.clear(); // the table is back
    queue_.clear();
    upcoming_.reset();
    awaiting_ = resyncing_ = false;
    // Back after a reconnect to the table as this copy has it (the usual case): whatever is on
    // screen, a shot rolling included, goes on.
    if (match.record().actions.size() == match_.record().actions.size() &&
        match.state_hash() == match_.state_hash()) {
        message_ = table_words();
        return;
    }
    match_ = std::move(match);
    reset_ = true;
}

void HallDriver::action(std::size_t seq, std::uint64_t hash, const RecordedAction& action) {
    // After a mismatch the record is on its way: the actions before it would only part again
    // (and each would ask for another record).
    if (!resyncing_)
        queue_.push_back({seq, hash, action});
}

void HallDriver::aim(int seat, const Strike& strike) {
    // Only the other seat's cue, and only once the table has caught up: this terminal's own
    // aim is already on screen.
    if (queue_.empty() && seat != link_.seat)
        seat_aim_ = SeatAim{seat, strike};
}

void HallDriver::chat(const std::string& name, const std::string& text) {
    chat_.push_back(name + ": " + text);
    if (chat_.size() > chat_kept)
        chat_.erase(chat_.begin());
}

void HallDriver::seat(int seat, const HallSeat& who) {
    if (seat < 1 || seat > 2)
        return;
    seats_[seat - 1] = who;
    if (!who.empty)
        match_.rename(seat, who.name);
}

void HallDriver::refused(const std::string& why) {
    awaiting_ = false;
    message_ = "The hall refused that: " + why;
}

bool HallDriver::may_act() const {
    if (link_.seat == 0)
        return false;
    // Either player may rack the next rack of a race; otherwise the match says whose turn.
    return match_.pending().kind == Pending::next_rack || match_.to_act() == link_.seat;
}

bool HallDriver::waits() const {
    // The server takes no action while a seat is empty (and counts a refusal as an error).
    return awaiting_ || !queue_.empty() || !may_act() || seats_[0].empty || seats_[1].empty;
}

std::optional<TableNews> HallDriver::submit(const RecordedAction& action, std::string& refusal) {
    // The server takes it; its echo comes back as the table's next action.
    if (awaiting_ || !link_.act) {
        refusal = "an action is on its way to the hall";
        return std::nullopt;
    }
    awaiting_ = true;
    aim_sent_.reset();
    link_.act(action);
    return std::nullopt;
}

const Upcoming* HallDriver::upcoming(Clock::time_point) {
    if (upcoming_)
        return &*upcoming_;
    if (queue_.empty())
        return nullptr;
    const RecordedAction& next = queue_.front().action;
    const int actor = match_.to_act();
    // The server's computer plays at once, a run of shots in a moment; each is shown as at
    // home, the cue turning to its aim and the bar filling first, unless this terminal has
    // fallen far behind.
    const bool computer = actor >= 1 && actor <= 2 && seats_[actor - 1].computer;
    upcoming_ = Upcoming{
        next, computer && next.kind == RecordedAction::Kind::shot && queue_.size() <= far_behind,
        queue_.size() > far_behind + 1};
    return &*upcoming_;
}

std::optional<TableNews> HallDriver::take() {
    if (queue_.empty())
        return std::nullopt;
    const QueuedAction next = queue_.front();
    queue_.pop_front();
    upcoming_.reset();
    // Whatever the server applied, what this terminal sent is settled: it was this action, or
    // its refusal is on the way.
    awaiting_ = false;
    MatchError error = MatchError::none;
    std::optional<TableNews> news;
    if (next.seq == match_.record().actions.size() + 1)
        news = take_action(match_, next.action, error, link_.seat);
    if (!news || match_.state_hash() != next.hash) {
        // This copy and the server's parted: the record sets it right.
        queue_.clear();
        sync_wanted_ = CopyState{match_.record().actions.size(), match_.state_hash()};
        resyncing_ = true;
        return std::nullopt;
    }
    return news;
}

std::optional<DriverReply> HallDriver::handle(const Input& in, const Layout&,
                                              const ScreenFacts& screen) {
    if (chat_entry_) {
        // What the server refuses is not typed: C1 controls, and characters that hide or turn
        // the line around (a chat line is held to a name's rule).
        const auto fits = [&](const std::string& typed) {
            return text_characters_allowed(typed) &&
                   code_points(chat_entry_->text) + code_points(typed) <= chat_chars;
        };
        if (chat_entry_->edit(in, fits) || in.kind != Input::Kind::key)
            return DriverReply{};
        // A line of nothing that shows (spaces, marks) says nothing: Enter closes it unsent, as
        // an empty one.
        const bool says_something = !shown_text_problem(chat_entry_->text, "chat");
        if (in.key == key_enter && says_something && link_.chat && !link_.chat(chat_entry_->text)) {
            chat_entry_->error = "one line a second: Enter again";
            return DriverReply{};
        }
        if (in.key == key_enter || in.key == key_escape)
            chat_entry_.reset();
        return DriverReply{};
    }
    if (in.kind == Input::Kind::key && in.key == '\t') {
        chat_entry_.emplace();
        return DriverReply{};
    }
    const bool leave_help_or_log =
        in.kind == Input::Kind::text && (in.text == "q" || in.text == "?" || in.text == "l");
    // A shot rolling can be hurried on any screen; the rest is the shooter's, once the
    // server's last word is in.
    if (screen.rolling || leave_help_or_log)
        return std::nullopt;
    if (screen.over && match_.pending().kind != Pending::next_rack)
        return std::nullopt; // q goes back to the lobby
    return waits() ? std::optional<DriverReply>(DriverReply{}) : std::nullopt;
}

void HallDriver::aim_set(const Strike& strike) {
    // The cue as it is now, each time it changes; the session keeps to the server's rate.
    if (waits() || !link_.aim || (aim_sent_ && same_strike(*aim_sent_, strike)))
        return;
    aim_sent_ = strike;
    link_.aim(strike);
}

std::string HallDriver::table_words() const {
    // Where the table stands, and with ball in hand what the player must do first.
    if (match_.record().actions.empty())
        return breaks_words(match_, match_.to_act(), may_act());
    if (match_.pending().kind == Pending::place) {
        const std::string where = ball_in_hand_words(match_.game().ball_in_hand());
        return standing_words(match_) +
               (may_act() ? ": place the cue ball " + where : ", with ball in hand " + where);
    }
    return standing_words(match_);
}

void HallDriver::compose(View& v, const ScreenFacts& screen) const {
    for (int p = 0; p < 2; ++p) {
        const HallSeat& seat = seats_[p];
        if (seat.empty)
            v.names[p] = "(empty seat)";
        else if (seat.away)
            v.names[p] += " (away)";
    }
    v.chat = chat_;
    v.hall = true;
    const bool still = !screen.rolling && !screen.over;
    if (chat_entry_) {
        // The end of a long line, where the typing is.
        const std::string& text = chat_entry_->text;
        const std::size_t shown = 40;
        std::size_t from = text.size() > shown ? text.size() - shown : 0;
        while (from > 0 && (text[from] & 0xC0) == 0x80)
            --from; // not inside a character
        v.message =
            "Say: " + std::string(from > 0 ? "..." : "") + text.substr(from) + "_  " +
            (chat_entry_->error.empty() ? "(Enter sends, Esc cancels)" : chat_entry_->error);
    } else if (link_.seat == 0) {
        v.message = "Watching. " + v.message;
    } else if (still && (seats_[0].empty || seats_[1].empty)) {
        v.message = "Waiting for an opponent to sit down (Tab: chat)";
    } else if (still && !may_act()) {
        v.message += std::string(v.message.empty() ? "" : "; ") + "waiting for " +
                     match_.name(3 - link_.seat) + " (Tab: chat)";
    }
}

std::string HallDriver::game_over_text(const std::string& told) const {
    const MatchState& s = match_.score();
    std::string text = told;
    // Snooker says frames: a match of them best of N, the next one broken off.
    const bool frames = game_row(match_.game().type()).scoring == Scoring::points;
    if (s.is_race()) {
        text += "\n\n" +
                (frames ? "Best of " + std::to_string(best_of_for_race(s.race_to)) + " frames"
                        : "Race to " + std::to_string(s.race_to)) +
                ": " + match_.name(1) + " " + std::to_string(s.racks_won[0]) + ", " +
                match_.name(2) + " " + std::to_string(s.racks_won[1]);
        if (const int winner = s.match_winner())
            text += "\n" + match_.name(winner) + " wins the match";
    }
    const std::string next = frames ? "frame" : "rack";
    if (match_.pending().kind == Pending::next_rack)
        text += link_.seat != 0
                    ? "\n\nEnter  next " + next + " (" + match_.name(match_.next_breaker()) +
                          (frames ? " breaks off)" : " breaks)") +
                          "\nq      back to the lobby (your seat waits)"
                    : "\n\nWaiting for the next " + next + "\nq  back to the lobby";
    else
        text += "\n\nq  back to the lobby";
    return text;
}

} // namespace termpool::tui
