#pragma once
// The game loop: modes (names, ball in hand, aiming, the shot, choices, game over), input
// handling and the View each frame is drawn from. Curses stays in terminal.cpp.

#include <chrono>
#include <optional>
#include <string>
#include <termpool/computer.hpp>
#include <termpool/practice.hpp>
#include <termpool/record.hpp>
#include <termpool/rules.hpp>
#include <termpool/simulator.hpp>
#include <termpool/stats.hpp>

#include "tui/aim.hpp"
#include "tui/options.hpp"
#include "tui/terminal.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// A saved game or match as it stands, replayed once by whoever read the save.
struct ResumedGame {
    ReplayedMatch match; ///< the current rack, the score and who broke it
    StatsTally tally;    ///< the players' figures so far
};

/// One session at the table.
class App {
public:
    /// A new session with the command line's presets.
    App(Terminal& terminal, const GameOptions& options);
    /// Runs until the players quit or a signal arrives; returns the exit status.
    int run();
    /// Continues a saved game (or match): `record`, and `state`, what it replayed to.
    void resume(const GameRecord& record, ResumedGame state);
    /// Plays a saved game back instead of playing: space pauses, Left/Right step a shot.
    void start_replay(const GameRecord& record);

private:
    enum class Mode { names, placing, aiming, animating, choosing, game_over, replay, moving };
    using Clock = std::chrono::steady_clock;

    void new_game(int breaker);
    void next_rack();
    void start_rack(const RecordedAction& rack);
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
    bool place(Vec2 spot);
    void choose(Choice choice);
    void save();
    void rewind_to(std::size_t action);
    bool replay_from(const GameRecord& record);
    std::string resumed_words() const;
    void replay_step();
    void handle_replay_key(const Input& in);
    bool computer_to_act() const;
    bool computers_watched_rack_over() const;
    void seat_computer(int player, Level level);
    int actor() const;
    void computer_turn();
    void compose(View& view) const;
    Grid frame(int width, int height);
    void handle(const Input& in);
    void handle_key(int key, const std::string& text);
    void handle_mouse(const Input& in);
    void handle_text_entry(const Input& in);
    void ask_race();
    void handle_race_entry(const Input& in);
    void update_preview();
    void aim_at_easiest();
    double current_power() const;
    Vec2 cue_position() const;
    std::vector<int> targets() const;
    bool calls_pocket(int target) const;

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

    Terminal& term_;
    GameOptions options_;
    Table table_;
    PhysicsParams params_;
    Game game_;
    std::uint64_t seed_;
    std::string names_[2] = {"Player 1", "Player 2"};
    Mode mode_ = Mode::names;
    Layout layout_;
    bool running_ = true;

    // Text entry (names at the start, `n` to rename).
    int entry_player_ = 0; // 1 or 2 while a name is being typed
    std::string entry_;
    std::string entry_error_;
    bool asking_race_ = false; // the name prompt's last question: the race length

    // Overlays.
    bool help_ = false;
    int help_page_ = 0;
    bool confirm_quit_ = false;

    // Aiming.
    double aim_deg_ = 0;
    double power_ = 0.3;
    double power_before_break_ = -1; // the power to return to after a break, -1: none held
    bool time_power_ = false;
    Clock::time_point power_start_;
    double side_ = 0, follow_ = 0;
    bool show_aid_ = true;
    bool show_marker_ = false;
    Vec2 marker_;
    bool dragging_ = false;
    bool drag_moved_ = false;
    int called_pocket_ = 0;
    bool pocket_chosen_ = false; // the player picked the pocket: keep it while aiming
    bool safety_ = false;
    bool push_out_ = false; // 9-ball: this shot is a push-out
    int target_index_ = -1;
    TargetLine target_line_ = TargetLine::straight; // how the proposed aim reaches its ball
    int preview_ball_ = -1;
    View preview_; // aiming aid paths

    // Ball in hand.
    Vec2 place_;

    // Practice: the table, and the ball being moved (-1: none held) with where it came from.
    std::optional<PracticeTable> practice_;
    int held_ball_ = -1;
    Vec2 held_at_;

    // The shot being shown.
    std::optional<Trajectory> trajectory_;
    ShotResult result_;
    ShotCall call_;
    Strike last_strike_; // practice: `r` sets it up again
    int shooter_before_ = 1;
    Clock::time_point shot_start_;
    std::vector<Ball> shown_balls_;

    // The computer in each seat, if any, and the move it is showing.
    std::optional<ComputerPlayer> computers_[2];
    bool planning_ = false;
    Clock::time_point plan_start_;
    std::optional<ComputerShot> plan_;
    double aim_from_ = 0;

    GameRecord record_; // everything done so far, as saved
    MatchState match_;  // the race and the racks won
    int rack_ = 1;      // the current rack's number
    int rack_breaker_ = 1;
    StatsTally tally_;          // the players' figures in this game or match
    bool break_before_ = false; // the shot being shown is a break
    bool replaying_ = false;
    bool paused_ = false;
    std::size_t next_action_ = 0; // replay: the next action of record_ to show

    std::string message_;
    std::string save_problem_;       // why the last save failed, shown until one works
    Clock::time_point game_over_at_; // when the last rack ended
};

} // namespace termpool::tui
