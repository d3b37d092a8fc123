// A turn at the table: the driver says what the table waits for and the App goes into that
// mode; placing, shooting and choosing become actions submitted to the driver, the actions of
// others come from it (paced like a player's when a computer's), and a shot is shown rolling
// before its verdict is told.

#include <optional>
#include <string>
#include <termpool/break_off.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/setup.hpp>

#include "tui/app.hpp"
#include "tui/cue_ball_spot.hpp"
#include "tui/messages.hpp"
#include "tui/nomination.hpp"
#include "tui/shot_call.hpp"
#include "tui/table_news.hpp"
#include "tui/turn_words.hpp"

namespace termpool::tui {

void App::begin() {
    message_ = driver_->referee()
                   ? breaks_words(driver_->match(), game().shooter(), driver_->may_act())
                   : driver_->table_words();
    // News from before the game (a config warning, where it is saved) leads the first line.
    for (auto n = options_.notices.rbegin(); n != options_.notices.rend(); ++n)
        message_ = *n + "; " + message_;
    start_turn();
}

void App::start_turn() {
    pacing_.stop();
    // Aiming until the pending action says otherwise; a shot shown before is over, so the game
    // is the driver's as it stands now.
    mode_ = AimingMode{};
    const PendingAction pending = driver_->pending();
    if (pending.kind == Pending::over || pending.kind == Pending::next_rack) {
        mode_ = OverMode{};
        return;
    }
    aim().new_turn();
    if (pending.kind == Pending::choose) {
        mode_ = ChoosingMode{};
        return;
    }
    if (pending.kind == Pending::place) {
        const Game& g = game();
        const Ball* cue = nullptr;
        for (const Ball& b : g.balls())
            if (b.id == 0)
                cue = &b;
        const bool must_move =
            !cue || cue->state == MotionState::pocketed || !g.legal_placement(cue->position);
        warn_of_third_foul();
        mode_ = PlacingMode{must_move ? first_cue_ball_spot(g, table_.head_spot()) : cue->position};
        return;
    }
    start_aiming();
}

void App::warn_of_third_foul() {
    // WPA 9-ball and 10-ball: a player on two fouls must be told before the shot that a third
    // loses (only the games with that rule count fouls in a row).
    const Game& g = game();
    if (g.consecutive_fouls(g.shooter()) >= 2)
        message_ += (message_.empty() ? "" : "; ") + name(g.shooter()) +
                    " is on two fouls: a third in a row loses the game";
}

void App::start_aiming() {
    mode_ = AimingMode{};
    aim().assist = driver_->match().record().assist; // the table's, for both seats
    // A pool break opens at full power on the easiest ball; snooker's break-off soft and thin
    // off the end red of the pack, to come back to baulk (break_off_strike).
    const bool break_off =
        game().is_break() && game_row(game().type()).default_break.aim == BreakAim::end_red;
    const std::optional<Strike> opening =
        break_off ? std::optional(break_off_strike(table_, params_, game().balls())) : std::nullopt;
    const double speed = opening ? opening->speed : game_row(game().type()).default_break.speed;
    aim().set_break(game().is_break(), power_from_speed(speed, true));
    aim_at_easiest();
    if (opening) {
        aim().aim_deg = opening->angle_deg;
        update_preview();
    }
    warn_of_third_foul();
    TurnFacts facts;
    facts.who = name(game().shooter());
    // Someone else's turn (the computer's, or another terminal's): no how-to.
    facts.here = driver_->may_act();
    facts.told = !verdicts_.empty();
    facts.mouse = term_.caps().mouse;
    facts.push_out = game().push_out_allowed();
    facts.nomination = snooker_play() && game().nomination_owed();
    facts.free_ball = game().snooker().free_ball;
    facts.line = aim().target_line;
    message_ = turn_words(message_, facts);
}

void App::act(const RecordedAction& action) {
    std::string refusal;
    std::optional<TableNews> news = driver_->submit(action, refusal);
    if (!refusal.empty()) {
        message_ = "Not taken: " + refusal; // nothing was done: the verdicts stay
        return;
    }
    // The player here acted: the verdicts told since their last action have been read.
    player_acts();
    if (news)
        show(std::move(*news));
}

void App::show(TableNews news) {
    if (news.shot && news.trajectory) {
        // The driver has judged the shot already; the game as it was shows until the balls
        // stop, and then its verdict is told.
        message_ = name(news.shot->shooter) + " shoots";
        told_ = news.words;
        RollingMode rolling;
        rolling.show.start(std::move(*news.shot), std::move(*news.trajectory),
                           std::move(news.before), news.score_before, Clock::now());
        mode_ = std::move(rolling);
        return;
    }
    message_.clear();
    if (!news.words.empty()) {
        tell(news.words);
        told_ = news.words;
    }
    start_turn();
}

void App::after_shot() {
    if (const RollingMode* rolling = as<RollingMode>(); rolling && driver_->referee())
        rack_log_.add(rolling->show.shot(), driver_->match().record());
    message_.clear();
    if (driver_->referee())
        tell(told_);
    else
        message_ = told_; // practice: no verdict, only what dropped
    start_turn();
}

void App::take_upcoming(Clock::time_point now) {
    const Upcoming* next = driver_->upcoming(now);
    if (!next)
        return;
    if (next->paced && !pace(*next, now))
        return;
    pacing_.stop();
    const bool hurry = next->hurry;
    if (std::optional<TableNews> news = driver_->take()) {
        show(std::move(*news));
        if (RollingMode* rolling = as<RollingMode>(); rolling && hurry)
            rolling->show.hurry();
    }
}

bool App::pace(const Upcoming& next, Clock::time_point now) {
    // The computer's move is shown like a player's: it places the cue ball, turns the cue to
    // its aim, fills the power bar, then shoots. Its cue is its own seat's: the player's cue
    // keeps what the player set.
    const RecordedAction& action = next.action;
    if (!pacing_.showing()) {
        pacing_.start(action, aim().aim_deg, now);
        if (PlacingMode* placing = as<PlacingMode>();
            placing && action.kind == RecordedAction::Kind::place)
            placing->spot = action.place;
    }
    if (action.kind != RecordedAction::Kind::shot)
        return pacing_.due(now);
    if (!as<AimingMode>())
        return true;
    const double t = pacing_.elapsed(now);
    AimState& cue = aim();
    cue.aim_deg = pacing_.aim_at(t);
    cue.side = action.strike.side;
    cue.follow = action.strike.follow;
    cue.elevation_deg = action.strike.elevation_deg;
    cue.power = pacing_.power_at(t, game().is_break());
    // The panel shows the call the shot makes; in snooker the computer's own nomination.
    cue.given_call = action.call;
    cue.nominated = action.call.call.ball;
    cue.nomination_chosen = snooker_play() && game().nomination_owed() && cue.nominated != 0;
    update_preview();
    return pacing_.due(now);
}

void App::try_place(Vec2 spot) {
    if (!game().legal_placement(spot)) {
        message_ = "The cue ball cannot go there: " + placement_problem(game(), spot);
        return;
    }
    RecordedAction action;
    action.kind = RecordedAction::Kind::place;
    action.place = spot;
    act(action);
}

void App::shoot() {
    const auto now = Clock::now();
    const Strike strike = aim().strike(game().is_break(), now);
    // A cue the simulator cannot play (a jump shot, which it does not model) is not shot: the
    // player adjusts it.
    if (const std::optional<std::string> problem = strike_problem(strike, params_)) {
        message_ = "Not played: " + *problem;
        return;
    }
    const double power = aim().current_power(now);
    RecordedAction action;
    action.kind = RecordedAction::Kind::shot;
    action.strike = strike;
    // The call the panel shows (shot_call), as the referee takes it.
    const auto calls = [this](int ball) { return driver_->calls_pocket(ball); };
    action.call = game().call_as_taken(shot_call(aim(), driver_->targets(), calls).call);
    // Snooker: the nomination the player named; without one the referee takes the ball hit
    // first, the aimed ball the panel proposed.
    if (snooker_play())
        action.call.call = nomination_call(game(), aim());
    aim().power = power;
    act(action);
}

void App::ask_concede() {
    // Only the player to act concedes, and only at this terminal's seat.
    if (driver_->may_act() && game().winner() == 0)
        confirm_concede_ = true;
}

void App::concede() {
    RecordedAction action;
    action.kind = RecordedAction::Kind::choose;
    action.choice = Choice::concede;
    act(action);
}

void App::on_key(ChoosingMode&, int, const std::string& text) {
    const auto& choices = game().choices();
    if (text.size() != 1 || text[0] < '1' || text[0] >= '1' + static_cast<int>(choices.size()))
        return;
    RecordedAction action;
    action.kind = RecordedAction::Kind::choose;
    action.choice = choices[static_cast<std::size_t>(text[0] - '1')];
    act(action);
}

void App::on_key(OverMode&, int key, const std::string& text) {
    if (driver_->pending().kind == Pending::next_rack) {
        if (driver_->may_act() && (key == key_enter || text == " " || text == "r")) {
            RecordedAction action;
            action.kind = RecordedAction::Kind::rack;
            action.breaker = driver_->match().next_breaker();
            act(action);
        }
        return;
    }
    // A new game between the same seats, where the table offers one (not in the hall: a new
    // game is a new table, from the lobby).
    if ((text == "r" || text == "n") && driver_->rematch(text == "r" ? 3 - game().winner() : 1)) {
        player_acts();
        message_ = breaks_words(driver_->match(), game().shooter(), driver_->may_act());
        start_turn();
    }
}

} // namespace termpool::tui
