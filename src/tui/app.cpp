#include "tui/app.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tui/aim.hpp"
#include "tui/help_text.hpp"
#include "tui/messages.hpp"
#include "tui/player_name.hpp"
#include "tui/pocket_cells.hpp"
#include "tui/save_file.hpp"
#include <termpool/computer.hpp>

namespace termpool::tui {
namespace {

constexpr int frame_ms = 16; // about 60 frames per second while something moves
constexpr double spin_step = 0.1, fine_spin_step = 0.02;
constexpr double power_step = 0.02;

bool calls_pocket(const Game& game, int target) {
    if (game.is_break())
        return false;
    switch (game.type()) {
    case GameType::eight_ball:
        return true;
    case GameType::eight_ball_bar:
        return target == 8;
    case GameType::nine_ball:
        return false;
    }
    return false;
}

} // namespace

App::App(Terminal& terminal, const GameOptions& options)
    : term_(terminal), options_(options), table_(make_table(options.setup)),
      params_(options.setup.physics), game_(make_game(options.setup, 1, 1)),
      seed_(options.seed.value_or(
          static_cast<std::uint64_t>(Clock::now().time_since_epoch().count()))) {
    // Names first: the first message already says who breaks.
    for (int p = 0; p < 2; ++p)
        if (options.names[p])
            names_[p] = *options.names[p];
    new_game(1);
    time_power_ = options.timed_power;
    show_aid_ = options.aim_aid;
    if (options.watch)
        seat_computer(1, *options.watch);
    if (options.computer)
        seat_computer(2, *options.computer);
    if (options.practice) {
        const RackType rack =
            options.setup.game == GameType::nine_ball ? RackType::nine_ball : RackType::eight_ball;
        practice_.emplace(table_, params_, rack, record_.seed); // the rack a game would have
        sync_practice();
    }
    // Ask for the names the command line did not give (practice has one player).
    if (!options.names[0] && !computers_[0]) {
        entry_player_ = 1;
    } else if (!options.names[1] && !computers_[1] && !practice_) {
        entry_player_ = 2;
    }
    if (entry_player_ != 0)
        message_.clear(); // "who breaks" comes once the names are known
    mode_ = entry_player_ != 0 ? Mode::names : Mode::placing;
    if (mode_ != Mode::names)
        begin();
}

void App::new_game(int breaker) {
    record_ = GameRecord{};
    record_.setup = options_.setup;
    record_.seed = seed_++;
    record_.breaker = breaker;
    record_.race_to = options_.race_to;
    record_.break_rule = options_.break_rule;
    match_ = MatchState{options_.race_to, options_.break_rule, {0, 0}};
    tally_ = StatsTally{};
    rack_ = 1;
    rack_breaker_ = breaker;
    game_ = make_game(options_.setup, breaker, record_.seed);
    shown_balls_ = game_.balls();
    trajectory_.reset();
    message_ = names_[breaker - 1] + " breaks: place the cue ball in the kitchen";
}

Vec2 App::cue_position() const {
    for (const Ball& b : game_.balls())
        if (b.id == 0 && b.state != MotionState::pocketed)
            return b.position;
    return table_.head_spot();
}

void App::begin() {
    message_ = practice_
                   ? "Practice: no referee. m moves a ball, r takes a shot again, t racks again"
                   : names_[game_.shooter() - 1] + " breaks: place the cue ball in the kitchen";
    // News from before the game (a config warning, where it is saved) leads the first line.
    for (auto n = options_.notices.rbegin(); n != options_.notices.rend(); ++n)
        message_ = *n + "; " + message_;
    start_turn();
}

void App::start_turn() {
    shown_balls_ = game_.balls();
    safety_ = false;
    push_out_ = false;
    pocket_chosen_ = false;
    target_index_ = -1;
    side_ = follow_ = 0;
    show_marker_ = false; // the pointer's mark belongs to the last aim
    dragging_ = false;
    if (game_.winner() != 0) {
        mode_ = Mode::game_over;
        game_over_at_ = Clock::now();
        return;
    }
    if (game_.chooser() != 0) {
        mode_ = Mode::choosing;
        return;
    }
    const Ball cue = [&] {
        for (const Ball& b : game_.balls())
            if (b.id == 0)
                return b;
        return Ball{};
    }();
    const bool must_place =
        game_.ball_in_hand() != BallInHand::none &&
        (cue.state == MotionState::pocketed || !game_.legal_placement(cue.position));
    if (game_.ball_in_hand() != BallInHand::none) {
        warn_of_third_foul();
        mode_ = Mode::placing;
        place_ = must_place ? (game_.legal_placement(table_.head_spot())
                                   ? table_.head_spot()
                                   : game_.legal_placements().front())
                            : cue.position;
        return;
    }
    start_aiming();
}

void App::warn_of_third_foul() {
    // WPA 9-ball: a player on two fouls must be told before the shot that a third loses.
    if (game_.type() == GameType::nine_ball && game_.consecutive_fouls(game_.shooter()) >= 2)
        message_ += (message_.empty() ? "" : "; ") + names_[game_.shooter() - 1] +
                    " is on two fouls: a third in a row loses the game";
}

void App::start_aiming() {
    mode_ = Mode::aiming;
    // A break wants a hard hit (a soft one is rarely legal): the bar starts full for it, and
    // the player's own setting comes back for the shots after.
    if (game_.is_break() && power_before_break_ < 0) {
        power_before_break_ = power_;
        power_ = 1.0;
    } else if (!game_.is_break() && power_before_break_ >= 0) {
        power_ = power_before_break_;
        power_before_break_ = -1;
    }
    aim_at_easiest();
    warn_of_third_foul();
    const std::string& who = names_[game_.shooter() - 1];
    if (game_.push_out_allowed()) {
        const std::string hint = "u declares a push-out";
        message_ = message_.empty() ? who + ": aim and shoot, or " + hint : message_ + "; " + hint;
    } else if (message_.empty() && !computers_[game_.shooter() - 1]) {
        // Short enough for the smallest panel; the help has the rest.
        message_ = who + ": aim (" + (term_.caps().mouse ? "mouse, " : "") +
                   "Left/Right), Space shoots" + (practice_ ? "; m moves a ball" : "");
    }
    // The proposed aim cannot reach the ball straight: say so before Space is pressed.
    if (target_line_ != TargetLine::straight && !computers_[game_.shooter() - 1])
        message_ += (message_.empty() ? "" : "; ") +
                    std::string(target_line_ == TargetLine::kick
                                    ? "no straight line to a legal ball: a kick off one rail"
                                    : "no clear line to a legal ball");
}

bool App::try_place(Vec2 spot) {
    if (!place(spot)) {
        message_ = "The cue ball cannot go there: " + placement_problem(game_, spot);
        return false;
    }
    message_.clear();
    start_aiming();
    return true;
}

bool App::calls_pocket(int target) const {
    return !practice_ && tui::calls_pocket(game_, target); // no referee, no calls
}

std::vector<int> App::targets() const {
    if (!practice_)
        return game_.legal_targets();
    std::vector<int> all; // no referee: every ball is fair
    for (const Ball& b : game_.balls())
        if (b.id != 0 && b.state != MotionState::pocketed)
            all.push_back(b.id);
    return all;
}

void App::aim_at_easiest() {
    const std::vector<TargetChoice> order =
        rank_targets(table_, game_.balls(), params_.ball_radius, cue_position(), targets());
    target_line_ = TargetLine::straight;
    if (!order.empty()) {
        target_index_ = std::clamp(target_index_, 0, static_cast<int>(order.size()) - 1);
        aim_deg_ = order[static_cast<std::size_t>(target_index_)].aim_deg;
        target_line_ = order[static_cast<std::size_t>(target_index_)].line;
    }
    update_preview();
}

void App::update_preview() {
    const AimPreview p =
        preview_shot(table_, game_.balls(), params_.ball_radius, cue_position(), aim_deg_);
    preview_.cue_path = p.cue_path;
    preview_.has_ghost = p.has_ghost;
    preview_.ghost = p.ghost;
    preview_.object_path = p.object_path;
    preview_.deflect_path = p.deflect_path;
    if (p.object_ball != preview_ball_)
        pocket_chosen_ = false;
    preview_ball_ = p.object_ball;
    if (!pocket_chosen_) {
        // Propose the obvious pocket: the one the object ball heads for most directly.
        called_pocket_ = 0;
        if (p.object_ball > 0 && calls_pocket(p.object_ball) && p.object_path.size() >= 2) {
            const Vec2 from = p.object_path.front();
            const Vec2 dir = normalized(p.object_path.back() - from);
            double best = -2;
            for (const Pocket& pocket : table_.pockets) {
                const double c = dot(normalized(pocket.position - from), dir);
                if (c > best) {
                    best = c;
                    called_pocket_ = pocket.number;
                }
            }
        }
    }
}

double App::current_power() const {
    if (!time_power_)
        return power_;
    const double t = std::chrono::duration<double>(Clock::now() - power_start_).count();
    return power_from_time(t);
}

void App::shoot() {
    const double power = current_power();
    const Strike strike{speed_from_power(power, game_.is_break()), aim_deg_, side_, follow_};
    ShotCall call;
    call.push_out = push_out_;
    call = game_.call_as_taken(call);
    if (safety_) {
        call.call.safety = true;
    } else if (preview_ball_ > 0 && calls_pocket(preview_ball_) && called_pocket_ != 0) {
        call.call = {preview_ball_, called_pocket_, false};
    }
    power_ = power;
    play(strike, call);
}

bool App::place(Vec2 spot) {
    if (!game_.place_cue_ball(spot))
        return false;
    RecordedAction action;
    action.kind = RecordedAction::Kind::place;
    action.place = spot;
    record_.actions.push_back(action);
    save();
    return true;
}

void App::choose(Choice choice) {
    if (!game_.choose(choice))
        return;
    RecordedAction action;
    action.kind = RecordedAction::Kind::choose;
    action.choice = choice;
    record_.actions.push_back(action);
    save();
}

void App::save() {
    if (replaying_ || practice_)
        return; // a replay shows a game, practice has none: neither writes over a saved game
    // The record is the whole game: rewritten after every action, so a dropped connection
    // loses at most the shot in flight.
    for (int p = 0; p < 2; ++p) {
        record_.names[p] = names_[p];
        record_.computers[p] =
            computers_[p] ? std::optional<Level>(computers_[p]->level()) : std::nullopt;
    }
    // A failure stays on the message line until a save works again: other messages come
    // and go, and the player must not miss that the game is not being kept.
    save_problem_.clear();
    write_atomically(options_.save_path, format_record(record_), save_problem_);
}

void App::play(const Strike& strike, const ShotCall& call) {
    if (!replaying_ && !practice_) {
        RecordedAction action;
        action.strike = strike;
        action.call = call;
        record_.actions.push_back(action);
    }
    call_ = call;
    last_strike_ = strike;
    shooter_before_ = game_.shooter();
    break_before_ = game_.is_break();
    Trajectory trajectory(params_, game_.balls().size());
    result_ = practice_ ? practice_->shoot(strike, &trajectory)
                        : simulate_shot(table_, params_, game_.balls(), strike, &trajectory);
    trajectory_ = std::move(trajectory);
    shot_start_ = Clock::now();
    mode_ = Mode::animating;
    message_ = names_[shooter_before_ - 1] + " shoots"; // the last verdict is over
}

void App::seat_computer(int player, Level level) {
    computers_[player - 1].emplace(level, seed_ + static_cast<std::uint64_t>(player));
    // Two computers (watching) are told apart by their seat.
    const std::string seat = options_.watch ? " " + std::to_string(player) : "";
    names_[player - 1] = "CPU" + seat + " (" + level_name(level) + ")";
}

int App::actor() const {
    return game_.chooser() != 0 ? game_.chooser() : game_.shooter();
}

bool App::computer_to_act() const {
    if (mode_ == Mode::names || mode_ == Mode::animating || mode_ == Mode::game_over)
        return false;
    return computers_[actor() - 1].has_value();
}

void App::computer_turn() {
    // The computer's turn is shown like a player's: it places the cue ball, turns the cue to
    // its aim over about a second, fills the power bar, then shoots.
    const double t = std::chrono::duration<double>(Clock::now() - plan_start_).count();
    ComputerPlayer& computer = *computers_[actor() - 1];
    if (!planning_) {
        planning_ = true;
        plan_start_ = Clock::now();
        if (mode_ == Mode::placing)
            place_ = computer.place_cue_ball(game_);
        if (mode_ == Mode::aiming) {
            plan_ = computer.shot(game_);
            aim_from_ = aim_deg_;
        }
        return;
    }
    if (mode_ == Mode::choosing) {
        if (t < 1.0)
            return;
        planning_ = false;
        const std::string who = names_[actor() - 1];
        const Choice choice = computer.choose(game_);
        choose(choice);
        message_ = who + ": " + choice_words(choice);
        start_turn();
        return;
    }
    if (mode_ == Mode::placing) {
        if (t < 0.7)
            return;
        planning_ = false;
        if (place(place_)) {
            message_.clear();
            start_aiming();
        }
        return;
    }
    // Aiming: turn the shorter way round, then fill the power bar.
    const double target = plan_->strike.angle_deg;
    const double delta = std::remainder(target - aim_from_, 360.0);
    aim_deg_ = turn(aim_from_, delta * std::min(1.0, t / 1.0));
    side_ = plan_->strike.side;
    follow_ = plan_->strike.follow;
    const double upper = game_.is_break() ? 12.0 : 7.0;
    power_ = std::clamp((plan_->strike.speed - 0.3) / (upper - 0.3), 0.0, 1.0) *
             std::clamp((t - 1.0) / 0.5, 0.0, 1.0);
    update_preview();
    if (t < 1.7)
        return;
    planning_ = false;
    play(plan_->strike, plan_->call);
}

void App::after_shot() {
    if (practice_) {
        trajectory_.reset();
        practice_shot_done();
        return;
    }
    const Verdict v = game_.apply(call_, result_);
    trajectory_.reset();
    tally_.on_shot(shooter_before_, break_before_, call_, v);
    if (v.winner != 0)
        match_.record_rack(v.winner);
    message_ = verdict_message(v, shooter_before_, names_);
    save();
    if (v.winner != 0 && match_.match_winner() != 0 && !replaying_)
        save_stats();
    start_turn();
    if (replaying_)
        mode_ = Mode::replay; // the replay shows the next action itself
}

void App::compose(View& v) const {
    v.table = &table_;
    v.balls = mode_ == Mode::animating ? shown_balls_ : game_.balls();
    v.ball_radius = params_.ball_radius;
    v.game = game_.type();
    v.names[0] = names_[0];
    v.names[1] = names_[1];
    v.shooter = game_.chooser() != 0 ? game_.chooser() : game_.shooter();
    if (mode_ == Mode::animating)
        v.shooter = shooter_before_;
    v.groups[0] = game_.group_of(1);
    v.groups[1] = game_.group_of(2);
    v.practice = practice_.has_value();
    v.race_to = match_.is_race() && !practice_ ? match_.race_to : 0;
    v.racks_won[0] = match_.racks_won[0];
    v.racks_won[1] = match_.racks_won[1];
    if (game_.type() == GameType::nine_ball) {
        v.fouls[0] = game_.consecutive_fouls(1);
        v.fouls[1] = game_.consecutive_fouls(2);
    }
    v.message =
        save_problem_.empty() ? message_ : "Could not save: " + save_problem_ + "; " + message_;
    v.help = help_;
    v.help_page = help_page_;
    if (mode_ == Mode::placing) {
        v.placing = true;
        v.placement_legal = game_.legal_placement(place_);
        for (Ball& b : v.balls) {
            if (b.id != 0)
                continue;
            b.position = place_;
            b.state = MotionState::stationary;
        }
        if (message_.empty())
            v.message = names_[game_.shooter() - 1] + ": place the cue ball";
    }
    if (mode_ == Mode::aiming) {
        v.aiming = true;
        v.aim_deg = aim_deg_;
        v.power = current_power();
        v.speed = speed_from_power(v.power, game_.is_break());
        v.time_power = time_power_;
        v.side = side_;
        v.follow = follow_;
        v.show_aid = show_aid_;
        if (show_aid_) {
            v.cue_path = preview_.cue_path;
            v.has_ghost = preview_.has_ghost;
            v.ghost = preview_.ghost;
            v.object_path = preview_.object_path;
            v.deflect_path = preview_.deflect_path;
        }
        v.show_marker = show_marker_;
        v.marker = marker_;
        // The panel says what the shot will call: the aimed ball into the chosen pocket.
        const bool calling =
            !safety_ && called_pocket_ != 0 && preview_ball_ > 0 && calls_pocket(preview_ball_);
        v.called_pocket = calling ? called_pocket_ : 0;
        v.called_ball = calling ? preview_ball_ : 0;
    }
    if (mode_ == Mode::moving)
        compose_moving(v);
    if (mode_ == Mode::choosing) {
        // What brought the choice (an illegal break, a push-out) goes in the box: it may sit
        // over the panel's message line.
        std::string text =
            (message_.empty() ? "" : message_ + "\n\n") + names_[game_.chooser() - 1] + ", choose:";
        for (std::size_t i = 0; i < game_.choices().size(); ++i)
            text += "\n" + std::to_string(i + 1) + "  " + choice_words(game_.choices()[i]);
        v.overlay = text;
    }
    if (mode_ == Mode::game_over)
        v.overlay = game_over_text();
    if (entry_player_ != 0) {
        std::string text = "termpool \u2014 " + std::string(game_type_name(game_.type())) +
                           "\n\nName of player " + std::to_string(entry_player_) + ": " + entry_ +
                           "_\n(Enter keeps \"" + names_[entry_player_ - 1] + "\")";
        if (entry_player_ == 2 && mode_ == Mode::names)
            text += "\n(or: computer [easy|medium|hard|pro])";
        if (!entry_error_.empty())
            text += "\n" + entry_error_;
        v.overlay = text;
    }
    if (asking_race_) {
        v.overlay = "termpool \u2014 " + std::string(game_type_name(game_.type())) +
                    "\n\nRace to how many racks? " + entry_ + "_\n(Enter keeps " +
                    std::to_string(std::max(1, options_.race_to)) + "; 1 is a single game)";
        if (!entry_error_.empty())
            v.overlay += "\n" + entry_error_;
    }
    if (confirm_quit_)
        v.overlay = "Quit the game?  y / n";
}

Grid App::frame(int width, int height) {
    // render() shows "Please enlarge the terminal" itself when the layout does not fit.
    layout_ = make_layout(table_, width, height);
    View view;
    compose(view);
    return render(view, layout_, term_.caps(), width, height);
}

bool App::nudge(Vec2& spot, int key, const std::string& text) const {
    // One cell a key; a row is as tall as two columns are wide. The keys keep the ball on
    // the cloth, where the player can see it.
    if (!layout_.fits)
        return false; // no cells to step by while "please enlarge" shows
    const double step = 1.0 / layout_.cells_per_metre, R = params_.ball_radius;
    if (key == key_left || text == "h")
        spot.x -= step;
    else if (key == key_right || text == "l")
        spot.x += step;
    else if (key == key_up || text == "k")
        spot.y += 2 * step;
    else if (key == key_down || text == "j")
        spot.y -= 2 * step;
    else
        return false;
    spot.x = std::clamp(spot.x, R, table_.length - R);
    spot.y = std::clamp(spot.y, R, table_.width - R);
    return true;
}

namespace {

bool is_backspace(int key) {
    return key == key_backspace || key == 8;
}

// Removes the last UTF-8 character of `s`.
void erase_last_character(std::string& s) {
    while (!s.empty() && (s.back() & 0xC0) == 0x80)
        s.pop_back();
    if (!s.empty())
        s.pop_back();
}

} // namespace

void App::handle_text_entry(const Input& in) {
    if (in.kind == Input::Kind::text) {
        entry_ += in.text;
        entry_error_.clear();
        return;
    }
    if (in.kind != Input::Kind::key)
        return;
    if (is_backspace(in.key)) {
        erase_last_character(entry_);
    } else if (in.key == key_enter) {
        // At the start, player 2 may be the computer: "computer" or "computer LEVEL".
        if (mode_ == Mode::names && entry_player_ == 2 && entry_.starts_with("computer")) {
            const std::string rest = entry_.size() > 9 ? entry_.substr(9) : "";
            const auto level =
                rest.empty() ? std::optional<Level>(Level::medium) : parse_level(rest);
            if (!level) {
                entry_error_ = "levels: easy, medium, hard, pro";
                return;
            }
            seat_computer(2, *level);
            entry_.clear();
            entry_error_.clear();
            entry_player_ = 0;
            ask_race();
            return;
        }
        std::string error;
        const auto name = clean_player_name(entry_, error);
        if (!error.empty()) {
            entry_error_ = error;
            return;
        }
        if (name)
            names_[entry_player_ - 1] = *name;
        entry_.clear();
        entry_error_.clear();
        const bool starting = mode_ == Mode::names;
        if (starting && entry_player_ == 1 && !options_.names[1] && !computers_[1] && !practice_) {
            entry_player_ = 2;
            return;
        }
        entry_player_ = 0;
        if (starting)
            ask_race();
    } else if (in.key == key_escape && mode_ != Mode::names) {
        entry_player_ = 0;
        entry_.clear();
        entry_error_.clear();
    }
}

void App::ask_race() {
    // The last question of the name prompt: how long a match (practice has none).
    if (practice_) {
        begin();
        return;
    }
    asking_race_ = true;
    entry_.clear();
    entry_error_.clear();
}

void App::handle_race_entry(const Input& in) {
    if (in.kind == Input::Kind::text && in.text.size() == 1 && in.text[0] >= '0' &&
        in.text[0] <= '9' && entry_.size() < 2) {
        entry_ += in.text;
        entry_error_.clear();
        return;
    }
    if (in.kind != Input::Kind::key)
        return;
    if (is_backspace(in.key)) {
        erase_last_character(entry_);
        return;
    }
    if (in.key != key_enter && in.key != key_escape)
        return;
    if (in.key != key_escape && !entry_.empty()) {
        const std::optional<int> race = parse_race_to(entry_);
        if (!race) {
            entry_error_ = "a race is 1 to " + std::to_string(max_race_to) + " racks";
            return;
        }
        options_.race_to = *race;
        record_.race_to = *race;
        match_.race_to = *race;
    }
    asking_race_ = false;
    entry_.clear();
    entry_error_.clear();
    begin();
}

void App::handle(const Input& in) {
    if (in.kind == Input::Kind::signal) {
        running_ = false;
        return;
    }
    if (in.kind == Input::Kind::none || in.kind == Input::Kind::resize)
        return;
    if (entry_player_ != 0) {
        handle_text_entry(in);
        return;
    }
    if (asking_race_) {
        handle_race_entry(in);
        return;
    }
    if (confirm_quit_) {
        // y, or q again (q q quits, as in many terminal programs).
        if (in.kind == Input::Kind::text && (in.text == "y" || in.text == "Y" || in.text == "q"))
            running_ = false;
        else if (in.kind != Input::Kind::mouse || in.clicked)
            confirm_quit_ = false;
        return;
    }
    if (help_) {
        // Pages forward and back; Esc, q, ?, Enter or a click close it.
        const int last = help_page_count(term_.width(), term_.height()) - 1;
        const int key = in.kind == Input::Kind::key ? in.key : 0;
        const std::string& t = in.text;
        if (t == " " || t == "j" || key == key_page_down || key == key_down)
            help_page_ = std::min(help_page_ + 1, last);
        else if (t == "k" || key == key_page_up || key == key_up)
            help_page_ = std::max(std::min(help_page_, last) - 1, 0);
        else if (t == "q" || t == "?" || key == key_escape || key == key_enter ||
                 (in.kind == Input::Kind::mouse && in.clicked)) {
            help_ = false;
            help_page_ = 0;
        }
        return;
    }
    if (replaying_) {
        handle_replay_key(in);
        return;
    }
    if (computer_to_act() && !(in.kind == Input::Kind::text && (in.text == "q" || in.text == "?")))
        return;
    if (in.kind == Input::Kind::mouse) {
        handle_mouse(in);
        return;
    }
    handle_key(in.key, in.text);
}

void App::handle_key(int key, const std::string& text) {
    if (text == "q") {
        if (mode_ == Mode::game_over)
            running_ = false;
        else
            confirm_quit_ = true;
        return;
    }
    if (text == "?") {
        help_ = true;
        return;
    }
    if (text == "n" && mode_ != Mode::game_over && mode_ != Mode::animating) {
        entry_player_ = game_.chooser() != 0 ? game_.chooser() : game_.shooter();
        entry_.clear();
        return;
    }
    switch (mode_) {
    case Mode::names:
    case Mode::replay:
        return;
    case Mode::moving:
        handle_moving_key(key, text);
        return;
    case Mode::animating:
        if (text == "x")
            shot_start_ -= std::chrono::hours(1);
        return;
    case Mode::game_over:
        if (match_.is_race() && match_.match_winner() == 0) {
            if (key == key_enter || text == " " || text == "r")
                next_rack();
            return;
        }
        if (text == "r" || text == "n") {
            const int loser = 3 - game_.winner();
            new_game(text == "r" ? loser : 1);
            start_turn();
        }
        return;
    case Mode::choosing: {
        const auto& choices = game_.choices();
        if (text.size() == 1 && text[0] >= '1' &&
            text[0] < '1' + static_cast<int>(choices.size())) {
            choose(choices[static_cast<std::size_t>(text[0] - '1')]);
            message_ = names_[game_.shooter() - 1] + (game_.is_break() ? " breaks" : " to shoot");
            start_turn();
        }
        return;
    }
    case Mode::placing:
        if (!nudge(place_, key, text) && (key == key_enter || text == " "))
            try_place(place_);
        return;
    case Mode::aiming:
        if (practice_ && handle_practice_key(text))
            return;
        break;
    }

    // Aiming. Keys move the aim away from the pointer, so its mark goes.
    if (key == key_left || key == key_right || key == key_shift_left || key == key_shift_right ||
        text == "h" || text == "l" || text == "H" || text == "L" || text == "[" || text == "]")
        show_marker_ = false;
    if (key == key_left || text == "h")
        aim_deg_ = turn(aim_deg_, 1);
    else if (key == key_right || text == "l")
        aim_deg_ = turn(aim_deg_, -1);
    else if (text == "H" || key == key_shift_left)
        aim_deg_ = turn(aim_deg_, 0.1);
    else if (text == "L" || key == key_shift_right)
        aim_deg_ = turn(aim_deg_, -0.1);
    else if (key == key_up || text == "k")
        power_ = std::min(1.0, power_ + power_step);
    else if (key == key_down || text == "j")
        power_ = std::max(0.0, power_ - power_step);
    else if (key == key_enter || text == " ") {
        shoot();
        return;
    } else if (text == "[" || text == "]") {
        target_index_ += text == "]" ? 1 : -1;
        const int n = static_cast<int>(targets().size());
        if (n > 0)
            target_index_ = (target_index_ % n + n) % n;
        aim_at_easiest();
        return;
    } else if (text == "w" || text == "W")
        follow_ = std::min(0.5, follow_ + (text == "w" ? spin_step : fine_spin_step));
    else if (text == "s" || text == "S")
        follow_ = std::max(-0.5, follow_ - (text == "s" ? spin_step : fine_spin_step));
    else if (text == "d" || text == "D")
        side_ = std::min(0.5, side_ + (text == "d" ? spin_step : fine_spin_step));
    else if (text == "a" || text == "A")
        side_ = std::max(-0.5, side_ - (text == "a" ? spin_step : fine_spin_step));
    else if (text == "c")
        side_ = follow_ = 0;
    else if (text == "p") {
        time_power_ = !time_power_;
        power_start_ = Clock::now();
        message_ = time_power_ ? "Timed power: the bar swings, Space stops it and shoots"
                               : "Distance power: the keys, or the pointer's distance in a drag";
    } else if (text == "g") {
        show_aid_ = !show_aid_;
        message_ = show_aid_ ? "Aiming aid on" : "Aiming aid off (g brings it back)";
    } else if (text == "u" && game_.push_out_allowed()) {
        push_out_ = !push_out_;
        message_ =
            push_out_ ? "Push-out: no foul but a scratch; then the other player chooses" : "";
    } else if (text == "0" && !practice_) {
        safety_ = !safety_;
        message_ = safety_ ? "Safety called: the turn passes whatever drops" : "";
    } else if (text.size() == 1 && text[0] >= '1' && text[0] <= '6') {
        called_pocket_ = text[0] - '0';
        pocket_chosen_ = true;
        safety_ = false;
    }
    side_ = std::round(side_ * 100) / 100;
    follow_ = std::round(follow_ * 100) / 100;
    update_preview();
}

void App::handle_mouse(const Input& in) {
    if (mode_ == Mode::animating) {
        if (in.clicked || in.pressed)
            shot_start_ -= std::chrono::hours(1);
        return;
    }
    if (!layout_.fits)
        return;
    if (mode_ == Mode::moving) {
        handle_moving_mouse(in);
        return;
    }
    const Vec2 pointer = from_cell(layout_, table_.width, in.x, in.y);
    if (mode_ == Mode::placing) {
        place_ = pointer;
        if (in.clicked || in.released)
            try_place(place_);
        return;
    }
    if (mode_ != Mode::aiming)
        return;
    if ((in.clicked || in.pressed) && tui::on_shoot_button(layout_, in.x, in.y)) {
        shoot();
        return;
    }
    if (in.clicked) {
        if (const int pocket = pocket_at(table_, layout_, in.x, in.y);
            pocket != 0 && called_pocket_ != 0) {
            called_pocket_ = pocket;
            pocket_chosen_ = true;
            return;
        }
        if (time_power_) {
            shoot();
            return;
        }
    }
    marker_ = pointer;
    show_marker_ = true;
    aim_deg_ = aim_from_pointer(cue_position(), pointer);
    // Hovering only aims; the pointer's distance sets the power while a button is held, so
    // a power set with the keys survives a look around the table.
    const bool holding = in.pressed || dragging_;
    if (!time_power_ && holding)
        power_ = power_from_distance(length(pointer - cue_position()));
    if (in.pressed) {
        if (time_power_) {
            shoot();
            return;
        }
        dragging_ = true;
        drag_moved_ = false;
    } else if (in.moved && dragging_) {
        drag_moved_ = true;
    } else if (in.released && dragging_) {
        dragging_ = false;
        if (drag_moved_) {
            update_preview();
            shoot();
            return;
        }
    }
    update_preview();
}

int App::run() {
    while (running_) {
        const int w = term_.width(), h = term_.height();
        if (mode_ == Mode::animating) {
            const double t = std::chrono::duration<double>(Clock::now() - shot_start_).count();
            if (t >= result_.rest_time) {
                after_shot();
            } else {
                shown_balls_ = trajectory_->sample(t);
            }
        }
        if (replaying_)
            replay_step();
        else if (computer_to_act())
            computer_turn();
        else if (computers_watched_rack_over())
            next_rack();
        term_.draw(frame(w, h));
        const bool moving = mode_ == Mode::animating || (mode_ == Mode::aiming && time_power_) ||
                            computer_to_act() || (replaying_ && !paused_);
        Input in = term_.read(moving ? frame_ms : 500);
        // Drain what has queued up so that a fast mouse does not lag behind.
        while (in.kind != Input::Kind::none && running_) {
            handle(in);
            if (in.kind == Input::Kind::signal)
                break;
            in = term_.read(0);
        }
    }
    // Quitting, or a signal: the game so far is kept (a shot still rolling is not: it replays
    // from its start).
    if (mode_ != Mode::names)
        save();
    return 0;
}

void App::start_replay(const GameRecord& record) {
    replaying_ = true;
    record_ = record;
    for (int p = 0; p < 2; ++p) {
        names_[p] = record.names[p];
        computers_[p].reset();
    }
    entry_player_ = 0;
    rewind_to(0);
}

void App::rewind_to(std::size_t action) {
    // Rebuild the match from the start without animation, up to (not including) `action`.
    GameRecord upto = record_;
    upto.actions.resize(std::min(action, record_.actions.size()));
    replay_from(upto);
    next_action_ = upto.actions.size();
    trajectory_.reset();
    shown_balls_ = game_.balls();
    mode_ = Mode::replay; // no aiming, no placing: the replay only shows
    message_ = "Replay (space pauses, Left/Right step a shot, x skips, q quits)";
}

bool App::replay_from(const GameRecord& record) {
    // The figures are not saved: they follow from the shots.
    tally_ = StatsTally{};
    auto replayed = replay_match(record, [&](const ReplayedShot& shot) {
        tally_.on_shot(shot.shooter, shot.was_break, shot.call, shot.verdict);
    });
    auto* match = std::get_if<ReplayedMatch>(&replayed);
    if (!match)
        return false;
    game_ = std::move(match->game);
    match_ = match->score;
    rack_ = match->rack;
    rack_breaker_ = match->rack_breaker;
    return true;
}

void App::replay_step() {
    if (paused_ || mode_ == Mode::animating)
        return;
    while (next_action_ < record_.actions.size()) {
        const RecordedAction a = record_.actions[next_action_++]; // a copy: play() may record
        if (a.kind == RecordedAction::Kind::place) {
            game_.place_cue_ball(a.place);
        } else if (a.kind == RecordedAction::Kind::rack) {
            start_rack(a);
        } else if (a.kind == RecordedAction::Kind::choose) {
            game_.choose(a.choice);
        } else {
            std::size_t shot = 0, shots = 0;
            for (std::size_t i = 0; i < record_.actions.size(); ++i) {
                const bool is_shot = record_.actions[i].kind == RecordedAction::Kind::shot;
                shots += is_shot;
                shot += is_shot && i < next_action_;
            }
            const std::string last = message_.starts_with("Replay") ? "" : message_;
            play(a.strike, a.call);
            message_ = "Replay, shot " + std::to_string(shot) + " of " + std::to_string(shots) +
                       " (space pauses, Left/Right step, x skips, q quits)" +
                       (last.empty() ? "" : ". Before: " + last);
            return;
        }
    }
    message_ = "Replay ended: Left steps back, q quits";
    paused_ = true;
}

void App::handle_replay_key(const Input& in) {
    if (in.kind == Input::Kind::mouse) {
        if (in.clicked && mode_ == Mode::animating)
            shot_start_ -= std::chrono::hours(1);
        return;
    }
    if (in.text == "q") {
        running_ = false;
    } else if (in.text == "?") {
        help_ = true;
        help_page_ = 0;
    } else if (in.text == " ") {
        paused_ = !paused_;
    } else if (in.text == "x" && mode_ == Mode::animating) {
        shot_start_ -= std::chrono::hours(1);
    } else if (in.key == key_left || in.key == key_right) {
        // Step a whole shot: back to the start of the previous one, or on past the next.
        std::size_t shot_starts = 0, target = 0;
        for (std::size_t i = 0; i < record_.actions.size(); ++i) {
            if (record_.actions[i].kind != RecordedAction::Kind::shot)
                continue;
            if (i + 1 <= next_action_ - (mode_ == Mode::animating ? 1 : 0))
                shot_starts = i + 1;
        }
        if (in.key == key_left) {
            target = 0;
            for (std::size_t i = 0; i + 1 < shot_starts; ++i)
                if (record_.actions[i].kind == RecordedAction::Kind::shot)
                    target = i + 1;
        } else {
            target = shot_starts;
            for (std::size_t i = shot_starts; i < record_.actions.size(); ++i)
                if (record_.actions[i].kind == RecordedAction::Kind::shot) {
                    target = i + 1;
                    break;
                }
        }
        rewind_to(target);
        paused_ = true;
    }
}

} // namespace termpool::tui
