#include "tui/aim_state.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tui/aid_path.hpp"
#include "tui/kick_aim.hpp"

namespace termpool::tui {
namespace {

constexpr double spin_step = 0.1, fine_spin_step = 0.02;

} // namespace

void AimState::new_turn() {
    safety = false;
    push_out = false;
    pocket_chosen = false;
    nominated = 0;
    nomination_chosen = false;
    target_index = -1;
    kick_ball = -1;
    side = follow = 0;
    elevation_deg = 0;
    show_marker = false; // the pointer's mark belongs to the last aim
    dragging = false;
    given_call.reset();
}

void AimState::set_break(bool is_break, double break_power) {
    if (is_break && power_before_break < 0) {
        power_before_break = power;
        power = break_power;
    } else if (!is_break && power_before_break >= 0) {
        power = power_before_break;
        power_before_break = -1;
    }
}

double AimState::current_power(Clock::time_point now) const {
    if (!time_power)
        return power;
    return power_from_time(std::chrono::duration<double>(now - power_start).count());
}

bool AimState::spin_key(const std::string& text) {
    if (text == "w" || text == "W")
        follow = std::min(0.5, follow + (text == "w" ? spin_step : fine_spin_step));
    else if (text == "s" || text == "S")
        follow = std::max(-0.5, follow - (text == "s" ? spin_step : fine_spin_step));
    else if (text == "d" || text == "D")
        side = std::min(0.5, side + (text == "d" ? spin_step : fine_spin_step));
    else if (text == "a" || text == "A")
        side = std::max(-0.5, side - (text == "a" ? spin_step : fine_spin_step));
    else if (text == "c")
        side = follow = 0;
    else
        return false;
    return true;
}

bool AimState::elevation_key(const std::string& text) {
    if (text == "e")
        elevation_deg = std::min(max_cue_elevation_deg, elevation_deg + elevation_step_deg);
    else if (text == "E")
        elevation_deg = std::max(0.0, elevation_deg - elevation_step_deg);
    else if (text == "v")
        elevation_deg = 0;
    else
        return false;
    return true;
}

Strike AimState::strike(bool is_break, Clock::time_point now) const {
    return {speed_from_power(current_power(now), is_break), aim_deg, side, follow, elevation_deg};
}

Strike AimState::set_strike(bool is_break) const {
    return {speed_from_power(power, is_break), aim_deg, side, follow, elevation_deg};
}

void AimState::aim_at_target(const std::vector<TargetChoice>& order) {
    target_line = TargetLine::straight;
    kick_ball = -1;
    if (order.empty())
        return;
    target_index = std::clamp(target_index, 0, static_cast<int>(order.size()) - 1);
    const TargetChoice& target = order[static_cast<std::size_t>(target_index)];
    aim_deg = target.aim_deg;
    target_line = target.line;
    kick_ball = target.line == TargetLine::kick ? target.ball : -1;
    kick_mirror_deg = aim_deg;
}

void AimState::update_preview(const Table& table, const PhysicsParams& params,
                              const std::vector<Ball>& balls, bool is_break,
                              const std::function<bool(int ball)>& calls_pocket) {
    // A kick just proposed: the mirror aim ignores the rail's rebound, throw and spin, and
    // would often miss or meet another ball first. Settled once, at the strike as set now.
    if (kick_ball >= 0 && aim_deg == kick_mirror_deg) {
        if (const auto settled = refine_kick(table, params, balls, set_strike(is_break), kick_ball))
            aim_deg = *settled;
        else
            target_line = TargetLine::uncertain_kick;
    }
    kick_ball = -1;
    // Lines as long as the table is round: every line runs to its rail or pocket.
    const double whole_table = 2 * (table.length + table.width);
    full_preview = preview_strike(table, params, balls, set_strike(is_break), whole_table, 1);
    preview = shown_preview(full_preview, assist, params.ball_radius);
    if (full_preview.object_ball != preview_ball)
        pocket_chosen = false;
    preview_ball = full_preview.object_ball;
    if (pocket_chosen)
        return;
    // Propose the obvious pocket: the one the object ball heads for most directly. Pro shows
    // nothing after the contact, so there the proposal reads only what a player sees, the line
    // of centres at contact, not the simulated departure (throw would give it away).
    called_pocket = 0;
    const std::vector<Vec2>& object = full_preview.object_path;
    if (preview_ball > 0 && calls_pocket(preview_ball) && object.size() >= 2) {
        const bool centres = assist == Assist::pro && full_preview.has_ghost &&
                             length(object[0] - full_preview.ghost) > 0;
        const Vec2 dir = centres ? normalized(object[0] - full_preview.ghost)
                                 : normalized(object[1] - object[0]);
        double best = -2;
        for (const Pocket& pocket : table.pockets) {
            const double c = dot(normalized(pocket.position - object[0]), dir);
            if (c > best) {
                best = c;
                called_pocket = pocket.number;
            }
        }
    }
}

CloseUp AimState::close_up_view(const std::vector<Ball>& balls) const {
    CloseUp c;
    c.shown = close_up;
    const double a = aim_deg * std::numbers::pi / 180;
    c.heading = {std::cos(a), std::sin(a)};
    // The contact is the cue's own business at every assist (pro draws the path to it too), so
    // the close-up reads it from the whole aid; only what comes after the contact, the object
    // ball's way out, is the assist's to show or hide.
    const AimPreview& whole = full_preview;
    // The cue ball's last stretch before the contact: squirt and swerve turn it off the aim.
    const std::vector<Vec2>& path = whole.cue_path;
    if (path.size() >= 2 && length(path.back() - path[path.size() - 2]) > 0)
        c.heading = normalized(path.back() - path[path.size() - 2]);
    if (!whole.has_ghost || whole.object_ball < 0)
        return c;
    for (const Ball& b : balls)
        if (b.id == whole.object_ball && b.state != MotionState::pocketed) {
            c.ball = b.id;
            c.object = b.position;
        }
    c.cue = whole.ghost;
    // The object ball's first direction, where the assist shows it.
    const std::vector<Vec2>& out = preview.object_path;
    if (out.size() >= 2 && length(out[1] - out[0]) > 0)
        c.departure = normalized(out[1] - out[0]);
    return c;
}

} // namespace termpool::tui
