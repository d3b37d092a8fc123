// A table in the hall: the server owns the match. What the player here does goes to the
// server as an action; what the server applied comes back and is played on this copy in the
// server's order (shots rolled out as at home), its state hash checked. The other seat's aim
// turns the cue on this screen as it is set; the table's chat shows in the panel.

#include <algorithm>
#include <string>

#include "tui/app.hpp"
#include "tui/messages.hpp"

namespace termpool::tui {
namespace {

constexpr std::size_t chat_kept = 50; // lines of chat a table keeps on screen
constexpr std::size_t chat_chars = 200;
// Actions waiting to be shown beyond which shots are no longer rolled out: the terminal
// catches up with the table.
constexpr std::size_t far_behind = 12;

std::size_t code_points(const std::string& text) {
    return static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

} // namespace

void App::join_hall(Match match, TableLink link) {
    link_ = std::move(link);
    entry_.player = 0;
    entry_.clear();
    take_hall_table(std::move(match));
}

void App::hall_record(Match match) {
    notice_.clear(); // the table is back
    // Back after a reconnect to the table as this copy has it (the usual case): whatever is on
    // screen, a shot rolling included, goes on.
    if (in_hall() && match.record().actions.size() == match_.record().actions.size() &&
        match.state_hash() == match_.state_hash()) {
        hall_queue_.clear();
        awaiting_hall_ = resyncing_ = false;
        if (mode_ == Mode::animating)
            message_ = name(show_.shot().shooter) + " shoots";
        else if (mode_ != Mode::game_over)
            message_ = hall_table_words();
        return;
    }
    take_hall_table(std::move(match));
}

std::string App::hall_table_words() const {
    // Where the table stands, and with ball in hand what the player must do first.
    if (match_.record().actions.empty())
        return breaks_words(match_.to_act());
    if (match_.pending().kind == Pending::place)
        return resumed_words() + ": place the cue ball";
    return resumed_words();
}

void App::take_hall_table(Match match) {
    match_ = std::move(match);
    table_ = make_table(match_.record().setup);
    params_ = game_physics(match_.record().setup);
    hall_queue_.clear();
    awaiting_hall_ = false;
    resyncing_ = false;
    show_.stop(match_.game().balls());
    verdicts_.clear();
    message_ = hall_table_words();
    start_turn();
}

void App::hall_action(std::size_t seq, std::uint64_t hash, const RecordedAction& action) {
    // After a mismatch the record is on its way: the actions before it would only part again
    // (and each would ask for another record).
    if (resyncing_)
        return;
    hall_queue_.push_back({seq, hash, action});
}

void App::hall_aim(int seat, const Strike& strike) {
    // Only the other seat's cue: this terminal's own aim is already on screen.
    if (mode_ != Mode::aiming || !hall_queue_.empty() || seat != game().shooter() ||
        (link_ && seat == link_->seat))
        return;
    aim().aim_deg = strike.angle_deg;
    aim().power = power_from_speed(strike.speed, game().is_break());
    aim().side = strike.side;
    aim().follow = strike.follow;
    aim().elevation_deg = strike.elevation_deg;
    aim().show_marker = false;
    update_preview();
}

void App::hall_chat(const std::string& name, const std::string& text) {
    chat_.push_back(name + ": " + text);
    if (chat_.size() > chat_kept)
        chat_.erase(chat_.begin());
}

void App::hall_seat(int seat, const HallSeat& who) {
    if (seat < 1 || seat > 2)
        return;
    hall_seats_[seat - 1] = who;
    if (!who.empty)
        match_.rename(seat, who.name);
}

void App::hall_refused(const std::string& why) {
    awaiting_hall_ = false;
    message_ = "The hall refused that: " + why;
}

void App::hall_notice(const std::string& text) {
    notice_ = text;
}

bool App::hall_seat_to_act() const {
    if (!link_ || link_->seat == 0)
        return false;
    // Either player may rack the next rack of a race; otherwise the match says whose turn.
    return match_.pending().kind == Pending::next_rack || match_.to_act() == link_->seat;
}

bool App::hall_waits() const {
    // The server takes no action while a seat is empty (and counts a refusal as an error).
    return awaiting_hall_ || !hall_queue_.empty() || !hall_seat_to_act() || hall_seats_[0].empty ||
           hall_seats_[1].empty;
}

bool App::send_to_hall(const RecordedAction& action) {
    if (awaiting_hall_ || !link_->act)
        return false;
    awaiting_hall_ = true;
    aim_sent_.reset();
    link_->act(action);
    return true;
}

void App::apply_hall_actions() {
    // One at a time, each once the shot before it has rolled out.
    while (!hall_queue_.empty() && mode_ != Mode::animating) {
        const HallAction next = hall_queue_.front();
        // The server's computer plays at once, a run of shots in a moment; each is shown as at
        // home, the cue turning to its aim and the bar filling first, unless this terminal
        // has fallen far behind.
        if (next.action.kind == RecordedAction::Kind::shot && mode_ == Mode::aiming &&
            hall_queue_.size() <= far_behind && hall_seats_[match_.to_act() - 1].computer) {
            const Clock::time_point now = Clock::now();
            if (!pacing_.showing()) {
                ComputerMove move;
                move.kind = Pending::shoot;
                move.shot.strike = next.action.strike;
                move.shot.call = next.action.call;
                pacing_.start(move, aim().aim_deg, now);
            }
            if (!show_computer_aim(now))
                return;
            pacing_.stop();
        }
        hall_queue_.pop_front();
        if (next.seq != match_.record().actions.size() + 1 || !apply_hall_action(next.action) ||
            match_.state_hash() != next.hash) {
            // This copy and the server's parted: the record sets it right.
            hall_queue_.clear();
            sync_wanted_ = CopyState{match_.record().actions.size(), match_.state_hash()};
            resyncing_ = true;
            return;
        }
        if (mode_ == Mode::animating && hall_queue_.size() > far_behind)
            show_.hurry();
    }
    if (mode_ != Mode::animating)
        send_hall_aim();
}

bool App::apply_hall_action(const RecordedAction& action) {
    // Whatever the server applied, what this terminal sent is settled: it was this action, or
    // its refusal is on the way.
    const int actor = match_.to_act();
    const std::string choice =
        choice_words(action.choice, game().type(), match_.game().free_ball_offered());
    awaiting_hall_ = false;
    if (action.kind == RecordedAction::Kind::shot) {
        Game before = match_.game();
        const MatchState score = match_.score();
        Trajectory trajectory(params_, before.balls().size());
        PlayedShot shot;
        if (match_.apply(action, &trajectory, &shot) != MatchError::none)
            return false;
        show_shot(std::move(shot), std::move(trajectory), score, std::move(before));
        return true;
    }
    if (match_.apply(action) != MatchError::none)
        return false;
    switch (action.kind) {
    case RecordedAction::Kind::place:
        message_.clear();
        start_aiming();
        break;
    case RecordedAction::Kind::choose:
        message_.clear();
        tell(action.choice == Choice::concede
                 ? name(actor) + " concedes the frame \u2014 " + name(3 - actor) + " wins it"
                 : name(actor) + ": " + choice);
        start_turn();
        break;
    case RecordedAction::Kind::rack:
        message_ = (snooker_play() ? "Frame " : "Rack ") + std::to_string(match_.rack()) + ": " +
                   breaks_words(action.breaker);
        start_turn();
        break;
    case RecordedAction::Kind::shot:
        break;
    }
    return true;
}

void App::send_hall_aim() {
    // The cue as it is now, each time it changes; the session keeps to the server's rate.
    if (mode_ != Mode::aiming || hall_waits() || !link_->aim)
        return;
    const Strike strike = aim().strike(game().is_break(), Clock::now());
    if (aim_sent_ && aim_sent_->speed == strike.speed && aim_sent_->angle_deg == strike.angle_deg &&
        aim_sent_->side == strike.side && aim_sent_->follow == strike.follow &&
        aim_sent_->elevation_deg == strike.elevation_deg)
        return;
    aim_sent_ = strike;
    link_->aim(strike);
}

bool App::handle_hall_key(const Input& in) {
    if (chat_entry_) {
        // The server refuses C1 controls (U+0080 to U+009F, UTF-8 C2 80 to C2 9F) as well.
        const auto c1 = [](const std::string& t) {
            return t.size() == 2 && static_cast<unsigned char>(t[0]) == 0xC2 &&
                   static_cast<unsigned char>(t[1]) < 0xA0;
        };
        const auto fits = [&](const std::string& typed) {
            return !c1(typed) && code_points(chat_entry_->text) + code_points(typed) <= chat_chars;
        };
        if (chat_entry_->edit(in, fits) || in.kind != Input::Kind::key)
            return true;
        if (in.key == key_enter && !chat_entry_->text.empty() && link_->chat &&
            !link_->chat(chat_entry_->text)) {
            chat_entry_->error = "one line a second: Enter again";
            return true;
        }
        if (in.key == key_enter || in.key == key_escape)
            chat_entry_.reset();
        return true;
    }
    if (in.kind == Input::Kind::key && in.key == '\t') {
        chat_entry_.emplace();
        return true;
    }
    const bool leave_or_help =
        in.kind == Input::Kind::text && (in.text == "q" || in.text == "?" || in.text == "l");
    // A shot rolling can be hurried on any screen; the rest is the shooter's, once the
    // server's last word is in.
    if (mode_ == Mode::animating || leave_or_help)
        return false;
    if (mode_ == Mode::game_over && match_.pending().kind != Pending::next_rack)
        return false; // q goes back to the lobby
    return hall_waits();
}

void App::compose_hall(View& v) const {
    for (int p = 0; p < 2; ++p) {
        const HallSeat& seat = hall_seats_[p];
        if (seat.empty)
            v.names[p] = "(empty seat)";
        else if (seat.away)
            v.names[p] += " (away)";
    }
    v.chat = chat_;
    v.hall = true;
    // Another player's choice shows its box here too, with whom it waits for.
    if (mode_ == Mode::choosing && !hall_seat_to_act() && !confirm_quit_)
        v.overlay += "\n\n(" + name(game().chooser()) + " chooses)";
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
    } else if (!link_ || link_->seat == 0) {
        v.message = "Watching. " + v.message;
    } else if (mode_ != Mode::animating && mode_ != Mode::game_over &&
               (hall_seats_[0].empty || hall_seats_[1].empty)) {
        v.message = "Waiting for an opponent to sit down (Tab: chat)";
    } else if (mode_ != Mode::animating && mode_ != Mode::game_over && !hall_seat_to_act()) {
        v.message += std::string(v.message.empty() ? "" : "; ") + "waiting for " +
                     name(3 - link_->seat) + " (Tab: chat)";
    }
}

std::string App::hall_game_over_text() const {
    const MatchState& s = match_.score();
    std::string text = said();
    if (s.is_race()) {
        text += "\n\nRace to " + std::to_string(s.race_to) + ": " + name(1) + " " +
                std::to_string(s.racks_won[0]) + ", " + name(2) + " " +
                std::to_string(s.racks_won[1]);
        if (const int winner = s.match_winner())
            text += "\n" + name(winner) + " wins the match";
    }
    if (match_.pending().kind == Pending::next_rack)
        text += link_->seat != 0 ? "\n\nEnter  next rack (" + name(match_.next_breaker()) +
                                       " breaks)\nq      back to the lobby (your seat waits)"
                                 : "\n\nWaiting for the next rack\nq  back to the lobby";
    else
        text += "\n\nq  back to the lobby";
    return text;
}

} // namespace termpool::tui
