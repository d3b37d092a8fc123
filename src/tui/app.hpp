#pragma once
// The session at the table: its modes (names, ball in hand, aiming, the shot rolling, choices,
// the rack over) turn input into actions for one table driver, and the driver's state into the
// View each frame is drawn from. Local play, the hall, a replay and practice differ only in
// their driver (table_driver.hpp); curses stays in terminal.cpp.

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <termpool/match.hpp>
#include <vector>

#include "player/options.hpp"
#include "tui/aim_state.hpp"
#include "tui/computer_pacing.hpp"
#include "tui/hall_driver.hpp"
#include "tui/rack_log.hpp"
#include "tui/shot_show.hpp"
#include "tui/table_driver.hpp"
#include "tui/table_modes.hpp"
#include "tui/terminal.hpp"
#include "tui/text_entry.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// One session at the table.
class App {
public:
    /// A new session with the command line's presets (a game, or practice).
    App(Terminal& terminal, const GameOptions& options);
    /// Runs until the players quit or a signal arrives; returns the exit status.
    int run();
    /// Continues a saved game (or match), replayed to where its record stands.
    void resume(Match match);
    /// Plays a saved game back instead of playing: space pauses, Left/Right step a shot.
    void start_replay(const GameRecord& record);
    /// Takes up the hall's table at `match`, playing `link.seat` (0: watching); the hall
    /// session feeds the server's news to the driver returned, which lives as long as the App.
    HallDriver& join_hall(Match match, TableLink link);

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

private:
    using Clock = std::chrono::steady_clock;

    /// The mode now, when it is an `M` (null otherwise).
    template <class M> M* as() { return std::get_if<M>(&mode_); }
    template <class M> const M* as() const { return std::get_if<M>(&mode_); }

    void use(std::unique_ptr<TableDriver> driver);
    const Game& game() const;
    const MatchState& score() const;
    const std::string& name(int player) const { return driver_->match().name(player); }
    /// The cue of the seat at the table now (the shooter shown).
    AimState& aim() { return aims_[game().shooter() == 2 ? 1 : 0]; }
    const AimState& aim() const { return aims_[game().shooter() == 2 ? 1 : 0]; }
    ScreenFacts screen() const;
    bool snooker_play() const;

    // The turn (app_turn.cpp).
    void begin();
    void start_turn();
    void start_aiming();
    void warn_of_third_foul();
    void act(const RecordedAction& action);
    void show(TableNews news);
    void after_shot();
    void take_upcoming(Clock::time_point now);
    bool pace(const Upcoming& next, Clock::time_point now);
    void try_place(Vec2 spot);
    void shoot();
    void ask_concede();
    void concede();

    // Input (app.cpp, app_aim.cpp).
    void handle_key(int key, const std::string& text);
    void on_key(NamesMode&, int, const std::string&) {}
    void on_key(PlacingMode& placing, int key, const std::string& text);
    void on_key(AimingMode&, int key, const std::string& text);
    void on_key(RollingMode& rolling, int key, const std::string& text);
    void on_key(ChoosingMode&, int key, const std::string& text);
    void on_key(OverMode&, int key, const std::string& text);
    void handle_mouse(const Input& in);
    void handle_aiming_mouse(const Input& in);
    void apply(const DriverReply& reply);
    void aim_at_easiest();
    void update_preview();
    bool nominate_key(const std::string& text);
    Vec2 cue_position() const;

    // The View (app_view.cpp).
    void compose(View& view) const;
    void compose_mode(const NamesMode&, View&) const {}
    void compose_mode(const PlacingMode& placing, View& view) const;
    void compose_mode(const AimingMode&, View& view) const;
    void compose_mode(const RollingMode&, View&) const {}
    void compose_mode(const ChoosingMode&, View& view) const;
    void compose_mode(const OverMode&, View& view) const;
    void compose_prompt(View& view) const;

    // The prompts (app_prompt.cpp): names, the computer, the race.
    void handle_text_entry(const Input& in);
    void take_name();
    void ask_race();
    void handle_race_entry(const Input& in);

    // What happened (app_log.cpp): the verdict line, the rack's log and the other boxes.
    void tell(std::string news);
    void player_acts();
    std::string said() const;
    void open_log();
    bool handle_log(const Input& in);
    std::string log_page_text() const;
    bool handle_overlay(const Input& in);

    Terminal& term_;
    GameOptions options_;
    std::uint64_t seed_;
    std::unique_ptr<TableDriver> driver_; // where the actions go: the one path of the table
    Table table_;
    PhysicsParams params_;
    TableMode mode_; // what the table waits for here (table_modes.hpp)
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
    ComputerPacing pacing_; // the computer's move being shown

    std::string message_; // hints and prompts: whatever comes next replaces them
    // The last shot's verdict and what followed (the computer's or the other terminal's own
    // verdicts and choices): shown until the player here acts again.
    std::vector<std::string> verdicts_;
    std::string told_; // the last verdict, for the box at the end of a rack
    RackLog rack_log_; // the rack's shots as they were told
    // The rack's log while it is open: its lines and the page shown.
    std::optional<std::vector<std::string>> log_;
    int log_page_ = 0;
};

} // namespace termpool::tui
