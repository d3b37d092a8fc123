// Practice at the table: the App's modes without a referee. `m` picks balls up and puts them
// down (keys or mouse), `r` takes the last shot again, `t` sets up a new rack.

#include <algorithm>
#include <string>

#include "tui/app.hpp"
#include "tui/terminal.hpp"

namespace termpool::tui {
namespace {

std::string ball_name(int id) {
    return id == 0 ? "cue ball" : std::to_string(id);
}

std::string potted_words(const ShotResult& result) {
    std::vector<int> potted;
    for (const Event& e : result.events)
        if (e.kind == EventKind::pocket && e.ball != 0)
            potted.push_back(e.ball);
    if (potted.empty())
        return "Nothing potted";
    std::string s = "Potted";
    for (const int id : potted)
        s += " " + std::to_string(id);
    return s;
}

} // namespace

void App::sync_practice() {
    // The rest of the App reads the table through a Game: one with no referee state.
    practice_game_ = Game::from_position(options_.setup.game, table_, params_, practice_->balls(),
                                         1, Group::open, practice_->is_break());
}

void App::practice_shot_done() {
    bool cue_potted = false;
    for (const Event& e : show_.shot().result.events)
        cue_potted |= e.kind == EventKind::pocket && e.ball == 0;
    sync_practice();
    message_ = potted_words(show_.shot().result) +
               (cue_potted ? "; the cue ball is back on the head spot" : "") +
               ". r takes the shot again, m moves a ball";
    start_turn();
}

bool App::handle_practice_key(const std::string& text) {
    if (text == "m") {
        start_moving();
    } else if (text == "r") {
        if (practice_->retake()) {
            sync_practice();
            // The same aim, spin and elevation (the power bar kept its setting, and a break taken
            // again has the break's full bar back), ready to adjust.
            mode_ = Mode::aiming;
            aim().set_break(game().is_break());
            aim().aim_deg = last_strike_.angle_deg;
            aim().side = last_strike_.side;
            aim().follow = last_strike_.follow;
            aim().elevation_deg = last_strike_.elevation_deg;
            aim().show_marker = false;
            message_ = "The balls are back: take the shot again";
            update_preview();
        } else {
            message_ = "No shot to take again";
        }
    } else if (text == "t") {
        practice_->rerack(seed_++);
        sync_practice();
        message_ = "A new rack";
        start_turn();
    } else {
        return false;
    }
    return true;
}

void App::start_moving() {
    mode_ = Mode::moving;
    held_ball_ = -1;
    message_ = "Move a ball: click one or press Tab; Esc ends";
}

void App::hold_ball(int id) {
    held_ball_ = id;
    held_at_ = table_.foot_spot();
    for (const Ball& b : practice_->balls())
        if (b.id == id && b.state != MotionState::pocketed)
            held_at_ = b.position;
    message_ = "Moving the " + ball_name(id) +
               ": arrows or the mouse move it, Enter or a click puts it down, Tab picks the "
               "next, Esc ends";
}

void App::put_down(Vec2 spot) {
    if (held_ball_ < 0)
        return;
    if (!practice_->put(held_ball_, spot)) {
        message_ =
            "The " + ball_name(held_ball_) + " cannot go there: " +
            (on_playing_surface(table_, spot, params_.ball_radius) ? "it would touch another ball"
                                                                   : "that is off the cloth");
        return;
    }
    sync_practice();
    message_ = "Put down the " + ball_name(held_ball_) + ". Tab or a click picks another, Esc ends";
    held_ball_ = -1;
}

void App::handle_moving_key(int key, const std::string& text) {
    const std::vector<Ball>& balls = practice_->balls();
    if (key == key_escape || text == "m") {
        held_ball_ = -1;
        message_.clear();
        start_turn();
        return;
    }
    if (key == '\t' || text == "]" || text == "[") {
        // Every ball, on the table or pocketed, in id order: a pocketed one comes back.
        std::vector<int> ids;
        for (const Ball& b : balls)
            ids.push_back(b.id);
        std::sort(ids.begin(), ids.end());
        const auto at = std::find(ids.begin(), ids.end(), held_ball_);
        const int n = static_cast<int>(ids.size());
        const int i = at == ids.end() ? (text == "[" ? 0 : -1) : static_cast<int>(at - ids.begin());
        hold_ball(ids[static_cast<std::size_t>(((i + (text == "[" ? -1 : 1)) % n + n) % n)]);
        return;
    }
    if (held_ball_ < 0)
        return;
    if (!nudge(held_at_, key, text) && (key == key_enter || text == " "))
        put_down(held_at_);
}

void App::handle_moving_mouse(const Input& in) {
    if (!layout_.fits)
        return;
    const Vec2 pointer = from_cell(layout_, table_.width, in.x, in.y);
    if (held_ball_ >= 0) {
        held_at_ = pointer;
        if (in.clicked || in.released)
            put_down(pointer);
        return;
    }
    if (!(in.clicked || in.pressed))
        return;
    // The ball under the pointer: within a cell of it, as a ball may be drawn a cell aside.
    const double reach = std::max(2 * params_.ball_radius, 1.5 / layout_.cells_per_metre);
    int nearest = -1;
    double best = reach * reach;
    for (const Ball& b : practice_->balls()) {
        if (b.state == MotionState::pocketed)
            continue;
        const double d = length_squared(b.position - pointer);
        if (d <= best)
            best = d, nearest = b.id;
    }
    if (nearest >= 0)
        hold_ball(nearest);
}

void App::compose_moving(View& v) const {
    if (held_ball_ < 0)
        return;
    // Every ball is in the list, pocketed ones too: a pocketed one comes back to be placed.
    for (Ball& b : v.balls) {
        if (b.id != held_ball_)
            continue;
        b.position = held_at_;
        b.state = MotionState::stationary;
    }
    // The cue ball shows a refused spot as in ball in hand.
    v.placing = held_ball_ == 0;
    v.placement_legal = practice_->can_put(held_ball_, held_at_);
}

} // namespace termpool::tui
