// The lobby's keys and questions: the name prompt, the new table's form, the seat offer, the
// marked table and what Enter, 1, 2, w and a click do with it; and the LobbyView drawn.
#include <algorithm>
#include <termpool/game_registry.hpp>
#include <termpool/race.hpp>

#include "player/player_name.hpp"
#include "tui/ball_style.hpp"
#include "tui/hall_session.hpp"

namespace termpool::tui {

void HallSession::handle_name_key(const Input& in) {
    // Keys past the widest name are not taken: the name would be cut there.
    const auto room = [&](const std::string& typed) { return name_has_room(entry_.text, typed); };
    if (entry_.edit(in, room) || in.kind != Input::Kind::key)
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
        const GameRow& next = game_registry().next(create_.game);
        create_.game = next.type;
        // Snooker is played on the snooker table, and pool on a pool table.
        if (next.table)
            create_.size = *next.table;
        else if (create_.size == TableSize::snooker)
            create_.size = TableSize::nine_foot;
    } else if (t == "t" && game_row(create_.game).table) {
        create_.size = *game_row(create_.game).table; // the only table for the game
    } else if (t == "t") {
        create_.size = create_.size == TableSize::nine_foot    ? TableSize::seven_foot
                       : create_.size == TableSize::seven_foot ? TableSize::eight_foot
                       : create_.size == TableSize::eight_foot ? TableSize::snooker
                                                               : TableSize::nine_foot;
    } else if (t == "+" || key == key_right || key == key_up) {
        create_.race_to = std::min(max_race_to, create_.race_to + 1);
    } else if (t == "-" || key == key_left || key == key_down) {
        create_.race_to = std::max(1, create_.race_to - 1);
    } else if (t == "a") {
        // Both seats play with it: standard, pro, guided, standard again.
        create_.assist = create_.assist == Assist::standard ? Assist::pro
                         : create_.assist == Assist::pro    ? Assist::guided
                                                            : Assist::standard;
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
           table_size_name(create_.size) + "\n" +
           (game_row(create_.game).scoring == Scoring::points
                ? "+- best of   " + std::to_string(best_of_for_race(create_.race_to)) +
                      (create_.race_to == 1 ? " (a single frame)" : " frames")
                : "+- race to   " + std::to_string(create_.race_to) +
                      (create_.race_to == 1 ? " (a single game)" : "")) +
           "\n"
           "a  assist    " +
           assist_name(create_.assist) +
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
