#pragma once
// The session at the table: its modes (names, ball in hand, aiming, the shot, choices, game
// over, replay, practice) turn input into the Match's actions and the state into the View each
// frame is drawn from. The game's flow is the Match's; curses stays in terminal.cpp.

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <termpool/match.hpp>
#include <termpool/practice.hpp>
#include <utility>
#include <vector>

#include "player/options.hpp"
#include "tui/aim_state.hpp"
#include "tui/computer_pacing.hpp"
#include "tui/shot_show.hpp"
#include "tui/table_link.hpp"
#include "tui/terminal.hpp"
#include "tui/text_entry.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// One session at the table.
class App {
public:
    /// A new session with the command line's presets.
    App(Terminal& terminal, const GameOptions& options);
    /// Runs until the players quit or a signal arrives; returns the exit status.
    int run();
    /// Continues a saved game (or match), replayed to where its record stands.
    void resume(Match match);
    /// Plays a saved game back instead of playing: space pauses, Left/Right step a shot.
    void start_replay(const GameRecord& record);

    // The loop's parts, for a front end with a loop of its own (the hall's).
    /// Moves time on: the shot rolling, the computer's or the hall's next move.
    void step();
    /// The frame to draw at this size.
    Grid frame(int width, int height);
    /// One input event.
    void handle(const Input& in);
    /// False once the players quit (in the hall: leave the table).
    bool running() const { return running_; }
    /// True while something moves on screen by itself: frames are due often.
    bool moving() const;

    // A table in the hall (app_hall.cpp): the server owns the match; this App shows the
    // server's actions as they come and sends what the player here does through `link`.
    /// Takes up the hall's table at `match`, playing `link.seat` (0: watching).
    void join_hall(Match match, TableLink link);
    /// The whole table again, from the server's record (after a mismatch or a reconnect).
    void hall_record(Match match);
    /// The server applied `action` as the table's action `seq`, giving state `hash`.
    void hall_action(std::size_t seq, std::uint64_t hash, const RecordedAction& action);
    /// The shooter in `seat` aims so.
    void hall_aim(int seat, const Strike& strike);
    /// A chat line at the table.
    void hall_chat(const std::string& name, const std::string& text);
    /// Who sits in `seat` (1 or 2) now.
    void hall_seat(int seat, const HallSeat& who);
    /// The server refused what this terminal sent.
    void hall_refused(const std::string& why);
    /// A word from the hall for the message line (the connection went or came back).
    void hall_notice(const std::string& text);
    /// Once (then nothing) after the local copy disagreed with the server's: where the copy
    /// stood; ask for the record.
    std::optional<CopyState> take_sync_request() { return std::exchange(sync_wanted_, {}); }

private:
    enum class Mode { names, placing, aiming, animating, choosing, game_over, replay, moving };
    using Clock = std::chrono::steady_clock;

    const Game& game() const;
    /// The cue of the seat at the table now (the shooter shown).
    AimState& aim() { return aims_[game().shooter() == 2 ? 1 : 0]; }
    const AimState& aim() const { return aims_[game().shooter() == 2 ? 1 : 0]; }
    const MatchState& score() const;
    const std::string& name(int player) const { return match_.name(player); }
    void new_game(int breaker);
    void next_rack();
    std::string game_over_text() const;
    void save_stats();
    void after_shot();
    void begin();
    void start_turn();
    void start_aiming();
    void warn_of_third_foul();
    bool try_place(Vec2 spot);
    bool nudge(Vec2& spot, int key, const std::string& text) const;
    void shoot();
    void play(const Strike& strike, const ShotCall& call);
    void show_shot(PlayedShot shot, Trajectory trajectory, MatchState score_before,
                   std::optional<Game> before);
    bool place(Vec2 spot);
    void choose(Choice choice);
    void save();
    void rewind_to(std::size_t action);
    std::string resumed_words() const;
    void replay_step();
    void handle_replay_key(const Input& in);
    bool computer_to_act() const;
    bool computers_watched_rack_over() const;
    void seat_computer(int player, Level level);
    void computer_turn();
    bool show_computer_aim(Clock::time_point now);
    void compose(View& view) const;
    void compose_aiming(View& view) const;
    void compose_prompt(View& view) const;
    bool handle_overlay(const Input& in);
    void handle_key(int key, const std::string& text);
    void handle_aiming_key(int key, const std::string& text);
    void handle_mouse(const Input& in);
    void handle_aiming_mouse(const Input& in);
    void handle_text_entry(const Input& in);
    void take_name();
    void ask_race();
    void handle_race_entry(const Input& in);
    void update_preview();
    void propose_nomination();
    bool nominate_key(const std::string& text);
    bool snooker_play() const;
    void ask_concede();
    void concede();
    std::string breaks_words(int breaker) const;
    void aim_at_easiest();
    Vec2 cue_position() const;
    std::vector<int> targets() const;
    bool calls_pocket(int target) const;

    // What happened (app_log.cpp): the verdict line and the rack's log.
    void tell(std::string news);
    void player_acts();
    std::string said() const;
    void open_log();
    bool handle_log(const Input& in);
    std::string log_page_text() const;

    // Practice (app_practice.cpp): no referee, any ball moved, the last shot taken again.
    void sync_practice();
    void practice_shot_done();
    bool handle_practice_key(const std::string& text);
    void start_moving();
    void hold_ball(int id);
    void put_down(Vec2 spot);
    void handle_moving_key(int key, const std::string& text);
    void handle_moving_mouse(const Input& in);
    void compose_moving(View& view) const;

    // The hall (app_hall.cpp).
    bool in_hall() const { return link_.has_value(); }
    void take_hall_table(Match match);
    std::string hall_table_words() const;
    bool hall_seat_to_act() const;
    bool hall_waits() const;
    bool send_to_hall(const RecordedAction& action);
    void apply_hall_actions();
    bool apply_hall_action(const RecordedAction& action);
    void send_hall_aim();
    bool handle_hall_key(const Input& in);
    void compose_hall(View& view) const;
    std::string hall_game_over_text() const;

    Terminal& term_;
    GameOptions options_;
    Table table_;
    PhysicsParams params_;
    std::uint64_t seed_;
    Match match_; // the game or match: seats, rack, score, record, figures
    Mode mode_ = Mode::names;
    Layout layout_;
    bool running_ = true;

    TextEntry entry_; // names at the start, `n` to rename, the race's length

    // Overlays.
    bool help_ = false;
    int help_page_ = 0;
    bool confirm_quit_ = false;
    bool confirm_concede_ = false; // snooker: "Concede the frame?" waits for y or n

    // Each seat's cue as it was last set: the computer's or the other terminal's shot turns
    // its own seat's cue, never what the player here set.
    AimState aims_[2];
    Vec2 place_; // ball in hand: where the cue ball would go

    // Practice: its table, read through a Game without referee state, and the ball being
    // moved (-1: none held) with where it is held.
    std::optional<PracticeTable> practice_;
    std::optional<Game> practice_game_;
    int held_ball_ = -1;
    Vec2 held_at_;

    ShotShow show_;      // the shot rolling on screen
    Strike last_strike_; // practice: `r` sets it up again

    ComputerPacing pacing_; // the computer's move being shown

    GameRecord replay_record_; // replay: the whole record being shown
    bool replaying_ = false;
    bool paused_ = false;
    std::size_t next_action_ = 0; // replay: the next action of replay_record_ to show

    // The hall: where this terminal's actions go, the server's actions not shown yet, the
    // seats as the hall sees them, the table's chat and the line being typed into it.
    struct HallAction {
        std::size_t seq = 0;
        std::uint64_t hash = 0;
        RecordedAction action;
    };
    std::optional<TableLink> link_;
    std::deque<HallAction> hall_queue_;
    bool awaiting_hall_ = false; // an action of ours is on its way to the server
    std::optional<CopyState> sync_wanted_;
    bool resyncing_ = false; // the record was asked for: actions wait for it
    HallSeat hall_seats_[2];
    std::vector<std::string> chat_;
    std::optional<TextEntry> chat_entry_;
    std::optional<Strike> aim_sent_;

    std::string message_; // hints and prompts: whatever comes next replaces them
    std::string notice_;  // the hall's word on the connection: first, until the table is back
    // The last shot's verdict and what followed (the computer's or the other terminal's own
    // verdicts and choices): shown until the player here acts again.
    std::vector<std::string> verdicts_;
    // The rack's log while it is open: its lines and the page shown.
    std::optional<std::vector<std::string>> log_;
    int log_page_ = 0;
    std::string save_problem_;       // why the last save failed, shown until one works
    Clock::time_point game_over_at_; // when the last rack ended
};

} // namespace termpool::tui
