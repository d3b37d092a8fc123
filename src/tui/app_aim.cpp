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

bool App::calls_pocket(int target) const {
    return !practice_ && match_.calls_pocket(target); // no referee, no calls
}

std::vector<int> App::targets() const {
    if (!practice_)
        return game().legal_targets();
    std::vector<int> all; // no referee: every ball is fair
    for (const Ball& b : game().balls())
        if (b.id != 0 && b.state != MotionState::pocketed)
            all.push_back(b.id);
    return all;
}

void App::aim_at_easiest() {
    aim_.aim_at_target(
        rank_targets(table_, game().balls(), params_.ball_radius, cue_position(), targets()));
    update_preview();
}

void App::update_preview() {
    aim_.update_preview(table_, params_, game().balls(), game().is_break(),
                        [this](int ball) { return calls_pocket(ball); });
    propose_nomination();
}

bool App::snooker_play() const {
    return !practice_ && game().type() == GameType::snooker;
}

void App::propose_nomination() {
    if (snooker_play())
        tui::propose_nomination(game(), aim_);
}

bool App::nominate_key(const std::string& text) {
    // Snooker's digits name a colour by its value; the pool keys for pockets and safety mean
    // nothing here.
    const std::optional<std::string> said =
        nomination_key(game(), aim_, text, name(game().shooter()));
    if (said)
        message_ = *said;
    return said.has_value();
}

void App::handle_aiming_key(int key, const std::string& text) {
    // Keys move the aim away from the pointer, so its mark goes.
    if (key == key_left || key == key_right || key == key_shift_left || key == key_shift_right ||
        text == "h" || text == "l" || text == "H" || text == "L" || text == "," || text == "." ||
        text == "[" || text == "]")
        aim_.show_marker = false;
    if (key == key_left || text == "h")
        aim_.aim_deg = turn(aim_.aim_deg, 1);
    else if (key == key_right || text == "l")
        aim_.aim_deg = turn(aim_.aim_deg, -1);
    else if (text == "H" || key == key_shift_left)
        aim_.aim_deg = turn(aim_.aim_deg, 0.1);
    else if (text == "L" || key == key_shift_right)
        aim_.aim_deg = turn(aim_.aim_deg, -0.1);
    else if (text == ",")
        aim_.aim_deg = turn(aim_.aim_deg, 0.01);
    else if (text == ".")
        aim_.aim_deg = turn(aim_.aim_deg, -0.01);
    else if (key == key_up || text == "k")
        aim_.power = std::min(1.0, aim_.power + power_step);
    else if (key == key_down || text == "j")
        aim_.power = std::max(0.0, aim_.power - power_step);
    else if (key == key_enter || text == " ") {
        shoot();
        return;
    } else if (text == "[" || text == "]") {
        aim_.target_index += text == "]" ? 1 : -1;
        const int n = static_cast<int>(targets().size());
        if (n > 0)
            aim_.target_index = (aim_.target_index % n + n) % n;
        aim_at_easiest();
        return;
    } else if (text == "p") {
        aim_.time_power = !aim_.time_power;
        aim_.power_start = Clock::now();
        message_ = aim_.time_power
                       ? "Timed power: the bar swings, Space stops it and shoots"
                       : "Distance power: the keys, or the pointer's distance in a drag";
    } else if (text == "g") {
        aim_.show_aid = !aim_.show_aid;
        message_ = aim_.show_aid ? "Aiming aid on" : "Aiming aid off (g brings it back)";
    } else if (text == "z") {
        aim_.close_up = !aim_.close_up;
        message_ = aim_.close_up ? "Close-up of the contact: , and . turn the aim 0.01 degree"
                                 : "Close-up off (z brings it back)";
    } else if (snooker_play() && nominate_key(text)) {
        return;
    } else if (text == "u" && game().push_out_allowed()) {
        aim_.push_out = !aim_.push_out;
        message_ =
            aim_.push_out ? "Push-out: no foul but a scratch; then the other player chooses" : "";
    } else if (text == "0" && !practice_) {
        aim_.safety = !aim_.safety;
        message_ = aim_.safety ? "Safety called: the turn passes whatever drops" : "";
    } else if (text.size() == 1 && text[0] >= '1' && text[0] <= '6') {
        aim_.called_pocket = text[0] - '0';
        aim_.pocket_chosen = true;
        aim_.safety = false;
    } else if (!aim_.elevation_key(text)) {
        aim_.spin_key(text);
    }
    aim_.side = std::round(aim_.side * 100) / 100;
    aim_.follow = std::round(aim_.follow * 100) / 100;
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
            pocket != 0 && aim_.called_pocket != 0) {
            aim_.called_pocket = pocket;
            aim_.pocket_chosen = true;
            return;
        }
        if (aim_.time_power) {
            shoot();
            return;
        }
    }
    aim_.marker = pointer;
    aim_.show_marker = true;
    aim_.aim_deg = aim_from_pointer(cue_position(), pointer);
    // Hovering only aims; the pointer's distance sets the power while a button is held, so
    // a power set with the keys survives a look around the table.
    const bool holding = in.pressed || aim_.dragging;
    if (!aim_.time_power && holding)
        aim_.power = power_from_distance(length(pointer - cue_position()));
    if (in.pressed) {
        if (aim_.time_power) {
            shoot();
            return;
        }
        aim_.dragging = true;
        aim_.drag_moved = false;
    } else if (in.moved && aim_.dragging) {
        aim_.drag_moved = true;
    } else if (in.released && aim_.dragging) {
        aim_.dragging = false;
        if (aim_.drag_moved) {
            update_preview();
            shoot();
            return;
        }
    }
    update_preview();
}

} // namespace termpool::tui
