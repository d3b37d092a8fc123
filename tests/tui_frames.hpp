#pragma once
// Views shared by the terminal-game tests: the 8-ball rack with the cue ball in the kitchen,
// aimed at the apex ball with the aiming aid.

#include <termpool/rack.hpp>

#include "tui/aim.hpp"
#include "tui/view.hpp"

namespace termpool::test {

/// The unseeded 8-ball rack on `table`, player 1 aiming `aim_deg` with the aid showing.
inline tui::View rack_view(const Table& table, double aim_deg = 1.5) {
    const PhysicsParams params;
    tui::View v;
    v.table = &table;
    v.balls = make_rack(table, params, RackType::eight_ball);
    v.ball_radius = params.ball_radius;
    v.game = GameType::eight_ball;
    v.names[0] = "Alice";
    v.names[1] = "Bob";
    v.shooter = 1;
    v.message = "Alice to break: ball in hand behind the head string.";
    v.aiming = true;
    v.aim_deg = aim_deg;
    v.power = 0.55;
    v.speed = tui::speed_from_power(v.power, true);
    v.side = 0.1;
    v.follow = -0.2;
    const tui::AimPreview p =
        tui::preview_shot(table, v.balls, params.ball_radius, table.head_spot(), aim_deg);
    v.cue_path = p.cue_path;
    v.has_ghost = p.has_ghost;
    v.ghost = p.ghost;
    v.object_path = p.object_path;
    v.deflect_path = p.deflect_path;
    return v;
}

} // namespace termpool::test
