#pragma once
// `termpool hall`: one person's terminal in the pool hall. It asks the name, connects to the
// hall's server (starting one when none runs), shows the lobby, and at a table hands the
// screen to an App that plays the server's actions. One loop waits on the keyboard and the
// socket together; a server that goes away is tried again with backoff, and the seat and the
// table come back where they stood. hall_session.cpp has the loop and the connection,
// hall_session_messages.cpp what the server says, hall_session_lobby.cpp the lobby's keys.

#include <chrono>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "hall/client.hpp"
#include "hall/reconnect_backoff.hpp"
#include "tui/app.hpp"
#include "tui/lobby_view.hpp"
#include "tui/terminal.hpp"
#include "tui/text_entry.hpp"

namespace termpool::tui {

/// How `termpool hall` was asked to run.
struct HallOptions {
    std::optional<std::string> name; ///< --name NAME (cleaned), else asked
    std::string socket_path;         ///< --socket PATH, else the default
    bool ascii = false;              ///< --ascii: plain ASCII and no colour
    std::string self_exe;            ///< this program, to start a server with
    std::string token_dir;           ///< where the seat tokens are kept, per name
};

/// One terminal in the hall, from the name prompt until the player quits.
class HallSession {
public:
    /// A session on `terminal`.
    HallSession(Terminal& terminal, HallOptions options);
    // The table's App holds callbacks into this session: it stays where it was made.
    HallSession(const HallSession&) = delete;
    HallSession& operator=(const HallSession&) = delete;
    /// Runs until the player quits or a signal arrives; 0, or 1 when the hall at the socket
    /// was refused (refusal()).
    int run();
    /// Why the hall at the socket was not trusted (its folder, socket or server is not this
    /// user's: hall::HallReach::refused), or "".
    const std::string& refusal() const { return refusal_; }

private:
    using Clock = std::chrono::steady_clock;
    enum class Form { none, name, create };

    void connect();
    void lost_connection(const std::string& why);
    void receive();
    void dispatch(const hall::ServerMessage& message);
    void record_ended(const hall::RecordEnd& end);
    void enter_table(Match match);
    void leave_table();
    void send(const hall::ClientMessage& message);
    void flush_aim();
    void handle(const Input& in);
    void handle_lobby_key(const Input& in);
    void handle_name_key(const Input& in);
    void handle_create_key(const Input& in);
    void sit_selected(int seat);
    void compose_lobby(LobbyView& view) const;
    const hall::TableView* table_view(int number) const;
    void show_seats();
    std::string create_form_text() const;
    int wait_ms() const;

    Terminal& term_;
    HallOptions options_;
    std::string name_;
    hall::HallClient client_;
    std::string token_;
    bool running_ = true;
    bool welcomed_ = false;
    bool ever_connected_ = false;
    bool stopped_ = false; // replaced by another terminal, or another version: no more tries
    std::string refusal_;  // the hall is not this user's: the session ends, saying why

    // The hall: the lobby's last snapshot (and the one being read), what is marked.
    std::vector<hall::TableView> tables_, next_tables_;
    std::vector<hall::PlayerView> players_, next_players_;
    int selected_ = 0;
    std::string message_;
    std::optional<hall::Yours> offer_; // a seat of ours that waits, not taken up yet
    std::set<int> declined_;           // tables whose offer was turned down: not asked again

    // The questions: the name, and a new table's settings.
    Form form_ = Form::none;
    TextEntry entry_;
    hall::Create create_;
    std::optional<Level> opponent_; // the new table's seat 2: a computer at this level
    bool seat_computer_after_join_ = false;

    // The table: its number and our seat (0 watching), its record as it comes, the App that
    // shows it. A table we were at when the connection went is taken up again after it.
    int table_ = 0;
    int seat_ = 0;
    std::string record_text_;
    std::optional<App> app_;
    HallDriver* driver_ = nullptr; // app_'s table driver, which the server's news goes to
    int rejoin_table_ = 0;
    int rejoin_seat_ = 0;

    // The cue as we aim it goes out at most every 50 ms: the newest waits its turn.
    std::optional<Strike> aim_waiting_;
    Clock::time_point aim_sent_at_;

    // Reconnecting: when the next try is due, and the schedule of the waits.
    Clock::time_point retry_at_;
    hall::ReconnectBackoff backoff_;
};

/// `termpool hall [--name NAME] [--socket PATH] [--ascii]`; the exit status.
int run_hall(const std::vector<std::string>& args);

} // namespace termpool::tui
