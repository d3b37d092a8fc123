// The App's frame: the session set up with its driver, input dispatched by mode, and the loop
// that draws and reads.
#include "tui/app.hpp"

#include <termpool/game_registry.hpp>
#include <termpool/setup.hpp>

#include "tui/cell_step.hpp"
#include "tui/local_driver.hpp"
#include "tui/practice_driver.hpp"
#include "tui/replay_driver.hpp"
#include "tui/table_news.hpp"

namespace termpool::tui {
namespace {

constexpr int frame_ms = 16; // about 60 frames per second while something moves

} // namespace

App::App(Terminal& terminal, const GameOptions& options)
    : term_(terminal), options_(options), seed_(options.seed.value_or(static_cast<std::uint64_t>(
                                              Clock::now().time_since_epoch().count()))),
      table_(make_table(options.setup)), params_(game_physics(options.setup)) {
    if (options.practice)
        use(std::make_unique<PracticeDriver>(options, seed_++));
    else
        use(std::make_unique<LocalDriver>(options, seed_++));
    for (AimState& seat : aims_) {
        seat.time_power = options.timed_power;
        seat.show_aid = options.aim_aid;
    }
    if (options.watch)
        driver_->seat_computer(1, *options.watch);
    if (options.computer)
        driver_->seat_computer(2, *options.computer);
    // Ask for the names the command line did not give (practice has one player).
    if (!options.names[0] && !driver_->match().seat(1).computer)
        entry_.player = 1;
    else if (!options.names[1] && !driver_->match().seat(2).computer && driver_->referee())
        entry_.player = 2;
    if (entry_.player == 0)
        begin();
}

void App::use(std::unique_ptr<TableDriver> driver) {
    driver_ = std::move(driver);
    rack_log_.rebuild(driver_->match().record(), driver_->match().rack());
    table_ = make_table(driver_->match().setup());
    params_ = game_physics(driver_->match().setup());
    mode_ = NamesMode{};
    verdicts_.clear();
}

void App::resume(Match match) {
    auto local = std::make_unique<LocalDriver>(options_, seed_++);
    local->resume(std::move(match));
    use(std::move(local));
    entry_.player = 0;
    // Where the game stands comes first here: the player needs it before any news.
    message_ = "Game resumed: " + standing_words(driver_->match());
    for (const std::string& n : options_.notices)
        message_ += "; " + n;
    start_turn();
}

void App::start_replay(const GameRecord& record) {
    use(std::make_unique<ReplayDriver>(record));
    entry_.player = 0;
}

HallDriver& App::join_hall(Match match, TableLink link) {
    auto hall = std::make_unique<HallDriver>(std::move(match), std::move(link));
    HallDriver& joined = *hall;
    use(std::move(hall));
    entry_.player = 0;
    entry_.clear();
    return joined;
}

const Game& App::game() const {
    // While a shot rolls the match has judged it already: show the game as it was.
    const RollingMode* rolling = as<RollingMode>();
    return rolling && rolling->show.before() ? *rolling->show.before() : driver_->game();
}

const MatchState& App::score() const {
    const RollingMode* rolling = as<RollingMode>();
    return rolling && rolling->show.before() ? rolling->show.score_before()
                                             : driver_->match().score();
}

bool App::snooker_play() const {
    return driver_->referee() && game_row(game().type()).scoring == Scoring::points;
}

ScreenFacts App::screen() const {
    return {as<RollingMode>() != nullptr, as<OverMode>() != nullptr, as<ChoosingMode>() != nullptr,
            confirm_quit_ || confirm_concede_};
}

Grid App::frame(int width, int height) {
    // render() shows "Please enlarge the terminal" itself when the layout does not fit.
    layout_ = make_layout(table_, width, height);
    View view;
    compose(view);
    return render(view, layout_, term_.caps(), width, height);
}

void App::handle(const Input& in) {
    if (in.kind == Input::Kind::signal) {
        running_ = false;
        return;
    }
    if (in.kind == Input::Kind::none || in.kind == Input::Kind::resize ||
        in.kind == Input::Kind::watched)
        return;
    if (entry_.player != 0) {
        handle_text_entry(in);
        return;
    }
    if (entry_.asking_race) {
        handle_race_entry(in);
        return;
    }
    if (handle_overlay(in))
        return;
    if (const std::optional<DriverReply> reply = driver_->handle(in, layout_, screen())) {
        apply(*reply);
        return;
    }
    const std::string& text = in.kind == Input::Kind::text ? in.text : std::string();
    if (text == "l") {
        open_log(); // `l` opens the rack's log on any screen at the table
        return;
    }
    // Whoever acts elsewhere (the computer, the other terminal, the record), this one may
    // still leave, read the help, or hurry a shot along.
    if (!driver_->may_act() && !as<RollingMode>() && !as<OverMode>() && text != "q" && text != "?")
        return;
    if (in.kind == Input::Kind::mouse)
        handle_mouse(in);
    else
        handle_key(in.key, in.text);
}

void App::apply(const DriverReply& reply) {
    if (reply.new_turn) {
        message_ = reply.words; // the turn's own hint follows when there are none
        start_turn();
    } else if (!reply.words.empty()) {
        message_ = reply.words;
    }
    if (reply.set_aim) {
        aim().aim_deg = reply.set_aim->angle_deg;
        aim().side = reply.set_aim->side;
        aim().follow = reply.set_aim->follow;
        aim().elevation_deg = reply.set_aim->elevation_deg;
        aim().show_marker = false;
        update_preview();
    }
}

void App::handle_key(int key, const std::string& text) {
    if (text == "q") {
        if (as<OverMode>() || driver_->quit_question().empty())
            running_ = false;
        else
            confirm_quit_ = true;
        return;
    }
    if (text == "?") {
        help_ = true;
        help_page_ = 0;
        return;
    }
    if (text == "C" && snooker_play() &&
        (as<PlacingMode>() || as<AimingMode>() || as<ChoosingMode>())) {
        ask_concede();
        return;
    }
    if (text == "n" && !as<OverMode>() && !as<RollingMode>() && driver_->may_rename()) {
        entry_.player = driver_->match().to_act();
        entry_.text.clear();
        return;
    }
    std::visit([&](auto& mode) { on_key(mode, key, text); }, mode_);
}

void App::on_key(PlacingMode& placing, int key, const std::string& text) {
    if (!step_spot(placing.spot, key, text, layout_, table_, params_.ball_radius,
                   game().ball_in_hand() == BallInHand::d) &&
        (key == key_enter || text == " "))
        try_place(placing.spot);
}

void App::on_key(RollingMode& rolling, int, const std::string& text) {
    if (text == "x")
        rolling.show.hurry();
}

void App::handle_mouse(const Input& in) {
    if (RollingMode* rolling = as<RollingMode>()) {
        if (in.clicked || in.pressed)
            rolling->show.hurry();
        return;
    }
    if (!layout_.fits)
        return;
    if (PlacingMode* placing = as<PlacingMode>()) {
        placing->spot = from_cell(layout_, table_.width, in.x, in.y);
        if (in.clicked || in.released)
            try_place(placing->spot);
        return;
    }
    if (as<AimingMode>())
        handle_aiming_mouse(in);
}

void App::step() {
    const Clock::time_point now = Clock::now();
    if (RollingMode* rolling = as<RollingMode>(); rolling && rolling->show.advance(now))
        after_shot();
    if (driver_->take_reset()) {
        // The table was replaced under this screen (the hall's record, a replay's step).
        verdicts_.clear();
        told_.clear();
        rack_log_.rebuild(driver_->match().record(), driver_->match().rack());
        message_ = driver_->table_words();
        start_turn();
    }
    if (std::string m = driver_->take_message(); !m.empty())
        message_ = std::move(m);
    if (const std::optional<SeatAim> seat = driver_->take_seat_aim();
        seat && as<AimingMode>() && seat->seat == game().shooter()) {
        // The other terminal's cue turns its own seat's cue here.
        AimState& cue = aims_[seat->seat == 2 ? 1 : 0];
        cue.aim_deg = seat->strike.angle_deg;
        cue.power = power_from_speed(seat->strike.speed, game().is_break());
        cue.side = seat->strike.side;
        cue.follow = seat->strike.follow;
        cue.elevation_deg = seat->strike.elevation_deg;
        cue.show_marker = false;
        update_preview();
    }
    if (!as<NamesMode>() && !as<RollingMode>())
        take_upcoming(now);
    if (as<AimingMode>() && driver_->may_act())
        driver_->aim_set(aim().strike(game().is_break(), now));
}

bool App::moving() const {
    return as<RollingMode>() || (as<AimingMode>() && aim().time_power) || pacing_.showing() ||
           driver_->busy();
}

int App::run() {
    while (running_) {
        const int w = term_.width(), h = term_.height();
        step();
        term_.draw(frame(w, h));
        Input in = term_.read(moving() ? frame_ms : 500);
        // Drain what has queued up so that a fast mouse does not lag behind.
        while (in.kind != Input::Kind::none && running_) {
            handle(in);
            if (in.kind == Input::Kind::signal)
                break;
            in = term_.read(0);
        }
    }
    // Quitting, or a signal: the game so far is kept (a shot still rolling too: the driver
    // kept it when it was played).
    if (!as<NamesMode>())
        driver_->leave();
    return 0;
}

} // namespace termpool::tui
