#pragma once
// Builders for referee tests: layouts, aimed shots and hand-made shot results.

#include <cmath>
#include <numbers>
#include <termpool/rules.hpp>

#include "physics_helpers.hpp"

namespace termpool::test {

inline const Table& nine_foot() {
    static const Table table = make_table(TableSize::nine_foot);
    return table;
}

constexpr double ball_radius = 0.028575;

/// Direction in degrees from a to b.
inline double aim_deg(Vec2 a, Vec2 b) {
    return std::atan2(b.y - a.y, b.x - a.x) * 180 / std::numbers::pi;
}

/// The strike angle that sends `object` towards `target` (ghost-ball aim) from `cue`.
inline double ghost_aim_deg(Vec2 cue, Vec2 object, Vec2 target) {
    const Vec2 ghost = object - normalized(target - object) * (2 * ball_radius);
    return aim_deg(cue, ghost);
}

/// Position of pocket `n` (1..6).
inline Vec2 pocket_at(int n) {
    return nine_foot().pockets[n - 1].position;
}

/// A game from a position; the balls are given as (id, x, y).
inline Game position(GameType type, std::vector<Ball> balls, int shooter = 1,
                     Group group = Group::open, bool is_break = false, bool push_out = false) {
    return Game::from_position(type, nine_foot(), PhysicsParams{}, std::move(balls), shooter, group,
                               is_break, push_out);
}

/// A shot result made by hand from the game's balls and a list of events: balls with a
/// `pocket` event end in that pocket, the others stay where they are.
inline ShotResult hand_made(const Game& game, std::vector<Event> events) {
    ShotResult r;
    r.events = events;
    r.balls = game.balls();
    for (const Event& e : events) {
        if (e.kind != EventKind::pocket)
            continue;
        for (Ball& b : r.balls)
            if (b.id == e.ball) {
                b.state = MotionState::pocketed;
                b.pocket = e.other;
            }
    }
    return r;
}

inline Event hit(int a, int b, double t = 0.1) {
    return {t, EventKind::ball_ball, a, b};
}
inline Event rail(int ball, double t = 0.2) {
    return {t, EventKind::cushion, ball, 0};
}
inline Event drop(int ball, int pocket, double t = 0.3) {
    return {t, EventKind::pocket, ball, pocket};
}
inline Event off(int ball, double t = 0.3) {
    return {t, EventKind::off_table, ball, 0};
}

/// Every ball of `ids` placed on a loose grid far from the pockets, cue ball first.
inline std::vector<Ball> spread(std::vector<int> ids) {
    std::vector<Ball> balls;
    int k = 0;
    for (const int id : ids) {
        balls.push_back(ball_at(id, 0.4 + 0.2 * (k % 8), 0.4 + 0.25 * (k / 8)));
        ++k;
    }
    return balls;
}

} // namespace termpool::test

namespace termpool::test {

/// Unit vector from pocket `n` straight out into the table (45 degrees at a corner).
inline Vec2 out_of_pocket(int n) {
    const Vec2 p = pocket_at(n);
    const double sy = p.y == 0 ? 1 : -1;
    if (n == 2 || n == 5)
        return {0, sy};
    const double sx = p.x == 0 ? 1 : -1;
    return Vec2{sx, sy} * (std::numbers::sqrt2 / 2);
}

/// Ball `id` `object_distance` m out of pocket `n`, the cue ball `cue_distance` m behind it on
/// the same line, so that a straight strike pots it.
inline std::vector<Ball> straight_in(int id, int n, double object_distance = 0.3,
                                     double cue_distance = 0.3) {
    const Vec2 out = out_of_pocket(n);
    const Vec2 object = pocket_at(n) + out * object_distance;
    const Vec2 cue = object + out * cue_distance;
    return {ball_at(0, cue.x, cue.y), ball_at(id, object.x, object.y)};
}

/// The strike for straight_in: at the pocket, firm, with a little draw so the cue ball stays.
inline Strike straight_strike(int n, double speed = 2.0) {
    const Vec2 out = out_of_pocket(n);
    return {speed, std::atan2(-out.y, -out.x) * 180 / std::numbers::pi, 0, -0.3};
}

/// `balls` plus more balls placed out of the way (bottom-left quarter of the table).
inline std::vector<Ball> with_extra(std::vector<Ball> balls, std::vector<int> ids) {
    int k = 0;
    for (const int id : ids) {
        balls.push_back(ball_at(id, 0.5 + 0.12 * (k % 5), 0.85 + 0.12 * (k / 5)));
        ++k;
    }
    return balls;
}

} // namespace termpool::test
