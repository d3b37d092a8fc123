// The App's frame: the session set up, input dispatched by mode, the View of each mode, and
// the loop that draws and reads.
#include "tui/app.hpp"

#include <algorithm>
#include <cmath>
#include <termpool/race.hpp>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>

#include "tui/help_text.hpp"
#include "tui/messages.hpp"

namespace termpool::tui {
namespace {

constexpr int frame_ms = 16; // about 60 frames per second while something moves

// The first game: the command line's setup, race and names, player 1 to break from the rack
// seeded `seed` (the computers' streams follow on from it).
Match first_match(const GameOptions& options, std::uint64_t seed) {
    GameRecord header;
    header.setup = options.setup;
    header.seed = seed;
    for (int p = 0; p < 2; ++p)
        if (options.names[p])
            header.names[p] = *options.names[p];
    header.race_to = options.race_to;
    header.break_rule = options.break_rule;
    auto started = Match::start(header, seed + 1);
    if (Match* match = std::get_if<Match>(&started))
        return std::move(*match);
    // The options come checked; should the match still refuse them, the defaults play.
    GameRecord defaults;
    defaults.setup.game = options.setup.game;
    defaults.seed = seed;
    return std::get<Match>(Match::start(defaults, seed + 1));
}

} // namespace

App::App(Terminal& terminal, const GameOptions& options)
    : term_(terminal), options_(options), table_(make_table(options.setup)),
      params_(game_physics(options.setup)), seed_(options.seed.value_or(static_cast<std::uint64_t>(
                                                Clock::now().time_since_epoch().count()))),
      match_(first_match(options, seed_++)) {
    shown_balls_ = game().balls();
    message_ = breaks_words(1);
    aim_.time_power = options.timed_power;
    aim_.show_aid = options.aim_aid;
    if (options.watch)
        seat_computer(1, *options.watch);
    if (options.computer)
        seat_computer(2, *options.computer);
    if (options.practice) {
        const RackType rack = game_rack(options.setup.game);
        // The rack a game would have.
        practice_.emplace(table_, params_, rack, match_.record().seed);
        sync_practice();
    }
    // Ask for the names the command line did not give (practice has one player).
    if (!options.names[0] && !match_.seat(1).computer) {
        entry_.player = 1;
    } else if (!options.names[1] && !match_.seat(2).computer && !practice_) {
        entry_.player = 2;
    }
    if (entry_.player != 0)
        message_.clear(); // "who breaks" comes once the names are known
    mode_ = entry_.player != 0 ? Mode::names : Mode::placing;
    if (mode_ != Mode::names)
        begin();
}

const Game& App::game() const {
    if (practice_game_)
        return *practice_game_;
    // While a shot rolls the match has judged it already: show the game as it was.
    return mode_ == Mode::animating && before_shot_ ? *before_shot_ : match_.game();
}

const MatchState& App::score() const {
    return mode_ == Mode::animating && before_shot_ ? score_before_ : match_.score();
}

void App::compose(View& v) const {
    const Game& g = game();
    v.table = &table_;
    v.balls = mode_ == Mode::animating ? shown_balls_ : g.balls();
    v.ball_radius = params_.ball_radius;
    v.game = g.type();
    v.names[0] = name(1);
    v.names[1] = name(2);
    // The panel marks who is at the table: at game over too, when the match's to_act() is
    // already the next rack's breaker.
    v.shooter = mode_ == Mode::animating ? shooter_before_
                : g.chooser() != 0       ? g.chooser()
                                         : g.shooter();
    v.groups[0] = g.group_of(1);
    v.groups[1] = g.group_of(2);
    v.practice = practice_.has_value();
    v.race_to = score().is_race() && !practice_ ? score().race_to : 0;
    v.racks_won[0] = score().racks_won[0];
    v.racks_won[1] = score().racks_won[1];
    if (is_rotation_game(g.type())) {
        v.fouls[0] = g.consecutive_fouls(1);
        v.fouls[1] = g.consecutive_fouls(2);
    }
    if (g.type() == GameType::snooker) {
        const SnookerState& s = g.snooker();
        v.scores[0] = s.scores[0];
        v.scores[1] = s.scores[1];
        v.current_break = s.current_break;
        v.highest_break[0] = s.highest_break[0];
        v.highest_break[1] = s.highest_break[1];
        v.ball_on = s.ball_on;
        v.free_ball = s.free_ball;
        v.points_remaining = g.points_remaining();
        if (s.ball_on == BallOn::in_order) {
            const std::vector<int> on = g.balls_on();
            v.lowest_colour = on.empty() ? 0 : on.front();
        }
        // A match of frames is said as best of N (a race to 3 is best of 5).
        v.best_of = score().is_race() ? best_of_for_race(score().race_to) : 0;
        v.race_to = 0;
        // Another terminal's nomination is not sent while it aims: no guess at it.
        if (mode_ == Mode::aiming && (!in_hall() || hall_seat_to_act())) {
            v.nominated = aim_.nominated;
            v.nomination_chosen = aim_.nomination_chosen;
        }
    }
    v.message =
        save_problem_.empty() ? message_ : "Could not save: " + save_problem_ + "; " + message_;
    v.help = help_;
    v.help_page = help_page_;
    switch (mode_) {
    case Mode::placing:
        v.placing = true;
        v.placement_legal = g.legal_placement(place_);
        for (Ball& b : v.balls) {
            if (b.id != 0)
                continue;
            b.position = place_;
            b.state = MotionState::stationary;
        }
        if (message_.empty())
            v.message = name(g.shooter()) + ": place the cue ball";
        break;
    case Mode::aiming:
        compose_aiming(v);
        break;
    case Mode::moving:
        compose_moving(v);
        break;
    case Mode::choosing: {
        // What brought the choice (an illegal break, a push-out) goes in the box: it may sit
        // over the panel's message line.
        std::string text =
            (message_.empty() ? "" : message_ + "\n\n") + name(g.chooser()) + ", choose:";
        for (std::size_t i = 0; i < g.choices().size(); ++i)
            text += "\n" + std::to_string(i + 1) + "  " +
                    choice_words(g.choices()[i], g.type(), g.free_ball_offered());
        if (snooker_play())
            text += "\nC  concede the frame";
        v.overlay = text;
        break;
    }
    case Mode::game_over:
        v.overlay = game_over_text();
        break;
    case Mode::names:
    case Mode::animating:
    case Mode::replay:
        break;
    }
    compose_prompt(v);
    if (in_hall())
        compose_hall(v);
    if (confirm_quit_)
        v.overlay = in_hall() ? "Leave the table?  y / n" : "Quit the game?  y / n";
    if (confirm_concede_)
        v.overlay = name(match_.to_act()) + ": concede the frame?  y / n";
}

void App::compose_aiming(View& v) const {
    v.aiming = true;
    v.aim_deg = aim_.aim_deg;
    v.power = aim_.current_power(Clock::now());
    v.speed = speed_from_power(v.power, game().is_break());
    v.is_break = game().is_break();
    v.time_power = aim_.time_power;
    v.side = aim_.side;
    v.follow = aim_.follow;
    v.elevation_deg = aim_.elevation_deg;
    // Marked before Space is pressed: the power bar swings or the keys change the power, and
    // the same elevation turns from playable to a jump.
    v.strike_refused =
        strike_problem(aim_.strike(game().is_break(), Clock::now()), params_).has_value();
    v.show_aid = aim_.show_aid;
    if (aim_.show_aid) {
        v.cue_path = aim_.preview.cue_path;
        v.has_ghost = aim_.preview.has_ghost;
        v.ghost = aim_.preview.ghost;
        v.object_path = aim_.preview.object_path;
        v.deflect_path = aim_.preview.deflect_path;
    }
    v.close_up = aim_.close_up_view(game().balls());
    v.show_marker = aim_.show_marker;
    v.marker = aim_.marker;
    // The panel says what the shot will call: the aimed ball into the chosen pocket.
    // Another terminal's call is not sent while it aims: this one's guess at it would mislead.
    const bool calling = !aim_.safety && aim_.called_pocket != 0 && aim_.preview_ball > 0 &&
                         calls_pocket(aim_.preview_ball) && (!in_hall() || hall_seat_to_act());
    v.called_pocket = calling ? aim_.called_pocket : 0;
    v.called_ball = calling ? aim_.preview_ball : 0;
}

void App::compose_prompt(View& v) const {
    const std::string title = "termpool \u2014 " + std::string(game_type_name(game().type()));
    if (entry_.player != 0) {
        v.overlay = title + "\n\nName of player " + std::to_string(entry_.player) + ": " +
                    entry_.text + "_\n(Enter keeps \"" + name(entry_.player) + "\")";
        if (entry_.player == 2 && mode_ == Mode::names)
            v.overlay += "\n(or: computer [easy|medium|hard|pro])";
    } else if (entry_.asking_race) {
        const int race = std::max(1, options_.race_to);
        if (snooker_play())
            v.overlay = title + "\n\nBest of how many frames? " + entry_.text + "_\n(Enter keeps " +
                        std::to_string(best_of_for_race(race)) + "; 1 is a single frame)";
        else
            v.overlay = title + "\n\nRace to how many racks? " + entry_.text + "_\n(Enter keeps " +
                        std::to_string(race) + "; 1 is a single game)";
    } else {
        return;
    }
    if (!entry_.error.empty())
        v.overlay += "\n" + entry_.error;
}

Grid App::frame(int width, int height) {
    // render() shows "Please enlarge the terminal" itself when the layout does not fit.
    layout_ = make_layout(table_, width, height);
    View view;
    compose(view);
    return render(view, layout_, term_.caps(), width, height);
}

bool App::nudge(Vec2& spot, int key, const std::string& text) const {
    // One cell a key; a row is as tall as two columns are wide. The keys keep the ball where
    // it may be put down (on_playing_surface), a pocket's mouth included.
    if (!layout_.fits)
        return false; // no cells to step by while "please enlarge" shows
    const double step = 1.0 / layout_.cells_per_metre, row = 1.0 / layout_.rows_per_metre;
    Vec2 by;
    if (key == key_left || text == "h")
        by = {-step, 0};
    else if (key == key_right || text == "l")
        by = {step, 0};
    else if (key == key_up || text == "k")
        by = {0, row};
    else if (key == key_down || text == "j")
        by = {0, -row};
    else
        return false;
    const Vec2 stepped = step_on_table(table_, spot, by, params_.ball_radius);
    // The D is small: the keys keep a ball in hand there inside it (the pointer may leave it,
    // and is told why the ball cannot go there).
    const bool in_d = mode_ == Mode::placing && game().ball_in_hand() == BallInHand::d;
    if (!in_d || !in_snooker_d(table_, spot) || in_snooker_d(table_, stepped))
        spot = stepped;
    return true;
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
    if (in_hall() && handle_hall_key(in))
        return;
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

bool App::handle_overlay(const Input& in) {
    if (confirm_concede_) {
        if (in.kind == Input::Kind::mouse && !in.clicked)
            return true;
        confirm_concede_ = false;
        if (in.kind == Input::Kind::text && (in.text == "y" || in.text == "Y"))
            concede();
        return true;
    }
    if (confirm_quit_) {
        // y, or q again (q q quits, as in many terminal programs).
        if (in.kind == Input::Kind::text && (in.text == "y" || in.text == "Y" || in.text == "q"))
            running_ = false;
        else if (in.kind != Input::Kind::mouse || in.clicked)
            confirm_quit_ = false;
        return true;
    }
    if (!help_)
        return false;
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
    return true;
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
    if (text == "C" && snooker_play() &&
        (mode_ == Mode::placing || mode_ == Mode::aiming || mode_ == Mode::choosing)) {
        ask_concede();
        return;
    }
    if (text == "n" && mode_ != Mode::game_over && mode_ != Mode::animating && !in_hall()) {
        entry_.player = match_.to_act();
        entry_.text.clear();
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
        if (match_.pending().kind == Pending::next_rack) {
            if (key == key_enter || text == " " || text == "r")
                next_rack();
            return;
        }
        if (in_hall())
            return; // a new game is a new table, from the lobby
        if (text == "r" || text == "n") {
            const int loser = 3 - game().winner();
            new_game(text == "r" ? loser : 1);
            start_turn();
        }
        return;
    case Mode::choosing: {
        const auto& choices = game().choices();
        if (text.size() == 1 && text[0] >= '1' &&
            text[0] < '1' + static_cast<int>(choices.size()) && in_hall()) {
            RecordedAction action;
            action.kind = RecordedAction::Kind::choose;
            action.choice = choices[static_cast<std::size_t>(text[0] - '1')];
            send_to_hall(action);
        } else if (text.size() == 1 && text[0] >= '1' &&
                   text[0] < '1' + static_cast<int>(choices.size())) {
            choose(choices[static_cast<std::size_t>(text[0] - '1')]);
            message_ = name(game().shooter()) + (game().is_break() ? " breaks" : " to shoot");
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
        handle_aiming_key(key, text);
        return;
    }
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
    if (mode_ == Mode::placing) {
        place_ = from_cell(layout_, table_.width, in.x, in.y);
        if (in.clicked || in.released)
            try_place(place_);
        return;
    }
    if (mode_ == Mode::aiming)
        handle_aiming_mouse(in);
}

void App::step() {
    if (mode_ == Mode::animating) {
        const double t = std::chrono::duration<double>(Clock::now() - shot_start_).count();
        if (t >= result_.rest_time)
            after_shot();
        else
            shown_balls_ = trajectory_->sample(t);
    }
    if (in_hall())
        apply_hall_actions();
    else if (replaying_)
        replay_step();
    else if (computer_to_act())
        computer_turn();
    else if (computers_watched_rack_over())
        next_rack();
}

bool App::moving() const {
    return mode_ == Mode::animating || (mode_ == Mode::aiming && aim_.time_power) ||
           computer_to_act() || (replaying_ && !paused_) || !hall_queue_.empty();
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
    // Quitting, or a signal: the game so far is kept (a shot still rolling is not: it replays
    // from its start).
    if (mode_ != Mode::names)
        save();
    return 0;
}

} // namespace termpool::tui
