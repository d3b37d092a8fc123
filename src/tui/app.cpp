// The App's frame: the session set up, input dispatched by mode, and the loop that draws
// and reads (the View of each mode is composed in app_view.cpp).
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
    show_.stop(game().balls());
    message_ = breaks_words(1);
    for (AimState& seat : aims_) {
        seat.time_power = options.timed_power;
        seat.show_aid = options.aim_aid;
    }
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
    return mode_ == Mode::animating && show_.before() ? *show_.before() : match_.game();
}

const MatchState& App::score() const {
    return mode_ == Mode::animating && show_.before() ? show_.score_before() : match_.score();
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
    const double step = 1.0 / layout_.cells_per_metre;
    Vec2 by;
    if (key == key_left)
        by = {-step, 0};
    else if (key == key_right)
        by = {step, 0};
    else if (key == key_up || text == "k")
        by = {0, 2 * step};
    else if (key == key_down || text == "j")
        by = {0, -2 * step};
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
    if (in.kind == Input::Kind::text && in.text == "l") {
        open_log(); // `l` opens the rack's log on any screen at the table
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
            show_.hurry();
        return;
    case Mode::game_over:
        if (match_.pending().kind == Pending::next_rack) {
            if (key == key_enter || text == " " || text == "r") {
                player_acts();
                next_rack();
            }
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
            player_acts();
            send_to_hall(action);
        } else if (text.size() == 1 && text[0] >= '1' &&
                   text[0] < '1' + static_cast<int>(choices.size())) {
            player_acts();
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
            show_.hurry();
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
    if (mode_ == Mode::animating && show_.advance(Clock::now()))
        after_shot();
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
    return mode_ == Mode::animating || (mode_ == Mode::aiming && aim().time_power) ||
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
