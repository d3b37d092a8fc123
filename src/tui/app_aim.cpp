// Aiming at the table: the keys and the pointer turn the cue, set the power, spin, elevation
// and call, and the aiming aid follows.

#include <algorithm>
#include <cmath>

#include "tui/app.hpp"
#include "tui/nomination.hpp"
#include "tui/pocket_cells.hpp"

namespace termpool::tui {
namespace {

constexpr double power_step = 0.02;

} // namespace

Vec2 App::cue_position() const {
    for (const Ball& b : game().balls())
        if (b.id == 0 && b.state != MotionState::pocketed)
            return b.position;
    return table_.head_spot();
}

void App::aim_at_easiest() {
    aim().aim_at_target(rank_openings(table_, game().balls(), params_.ball_radius, cue_position(),
                                      driver_->targets(), aim().assist));
    update_preview();
}

void App::update_preview() {
    aim().update_preview(table_, params_, game().balls(), game().is_break(),
                         [this](int ball) { return driver_->calls_pocket(ball); });
    if (snooker_play())
        propose_nomination(game(), aim());
}

bool App::nominate_key(const std::string& text) {
    // Snooker's digits name a colour by its value; the pool keys for pockets and safety mean
    // nothing here.
    const std::optional<std::string> said =
        nomination_key(game(), aim(), text, name(game().shooter()));
    if (!said)
        return false;
    message_ = *said;
    // A named colour is the ball to hit: the cue turns to it, by the easiest line there is (as
    // a turn opens at the assist's aim), so that Space does not foul on the ball aimed before.
    const int named = aim().nominated;
    const auto on_table = [&](const Ball& b) {
        return b.id == named && b.state != MotionState::pocketed;
    };
    if (aim().nomination_chosen && named > 0 &&
        std::any_of(game().balls().begin(), game().balls().end(), on_table)) {
        aim().target_index = 0;
        aim().aim_at_target(rank_openings(table_, game().balls(), params_.ball_radius,
                                          cue_position(), {named}, aim().assist));
        aim().show_marker = false;
        message_ += "; the cue turns to it";
    }
    update_preview();
    return true;
}

void App::on_key(AimingMode&, int key, const std::string& text) {
    // Keys move the aim away from the pointer, so its mark goes.
    if (key == key_left || key == key_right || key == key_shift_left || key == key_shift_right ||
        text == "," || text == "." || text == "[" || text == "]")
        aim().show_marker = false;
    if (key == key_left)
        aim().aim_deg = turn(aim().aim_deg, 1);
    else if (key == key_right)
        aim().aim_deg = turn(aim().aim_deg, -1);
    else if (key == key_shift_left)
        aim().aim_deg = turn(aim().aim_deg, 0.1);
    else if (key == key_shift_right)
        aim().aim_deg = turn(aim().aim_deg, -0.1);
    else if (text == ",")
        aim().aim_deg = turn(aim().aim_deg, 0.01);
    else if (text == ".")
        aim().aim_deg = turn(aim().aim_deg, -0.01);
    else if (key == key_up || text == "k")
        aim().power = std::min(1.0, aim().power + power_step);
    else if (key == key_down || text == "j")
        aim().power = std::max(0.0, aim().power - power_step);
    else if (key == key_enter || text == " ") {
        shoot();
        return;
    } else if (text == "[" || text == "]") {
        aim().target_index += text == "]" ? 1 : -1;
        const int n = static_cast<int>(driver_->targets().size());
        if (n > 0)
            aim().target_index = (aim().target_index % n + n) % n;
        aim_at_easiest();
        return;
    } else if (text == "p") {
        // How the power is set is the terminal's way, for every seat.
        const bool timed = !aim().time_power;
        for (AimState& seat : aims_) {
            seat.time_power = timed;
            seat.power_start = Clock::now();
        }
        message_ = aim().time_power
                       ? "Timed power: the bar swings, Space stops it and shoots"
                       : "Distance power: the keys, or the pointer's distance in a drag";
    } else if (text == "g") {
        const bool shown = !aim().show_aid;
        for (AimState& seat : aims_)
            seat.show_aid = shown;
        message_ = aim().show_aid ? "Aiming aid on" : "Aiming aid off (g brings it back)";
    } else if (text == "z") {
        // The close-up, like the aid, is this terminal's way of looking: both seats' cues.
        const bool shown = !aim().close_up;
        for (AimState& seat : aims_)
            seat.close_up = shown;
        message_ = shown ? "Close-up of the contact: , and . turn the aim 0.01 degree"
                         : "Close-up off (z brings it back)";
    } else if (snooker_play() && nominate_key(text)) {
        return;
    } else if (text == "u" && game().push_out_allowed()) {
        aim().push_out = !aim().push_out;
        message_ =
            aim().push_out ? "Push-out: no foul but a scratch; then the other player chooses" : "";
    } else if (text == "0" && driver_->referee()) {
        aim().safety = !aim().safety;
        message_ = aim().safety ? "Safety called: the turn passes whatever drops" : "";
    } else if (text.size() == 1 && text[0] >= '1' && text[0] <= '6') {
        aim().called_pocket = text[0] - '0';
        aim().pocket_chosen = true;
        aim().safety = false;
        update_preview();
        // The call changed: the safety's word goes, and a pocket with no ball in line says why
        // the panel names none.
        message_ = aim().preview_ball > 0
                       ? ""
                       : "No ball in line to call: aim at a ball, then 1-6 names its pocket";
        return;
    } else if (!aim().elevation_key(text)) {
        aim().spin_key(text);
    }
    aim().side = std::round(aim().side * 100) / 100;
    aim().follow = std::round(aim().follow * 100) / 100;
    update_preview();
}

void App::handle_aiming_mouse(const Input& in) {
    const Vec2 pointer = from_cell(layout_, table_.width, in.x, in.y);
    if ((in.clicked || in.pressed) && tui::on_shoot_button(layout_, in.x, in.y)) {
        shoot();
        return;
    }
    if (in.clicked) {
        if (const int pocket = pocket_at(table_, layout_, in.x, in.y);
            pocket != 0 && aim().called_pocket != 0) {
            aim().called_pocket = pocket;
            aim().pocket_chosen = true;
            return;
        }
        if (aim().time_power) {
            shoot();
            return;
        }
    }
    aim().marker = pointer;
    aim().show_marker = true;
    aim().aim_deg = aim_from_pointer(cue_position(), pointer);
    // Hovering only aims; the pointer's distance sets the power while a button is held, so
    // a power set with the keys survives a look around the table.
    const bool holding = in.pressed || aim().dragging;
    if (!aim().time_power && holding)
        aim().power = power_from_distance(length(pointer - cue_position()));
    if (in.pressed) {
        if (aim().time_power) {
            shoot();
            return;
        }
        aim().dragging = true;
        aim().drag_moved = false;
    } else if (in.moved && aim().dragging) {
        aim().drag_moved = true;
    } else if (in.released && aim().dragging) {
        aim().dragging = false;
        if (aim().drag_moved) {
            update_preview();
            shoot();
            return;
        }
    }
    update_preview();
}

} // namespace termpool::tui
