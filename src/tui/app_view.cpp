// The View of each mode: the table, the panel's players and score, the cue as aimed, the
// boxes (choices, game over, the prompts, the log) and the message line with its verdicts.

#include <algorithm>
#include <termpool/game_registry.hpp>
#include <termpool/race.hpp>
#include <termpool/setup.hpp>

#include "tui/app.hpp"
#include "tui/messages.hpp"
#include "tui/shot_call.hpp"

namespace termpool::tui {

void App::compose(View& v) const {
    const Game& g = game();
    const RollingMode* rolling = as<RollingMode>();
    v.table = &table_;
    v.balls = rolling ? rolling->show.balls() : g.balls();
    v.ball_radius = params_.ball_radius;
    v.game = g.type();
    v.names[0] = name(1);
    v.names[1] = name(2);
    // The panel marks who is at the table: at game over too, when the match's to_act() is
    // already the next rack's breaker.
    v.shooter = rolling            ? rolling->show.shot().shooter
                : g.chooser() != 0 ? g.chooser()
                                   : g.shooter();
    v.groups[0] = g.group_of(1);
    v.groups[1] = g.group_of(2);
    v.practice = !driver_->referee();
    v.race_to = score().is_race() && driver_->referee() ? score().race_to : 0;
    v.racks_won[0] = score().racks_won[0];
    v.racks_won[1] = score().racks_won[1];
    // Only the games with the three-foul rule count fouls in a row.
    v.fouls[0] = g.consecutive_fouls(1);
    v.fouls[1] = g.consecutive_fouls(2);
    if (game_row(g.type()).scoring == Scoring::points) {
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
        if (as<AimingMode>() && driver_->shows_call()) {
            v.nominated = aim().nominated;
            v.nomination_chosen = aim().nomination_chosen;
        }
    }
    const std::string problem = driver_->problem();
    v.message = problem.empty() ? said() : "Could not save: " + problem + "; " + said();
    v.help = help_;
    v.help_page = help_page_;
    std::visit([&](const auto& mode) { compose_mode(mode, v); }, mode_);
    compose_prompt(v);
    driver_->compose(v, screen());
    if (log_)
        v.overlay = log_page_text();
    if (confirm_quit_)
        v.overlay = driver_->quit_question();
    if (confirm_concede_)
        v.overlay = name(driver_->match().to_act()) + ": concede the frame?  y / n";
}

void App::compose_mode(const PlacingMode& placing, View& v) const {
    const Game& g = game();
    v.placing = true;
    v.placement_legal = g.legal_placement(placing.spot);
    for (Ball& b : v.balls) {
        if (b.id != 0)
            continue;
        b.position = placing.spot;
        b.state = MotionState::stationary;
    }
    // Told to the player here, said of another seat; in snooker the D is named.
    const std::string where = ball_in_hand_words(g.ball_in_hand());
    const std::string ball = "the cue ball" + (where.empty() ? "" : " " + where);
    const std::string placing_words = driver_->may_act() ? name(g.shooter()) + ": place " + ball
                                                         : name(g.shooter()) + " places " + ball;
    if (said().empty())
        v.message = placing_words;
    else if (driver_->may_act() && !g.is_break())
        // The verdict said why ("... has ball in hand"); the player here is told what to do, as
        // the break's words tell the breaker.
        v.message += "; " + placing_words;
}

void App::compose_mode(const OverMode&, View& v) const {
    v.overlay = driver_->game_over_text(told_.empty() ? said() : told_);
}

void App::compose_mode(const ChoosingMode&, View& v) const {
    // What brought the choice (an illegal break, a push-out) goes in the box: it may sit over
    // the panel's message line.
    const Game& g = game();
    // The keys are for the player here; another seat's options are only listed.
    const bool here = driver_->may_act();
    std::string text = (said().empty() ? "" : said() + "\n\n") + name(g.chooser()) +
                       (here ? ", choose:" : " chooses from:");
    for (std::size_t i = 0; i < g.choices().size(); ++i)
        text += "\n" + (here ? std::to_string(i + 1) : std::string("-")) + "  " +
                choice_words(g.choices()[i], g.type(), g.free_ball_offered(), g.ball_in_hand());
    if (snooker_play())
        text += here ? "\nC  concede the frame" : "\n-  concede the frame";
    v.overlay = text;
}

void App::compose_mode(const AimingMode&, View& v) const {
    v.aiming = true;
    v.aim_deg = aim().aim_deg;
    v.power = aim().current_power(Clock::now());
    v.speed = speed_from_power(v.power, game().is_break());
    v.is_break = game().is_break();
    v.time_power = aim().time_power;
    v.side = aim().side;
    v.follow = aim().follow;
    v.elevation_deg = aim().elevation_deg;
    // Marked before Space is pressed: the power bar swings or the keys change the power, and
    // the same elevation turns from playable to a jump.
    v.strike_refused =
        strike_problem(aim().strike(game().is_break(), Clock::now()), params_).has_value();
    v.show_aid = aim().show_aid;
    if (aim().show_aid) {
        v.cue_path = aim().preview.cue_path;
        v.has_ghost = aim().preview.has_ghost;
        v.ghost = aim().preview.ghost;
        v.object_path = aim().preview.object_path;
        v.deflect_path = aim().preview.deflect_path;
    }
    v.close_up = aim().close_up_view(game().balls());
    v.show_marker = aim().show_marker;
    v.marker = aim().marker;
    // The panel says what the shot will call, as shoot() makes it. Another terminal's call is
    // not sent while it aims (this one's guess at it would mislead), only with its shot.
    const CallShown call =
        shot_call(aim(), driver_->targets(), [this](int b) { return driver_->calls_pocket(b); });
    const bool own = driver_->shows_call() && driver_->may_act();
    if (own || aim().given_call) {
        v.called_pocket = call.call.call.ball > 0 ? call.call.call.pocket : 0;
        v.called_ball = call.call.call.ball;
        v.call_off_ball = call.off_ball;
        v.called_safety = call.call.call.safety;
        v.foul_ball = own ? call.foul_ball : 0;
    }
    // Guided: the balls the shooter may not hit first are dimmed.
    if (aim().assist == Assist::guided && driver_->referee()) {
        const std::vector<int> legal = driver_->targets();
        for (const Ball& b : game().balls())
            if (b.id != 0 && std::find(legal.begin(), legal.end(), b.id) == legal.end())
                v.dimmed_balls.push_back(b.id);
    }
}

void App::compose_prompt(View& v) const {
    const std::string title = "termpool \u2014 " + std::string(game_type_name(game().type()));
    if (entry_.player != 0) {
        v.overlay = title + "\n\nName of player " + std::to_string(entry_.player) + ": " +
                    entry_.text + "_\n(Enter keeps \"" + name(entry_.player) + "\")";
        if (entry_.player == 2 && as<NamesMode>())
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

} // namespace termpool::tui
