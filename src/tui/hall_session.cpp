#include "tui/hall_session.hpp"

#include <algorithm>
#include <cstdio>
#include <termpool/race.hpp>
#include <variant>

#include "hall/autostart.hpp"
#include "hall/token_store.hpp"
#include "tui/ball_style.hpp"
#include "tui/player_name.hpp"

namespace termpool::tui {
namespace {

using namespace std::chrono_literals;

constexpr auto aim_interval = 50ms;  // the rate for the shooter's cue
constexpr auto chat_interval = 1s;   // the server refuses more (and counts it as an error)
constexpr int frame_ms = 16;         // while something moves
constexpr int lines_per_round = 500; // messages read before the screen is drawn again

HallSeat hall_seat_of(const hall::SeatView& seat) {
    return {seat.name, seat.kind == hall::SeatKind::away, seat.kind == hall::SeatKind::empty,
            seat.kind == hall::SeatKind::computer};
}

} // namespace

HallSession::HallSession(Terminal& terminal, HallOptions options)
    : term_(terminal), options_(std::move(options)) {
    if (options_.name) {
        name_ = *options_.name;
    } else {
        form_ = Form::name;
    }
}

int HallSession::run() {
    if (form_ != Form::name)
        connect();
    while (running_) {
        if (form_ != Form::name && !stopped_ && client_.closed() && Clock::now() >= retry_at_)
            connect();
        receive();
        if (app_) {
            app_->step();
            if (const auto copy = app_->take_sync_request())
                send(hall::Sync{copy->actions, copy->hash});
            if (!app_->running())
                leave_table();
        }
        flush_aim();
        const int w = term_.width(), h = term_.height();
        if (app_) {
            term_.draw(app_->frame(w, h));
        } else {
            LobbyView view;
            compose_lobby(view);
            term_.draw(render_lobby(view, term_.caps(), w, h));
        }
        Input in = term_.read(wait_ms(), client_.fd());
        // What has queued up is taken before the next frame, so that a fast mouse does not
        // lag behind and a burst of messages costs one frame.
        for (int n = 0; in.kind != Input::Kind::none && running_ && n < lines_per_round; ++n) {
            if (in.kind == Input::Kind::watched)
                receive();
            else
                handle(in);
            if (in.kind == Input::Kind::signal)
                break;
            in = term_.read(0, client_.fd());
        }
    }
    // A seat in a game under way waits for us (the server marks it away); nothing to save.
    client_.disconnect();
    return 0;
}

int HallSession::wait_ms() const {
    if (app_ && app_->moving())
        return frame_ms;
    if (aim_waiting_)
        return static_cast<int>(aim_interval.count());
    if (form_ != Form::name && !stopped_ && client_.closed()) {
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(retry_at_ - Clock::now());
        return static_cast<int>(std::clamp<long long>(left.count(), 0, 1000));
    }
    return 1000; // the clock in a waiting message, at most
}

void HallSession::connect() {
    // The hall is started when none answers, at the first try and after a server went away
    // (it restores its tables): a second terminal doing the same at once finds it locked.
    std::string started_log;
    const std::string why =
        hall::connect_or_start(client_, options_.socket_path, options_.self_exe, started_log);
    if (!why.empty()) {
        lost_connection(why);
        return;
    }
    client_.keep_copies(false); // the App plays every action itself
    welcomed_ = false;
    if (token_.empty())
        token_ = hall::load_token(options_.token_dir, name_);
    send(hall::Hello{hall::protocol_version, token_, name_});
}

void HallSession::lost_connection(const std::string& why) {
    client_.disconnect();
    welcomed_ = false;
    if (stopped_)
        return; // the message says why, and r tries again
    if (app_ && table_ != 0) {
        rejoin_table_ = table_;
        rejoin_seat_ = seat_;
    }
    const auto wait = backoff_.next();
    retry_at_ = Clock::now() + wait;
    char delay[32];
    std::snprintf(delay, sizeof delay, "%.2g", std::chrono::duration<double>(wait).count());
    message_ = "The hall is away (" + why + "); trying again in " + delay + " s (r: now)";
    if (app_)
        app_->hall_notice(std::string("The hall is away: trying again in ") + delay +
                          " s; your seat waits");
}

void HallSession::receive() {
    if (client_.closed())
        return;
    for (int n = 0; n < lines_per_round; ++n) {
        if (auto message = client_.receive(0ms))
            dispatch(*message);
        else if (!client_.line_waiting())
            break;
    }
    if (client_.closed() && !client_.line_waiting())
        lost_connection("the connection closed");
}

void HallSession::send(const hall::ClientMessage& message) {
    if (!client_.closed())
        client_.send(message);
}

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
            app_->hall_refused(words);
        else
            message_ = "The hall said: " + words;
        if (m->code == hall::ErrorCode::replaced || m->code == hall::ErrorCode::version) {
            // Trying again would only throw the other terminal out (or meet the same
            // version): this one stops until asked.
            stopped_ = true;
            app_.reset();
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
            table_ = seat_ = 0;
        }
    } else if (const auto* m = std::get_if<hall::Yours>(&message)) {
        if (m->table != rejoin_table_ && m->table != table_ && !declined_.count(m->table))
            offer_ = *m;
    } else if (const auto* m = std::get_if<hall::SeatChange>(&message)) {
        if (app_ && m->table == table_)
            app_->hall_seat(m->seat, hall_seat_of(m->view));
    } else if (const auto* m = std::get_if<hall::ActionDone>(&message)) {
        if (app_ && m->table == table_)
            app_->hall_action(m->seq, m->hash, m->action);
    } else if (const auto* m = std::get_if<hall::AimShown>(&message)) {
        if (app_ && m->table == table_)
            app_->hall_aim(m->seat, m->strike);
    } else if (const auto* m = std::get_if<hall::ChatShown>(&message)) {
        if (app_ && m->table == table_)
            app_->hall_chat(m->name, m->text);
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
        app_->hall_record(std::move(match));
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
            app_->hall_refused("the hall is away; play it again once it is back");
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
    app_->join_hall(std::move(match), std::move(link));
    show_seats();
}

void HallSession::leave_table() {
    if (table_ != 0) {
        send(hall::Leave{});
        message_ = "Back in the lobby from table " + std::to_string(table_) +
                   (seat_ != 0 ? " (a seat in a game under way waits for you)" : "");
    }
    app_.reset();
    table_ = seat_ = 0;
    rejoin_table_ = rejoin_seat_ = 0;
    aim_waiting_.reset();
}

void HallSession::show_seats() {
    if (!app_)
        return;
    if (const hall::TableView* t = table_view(table_))
        for (int s = 1; s <= 2; ++s)
            app_->hall_seat(s, hall_seat_of(t->seats[s - 1]));
}

const hall::TableView* HallSession::table_view(int number) const {
    for (const hall::TableView& t : tables_)
        if (t.number == number)
            return &t;
    return nullptr;
}

void HallSession::flush_aim() {
    const auto now = Clock::now();
    if (!aim_waiting_ || !welcomed_ || now - aim_sent_at_ < aim_interval)
        return;
    send(hall::Aim{*aim_waiting_});
    aim_waiting_.reset();
    aim_sent_at_ = now;
}

void HallSession::handle(const Input& in) {
    if (in.kind == Input::Kind::signal) {
        running_ = false;
        return;
    }
    if (form_ == Form::name) {
        handle_name_key(in);
        return;
    }
    if (app_) {
        app_->handle(in);
        return;
    }
    if (form_ == Form::create) {
        handle_create_key(in);
        return;
    }
    handle_lobby_key(in);
}

void HallSession::handle_name_key(const Input& in) {
    if (entry_.edit(in) || in.kind != Input::Kind::key)
        return;
    if (in.key == key_escape) {
        running_ = false;
        return;
    }
    if (in.key != key_enter)
        return;
    std::string error;
    const auto name = clean_player_name(entry_.text, error);
    if (!name) {
        entry_.error = error.empty() ? "a name, please" : error;
        return;
    }
    name_ = *name;
    entry_.clear();
    form_ = Form::none;
    connect();
}

void HallSession::handle_create_key(const Input& in) {
    const std::string& t = in.kind == Input::Kind::text ? in.text : std::string();
    const int key = in.kind == Input::Kind::key ? in.key : 0;
    if (key == key_escape || t == "q") {
        form_ = Form::none;
    } else if (key == key_enter) {
        form_ = Form::none;
        send(create_);
    } else if (t == "g") {
        create_.game = create_.game == GameType::eight_ball       ? GameType::eight_ball_bar
                       : create_.game == GameType::eight_ball_bar ? GameType::nine_ball
                                                                  : GameType::eight_ball;
    } else if (t == "t") {
        create_.size = create_.size == TableSize::nine_foot    ? TableSize::seven_foot
                       : create_.size == TableSize::seven_foot ? TableSize::eight_foot
                                                               : TableSize::nine_foot;
    } else if (t == "+" || key == key_right || key == key_up) {
        create_.race_to = std::min(max_race_to, create_.race_to + 1);
    } else if (t == "-" || key == key_left || key == key_down) {
        create_.race_to = std::max(1, create_.race_to - 1);
    } else if (t == "o") {
        // A person, then each computer level, then a person again.
        if (!opponent_)
            opponent_ = Level::easy;
        else if (*opponent_ == Level::pro)
            opponent_.reset();
        else
            opponent_ = static_cast<Level>(static_cast<int>(*opponent_) + 1);
    }
}

void HallSession::handle_lobby_key(const Input& in) {
    const std::string& t = in.kind == Input::Kind::text ? in.text : std::string();
    const int key = in.kind == Input::Kind::key ? in.key : 0;
    const int count = static_cast<int>(tables_.size());
    if (offer_) {
        if (key == key_enter || t == "y") {
            send(hall::Sit{offer_->table, offer_->seat});
            offer_.reset();
            return;
        }
        if (key == key_escape || t == "n") {
            declined_.insert(offer_->table);
            offer_.reset();
            return;
        }
    }
    if (in.kind == Input::Kind::mouse) {
        // A click marks a table, a click on the marked one sits (as Enter).
        if (!in.pressed && !in.clicked)
            return;
        LobbyView view;
        compose_lobby(view);
        const int row = lobby_table_at(view, term_.height(), in.y);
        if (row >= 0) {
            if (row == selected_)
                sit_selected(0);
            selected_ = row;
        }
        return;
    }
    if (t == "q") {
        running_ = false;
    } else if (key == key_up || t == "k") {
        selected_ = std::max(0, selected_ - 1);
    } else if (key == key_down || t == "j") {
        selected_ = std::min(std::max(0, count - 1), selected_ + 1);
    } else if (t == "c") {
        form_ = Form::create;
    } else if (key == key_enter) {
        sit_selected(0);
    } else if (t == "1" || t == "2") {
        sit_selected(t[0] - '0');
    } else if (t == "w" && selected_ < count) {
        send(hall::Watch{tables_[static_cast<std::size_t>(selected_)].number});
    } else if (t == "r" && client_.closed()) {
        stopped_ = false;
        retry_at_ = Clock::now(); // try again now
    }
}

void HallSession::sit_selected(int seat) {
    if (selected_ >= static_cast<int>(tables_.size()))
        return;
    const hall::TableView& t = tables_[static_cast<std::size_t>(selected_)];
    if (seat == 0) {
        // Enter: our own away seat, else the first empty one, else watch.
        for (int s = 1; s <= 2 && seat == 0; ++s)
            if (t.seats[s - 1].kind == hall::SeatKind::away && t.seats[s - 1].name == name_)
                seat = s;
        for (int s = 1; s <= 2 && seat == 0; ++s)
            if (t.seats[s - 1].kind == hall::SeatKind::empty)
                seat = s;
    }
    if (seat == 0)
        send(hall::Watch{t.number});
    else
        send(hall::Sit{t.number, seat});
}

std::string HallSession::create_form_text() const {
    const std::string opponent =
        opponent_ ? std::string("the computer (") + level_name(*opponent_) + ")" : "a person";
    return "A new table\n\n"
           "g  game      " +
           std::string(game_title(create_.game)) +
           "\n"
           "t  table     " +
           table_size_name(create_.size) +
           "\n"
           "+- race to   " +
           std::to_string(create_.race_to) + (create_.race_to == 1 ? " (a single game)" : "") +
           "\n"
           "o  opponent  " +
           opponent + "\n\nEnter creates it, Esc goes back";
}

void HallSession::compose_lobby(LobbyView& v) const {
    v.name = name_;
    v.tables = tables_;
    v.players = players_;
    v.selected = selected_;
    v.connected = welcomed_;
    v.message = message_;
    if (form_ == Form::name) {
        v.name = "";
        v.overlay = "termpool hall\n\nYour name: " + entry_.text + "_" +
                    (entry_.error.empty() ? "" : "\n" + entry_.error) +
                    "\n\nEnter goes in, Esc leaves";
    } else if (form_ == Form::create) {
        v.overlay = create_form_text();
    } else if (offer_) {
        v.overlay = "Your seat at table " + std::to_string(offer_->table) +
                    " waits for you.\n\nEnter  sit down and play on\nEsc    not now";
    } else if (!welcomed_ && !ever_connected_) {
        v.overlay = "Connecting to the hall...\n\n" + message_;
    }
}

} // namespace termpool::tui
