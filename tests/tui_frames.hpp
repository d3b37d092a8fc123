#pragma once
// Views shared by the terminal-game tests: the 8-ball rack with the cue ball in the kitchen,
// aimed at the apex ball with the aiming aid, and a crowded table in the middle of a match. The
// aid is the game's: the simulator's path for the strike the view shows.

#include <cmath>
#include <termpool/rack.hpp>

#include "tui/aid_path.hpp"
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
    v.is_break = true;
    v.side = 0.1;
    v.follow = -0.2;
    const tui::AimPreview p =
        tui::preview_strike(table, params, v.balls, {v.speed, aim_deg, v.side, v.follow});
    v.cue_path = p.cue_path;
    v.has_ghost = p.has_ghost;
    v.ghost = p.ghost;
    v.object_path = p.object_path;
    v.deflect_path = p.deflect_path;
    return v;
}

/// Mid-game in a race to 5 (Alice 2, Bob 1): Alice has the solids and has pocketed the 1 and
/// the 5, Bob the stripes with the 11 and the 14 down. Eight balls lie touching in a bunch
/// (the 3 beside the 13, the 12 beside the 2 and the 15, the 10 beside the 7), the 6 and the
/// 9 touch on the bottom cushion and the 4 waits by the top-right corner. Alice aims at the 3,
/// which she calls in the top-right corner.
inline tui::View crowded_view(const Table& table) {
    const PhysicsParams params;
    const double d = 2 * params.ball_radius + 0.0005, R = params.ball_radius;
    const double row = d * std::sqrt(3.0) / 2;
    const Vec2 bunch{1.85, 0.85};
    const auto at = [&](double i, double j) { return Vec2{bunch.x + i * d, bunch.y + j * row}; };
    const auto ball = [](int id, Vec2 p, MotionState state = MotionState::stationary) {
        Ball b;
        b.id = id;
        b.position = p;
        b.state = state;
        return b;
    };
    tui::View v;
    v.table = &table;
    v.balls = {ball(0, {1.2, 0.55}),
               ball(3, at(0, 0)),
               ball(13, at(1, 0)),
               ball(8, at(2, 0)),
               ball(12, at(0.5, 1)),
               ball(2, at(1.5, 1)),
               ball(15, at(2.5, 1)),
               ball(10, at(1, 2)),
               ball(7, at(2, 2)),
               ball(6, {0.9, R + 0.002}),
               ball(9, {0.9 + d, R + 0.002}),
               ball(4, {2.42, 1.15}),
               ball(1, table.pockets[5].position, MotionState::pocketed),
               ball(5, table.pockets[1].position, MotionState::pocketed),
               ball(11, table.pockets[3].position, MotionState::pocketed),
               ball(14, table.pockets[2].position, MotionState::pocketed)};
    v.ball_radius = params.ball_radius;
    v.game = GameType::eight_ball;
    v.names[0] = "Alice";
    v.names[1] = "Bob";
    v.shooter = 1;
    v.groups[0] = Group::solids;
    v.groups[1] = Group::stripes;
    v.race_to = 5;
    v.racks_won[0] = 2;
    v.racks_won[1] = 1;
    v.message = "Alice pocketed the 5 and shoots again.";
    v.aiming = true;
    const Vec2 cue = v.balls[0].position, target = v.balls[1].position;
    v.aim_deg = std::atan2(target.y - cue.y, target.x - cue.x) * 180 / M_PI;
    v.power = 0.35;
    v.speed = tui::speed_from_power(v.power, false);
    v.called_pocket = 4;
    v.called_ball = 3;
    const tui::AimPreview p = tui::preview_strike(table, params, v.balls, {v.speed, v.aim_deg});
    v.cue_path = p.cue_path;
    v.has_ghost = p.has_ghost;
    v.ghost = p.ghost;
    v.object_path = p.object_path;
    v.deflect_path = p.deflect_path;
    return v;
}

} // namespace termpool::test
