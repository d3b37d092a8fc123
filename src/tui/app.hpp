#pragma once
// The session at the table: its modes (names, ball in hand, aiming, the shot, choices, game
// over, replay, practice) turn input into the Match's actions and the state into the View each
// frame is drawn from. The game's flow is the Match's; curses stays in terminal.cpp.

#include <chrono>
#include <optional>
#include <string>
#include <termpool/match.hpp>
#include <termpool/practice.hpp>

#include "tui/aim_state.hpp"
#include "tui/computer_pacing.hpp"
#include "tui/options.hpp"
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

private:
    enum class Mode { names, placing, aiming, animating, choosing, game_over, replay, moving };
    using Clock = std::chrono::steady_clock;

    const Game& game() const;
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
    void compose(View& view) const;
    void compose_aiming(View& view) const;
    void compose_prompt(View& view) const;
    Grid frame(int width, int height);
    void handle(const Input& in);
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
    void aim_at_easiest();
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

    AimState aim_;
    Vec2 place_; // ball in hand: where the cue ball would go

    // Practice: its table, read through a Game without referee state, and the ball being
    // moved (-1: none held) with where it is held.
    std::optional<PracticeTable> practice_;
    std::optional<Game> practice_game_;
    int held_ball_ = -1;
    Vec2 held_at_;

    // The shot being shown: the match has judged it already, and shows the game as it was
    // until the balls stop.
    std::optional<Trajectory> trajectory_;
    ShotResult result_;
    Verdict verdict_;
    std::optional<Game> before_shot_;
    MatchState score_before_;
    Strike last_strike_; // practice: `r` sets it up again
    int shooter_before_ = 1;
    Clock::time_point shot_start_;
    std::vector<Ball> shown_balls_;

    ComputerPacing pacing_; // the computer's move being shown

    GameRecord replay_record_; // replay: the whole record being shown
    bool replaying_ = false;
    bool paused_ = false;
    std::size_t next_action_ = 0; // replay: the next action of replay_record_ to show

    std::string message_;
    std::string save_problem_;       // why the last save failed, shown until one works
    Clock::time_point game_over_at_; // when the last rack ended
};

} // namespace termpool::tui
