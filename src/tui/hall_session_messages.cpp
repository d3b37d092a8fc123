// What the hall says, taken in: the welcome and its token, errors, the lobby's snapshots, a
// table joined (its record rebuilt into the App that shows it) or left, and the table's news
// (seats, actions, aims, chat) handed to the App.
#include <variant>

#include "hall/token_store.hpp"
#include "tui/hall_session.hpp"

namespace termpool::tui {
namespace {

using namespace std::chrono_literals;

constexpr auto chat_interval = 1s; // the server refuses more (and counts it as an error)

HallSeat hall_seat_of(const hall::SeatView& seat) {
    return {seat.name, seat.kind == hall::SeatKind::away, seat.kind == hall::SeatKind::empty,
            seat.kind == hall::SeatKind::computer};
}

} // namespace

void HallSession::dispatch(const hall::ServerMessage& message) {
    if (const auto* m = std::get_if<hall::Welcome>(&message)) {
        welcomed_ = ever_connected_ = true;
        backoff_.reset();
        message_ = "Welcome, " + name_ + ".";
        if (m->token != token_) {
            token_ = m->token;
            // Without it kept, a dropped terminal could not take its seat back.
            if (const std::string why = hall::save_token(options_.token_dir, name_, token_);
                !why.empty())
                message_ += " (Your seat token could not be kept: " + why + ")";
        }
        if (rejoin_table_ != 0) {
            if (rejoin_seat_ != 0)
                send(hall::Sit{rejoin_table_, rejoin_seat_});
            else
                send(hall::Watch{rejoin_table_});
        }
    } else if (const auto* m = std::get_if<hall::Error>(&message)) {
        const std::string words = m->text.empty() ? hall::error_code_name(m->code) : m->text;
        if (app_ && table_ != 0)
            driver_->refused(words);
        else
            message_ = "The hall said: " + words;
        if (m->code == hall::ErrorCode::name_taken && !options_.name && !ever_connected_) {
            // A name typed at the prompt, refused at the first hello: the prompt asks again,
            // the hall's words under it. (Under --name there is no other to give; on a
            // reconnect a table may be on screen: the session stops below, as before.)
            client_.disconnect();
            welcomed_ = false;
            token_.clear(); // a token goes with its name: the next name looks up its own
            name_.clear();
            form_ = Form::name;
            entry_.clear();
            entry_.error = words;
            message_.clear();
            return;
        }
        if (m->code == hall::ErrorCode::replaced || m->code == hall::ErrorCode::version ||
            m->code == hall::ErrorCode::name_taken) {
            // Trying again would only throw the other terminal out (or meet the same
            // version, or the same name): this one stops until asked.
            stopped_ = true;
            app_.reset();
            driver_ = nullptr;
            table_ = seat_ = rejoin_table_ = rejoin_seat_ = 0;
            message_ = m->code == hall::ErrorCode::replaced
                           ? name_ + " came into the hall from another terminal, which plays on; "
                                     "this one has stopped (r: take over here, q: quit)"
                           : "The hall said: " + words + " (q: quit)";
        } else if (!welcomed_) {
            message_ = "The hall said: " + words; // the server closes; the next try waits
        }
    } else if (std::holds_alternative<hall::LobbyBegin>(message)) {
        next_tables_.clear();
        next_players_.clear();
    } else if (const auto* m = std::get_if<hall::TableView>(&message)) {
        next_tables_.push_back(*m);
    } else if (const auto* m = std::get_if<hall::PlayerView>(&message)) {
        next_players_.push_back(*m);
    } else if (std::holds_alternative<hall::LobbyEnd>(message)) {
        // The marked row stays on its table as others come and go.
        const int marked = selected_ < static_cast<int>(tables_.size())
                               ? tables_[static_cast<std::size_t>(selected_)].number
                               : 0;
        tables_ = std::move(next_tables_);
        players_ = std::move(next_players_);
        next_tables_.clear();
        next_players_.clear();
        for (std::size_t i = 0; i < tables_.size(); ++i)
            if (tables_[i].number == marked)
                selected_ = static_cast<int>(i);
        selected_ = std::clamp(selected_, 0, std::max(0, static_cast<int>(tables_.size()) - 1));
        if (app_ && table_ != 0 && !table_view(table_)) {
            // The table closed under us (a game not started is not kept over a restart).
            message_ = "Table " + std::to_string(table_) + " is gone";
            app_.reset();
            driver_ = nullptr;
            table_ = seat_ = rejoin_table_ = rejoin_seat_ = 0;
        }
        show_seats();
    } else if (const auto* m = std::get_if<hall::Created>(&message)) {
        message_ = "Table " + std::to_string(m->table) + " is yours: waiting for an opponent";
        seat_computer_after_join_ = opponent_.has_value();
        send(hall::Sit{m->table, 1});
    } else if (const auto* m = std::get_if<hall::Joined>(&message)) {
        message_.clear();
        table_ = m->table;
        seat_ = m->seat;
        record_text_.clear();
        rejoin_table_ = rejoin_seat_ = 0;
        if (offer_ && offer_->table == m->table)
            offer_.reset();
        if (seat_ != 0 && seat_computer_after_join_) {
            send(hall::SeatComputer{3 - seat_, opponent_});
            seat_computer_after_join_ = false;
        }
    } else if (const auto* m = std::get_if<hall::RecordLine>(&message)) {
        if (m->table == table_)
            record_text_ += m->text + "\n";
    } else if (const auto* m = std::get_if<hall::RecordEnd>(&message)) {
        record_ended(*m);
    } else if (const auto* m = std::get_if<hall::Left>(&message)) {
        if (m->table == table_) {
            app_.reset();
            driver_ = nullptr;
            table_ = seat_ = 0;
        }
    } else if (const auto* m = std::get_if<hall::Yours>(&message)) {
        if (m->table != rejoin_table_ && m->table != table_ && !declined_.count(m->table))
            offer_ = *m;
    } else if (const auto* m = std::get_if<hall::SeatChange>(&message)) {
        if (app_ && m->table == table_)
            driver_->seat(m->seat, hall_seat_of(m->view));
    } else if (const auto* m = std::get_if<hall::ActionDone>(&message)) {
        if (app_ && m->table == table_)
            driver_->action(m->seq, m->hash, m->action);
    } else if (const auto* m = std::get_if<hall::AimShown>(&message)) {
        if (app_ && m->table == table_)
            driver_->aim(m->seat, m->strike);
    } else if (const auto* m = std::get_if<hall::ChatShown>(&message)) {
        if (app_ && m->table == table_)
            driver_->chat(m->name, m->text);
    }
}

void HallSession::record_ended(const hall::RecordEnd& end) {
    if (end.table != table_)
        return;
    const std::string text = std::exchange(record_text_, {});
    auto parsed = parse_record(text);
    std::optional<Match> match;
    if (const auto* record = std::get_if<GameRecord>(&parsed)) {
        auto replayed = Match::replay(*record);
        if (auto* m = std::get_if<Match>(&replayed))
            match = std::move(*m);
    }
    if (!match || match->record().actions.size() != end.seq || match->state_hash() != end.hash) {
        // Asking again would bring the same record: this build and the server's disagree.
        message_ = "Table " + std::to_string(end.table) +
                   " does not replay here as on the server (another termpool version?)";
        leave_table();
        return;
    }
    enter_table(std::move(*match));
}

void HallSession::enter_table(Match match) {
    if (app_) {
        driver_->record(std::move(match));
        show_seats();
        return;
    }
    GameOptions options;
    options.setup = match.record().setup;
    options.names[0] = match.record().names[0];
    options.names[1] = match.record().names[1];
    options.ascii = options_.ascii;
    options.seed = 1; // the App's own first game is replaced at once by the table's
    app_.emplace(term_, options);
    TableLink link;
    link.seat = seat_;
    link.act = [this](const RecordedAction& action) {
        if (!welcomed_) {
            driver_->refused("the hall is away; play it again once it is back");
            return;
        }
        aim_waiting_.reset(); // the shot is on its way: the cue before it is old news
        if (action.kind == RecordedAction::Kind::rack)
            send(hall::NextRack{});
        else
            send(hall::Act{action});
    };
    link.aim = [this](const Strike& strike) { aim_waiting_ = strike; };
    link.chat = [this, last = Clock::time_point{}](const std::string& text) mutable {
        const auto now = Clock::now();
        if (last != Clock::time_point{} && now - last < chat_interval)
            return false;
        last = now;
        send(hall::Chat{text});
        return true;
    };
    driver_ = &app_->join_hall(std::move(match), std::move(link));
    show_seats();
}

void HallSession::leave_table() {
    if (table_ != 0) {
        send(hall::Leave{});
        // The hall keeps a seat only in a game under way (HallCore::leave_table).
        const bool kept = seat_ != 0 && driver_ && driver_->match().under_way();
        message_ = "Back in the lobby from table " + std::to_string(table_) +
                   (kept ? " (a seat in a game under way waits for you)" : "");
    }
    app_.reset();
    driver_ = nullptr;
    table_ = seat_ = 0;
    rejoin_table_ = rejoin_seat_ = 0;
    aim_waiting_.reset();
}

void HallSession::show_seats() {
    if (!app_)
        return;
    if (const hall::TableView* t = table_view(table_))
        for (int s = 1; s <= 2; ++s)
            driver_->seat(s, hall_seat_of(t->seats[s - 1]));
}

const hall::TableView* HallSession::table_view(int number) const {
    for (const hall::TableView& t : tables_)
        if (t.number == number)
            return &t;
    return nullptr;
}

} // namespace termpool::tui
