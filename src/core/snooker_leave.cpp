// The worth of a snooker table to the computer: pot chances from geometry, and a shot's worth.
#include "snooker_leave.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <termpool/snooker_layout.hpp>

#include "computer_parts.hpp"
#include "shot_lines.hpp"

namespace termpool {
namespace {

// Points and position in one unit: 12 to a point.
constexpr double per_point = 12;
// The worth of being at the table with a sure pot of a red (a chance of 1, weight 1): the
// break that usually follows, about 17 points.
constexpr double chance_worth = 200;
// Keeping the table with nothing to pot is still the initiative.
constexpr double kept_worth = 20;

// Standard normal distribution function.
double normal_cdf(double x) {
    return 0.5 * std::erfc(-x / std::numbers::sqrt2);
}

} // namespace

double snooker_ball_weight(int id) {
    return is_snooker_red(id) ? 1.0 : 0.5 + 0.5 * snooker_value(id) / 7.0;
}

double chance_within(double half_window, double sigma) {
    return 2 * normal_cdf(half_window / sigma) - 1;
}

double snooker_pot_chance(const Table& table, double R, Vec2 cue, Vec2 object, int pocket,
                          double sigma_deg) {
    const Pocket& p = table.pockets[pocket - 1];
    const Vec2 to_pocket = p.position - object;
    const double d2 = length(to_pocket);
    const Vec2 ghost = object - normalized(to_pocket) * (2 * R);
    const double d1 = length(ghost - cue);
    const double cut = dot(normalized(ghost - cue), normalized(to_pocket));
    if (cut <= 0.05 || d2 <= 0)
        return 0;
    // How squarely the ball meets the pocket: 1 along its axis.
    const double square = dot(normalized(to_pocket), -p.capture_normal);
    const bool middle = pocket == 2 || pocket == 5;
    const double tolerance = middle ? 0.031 * std::clamp((square - 0.4) / 0.6, 0.0, 1.0) : 0.025;
    if (tolerance <= 0)
        return 0;
    // The object ball's error is the cue ball's times d1 / (2 R cos cut); the pocket takes a
    // miss of `tolerance` at d2.
    const double window = tolerance * 2 * R * cut / (std::max(d1, R) * d2);
    const double sigma = sigma_deg * std::numbers::pi / 180;
    return chance_within(window, sigma);
}

double snooker_best_chance(const Game& game, double sigma_deg) {
    const double R = game.params().ball_radius;
    return best_clear_pot(game, [&](int target, const Ball& cue, const Ball& object, int pocket,
                                    double) {
        return snooker_ball_weight(target) * snooker_pot_chance(game.table(), R, cue.position,
                                                                object.position, pocket, sigma_deg);
    });
}

double snooker_shot_value(const Verdict& v, int shooter, const Game& after, double sigma_deg) {
    if (v.winner != 0)
        return v.winner == shooter ? 10000 : -10000;
    double s = per_point * (v.points - v.penalty);
    if (v.foul != Foul::none)
        return s - 60 - (v.miss ? 20 : 0);
    if (v.next_shooter == shooter)
        return s + kept_worth + chance_worth * snooker_best_chance(after, sigma_deg);
    s -= chance_worth * snooker_best_chance(after, sigma_deg);
    return with_leave_worth(s, after, true);
}

double with_leave_worth(double s, const Game& after, bool baulk_wants_distance) {
    if (after.shooter_snookered())
        s += 40;
    const Ball* cue = ball_in_play(after.balls(), 0);
    if (!cue)
        return s;
    const Table& t = after.table();
    const double R = after.params().ball_radius;
    double nearest = 1e9;
    for (const int id : after.balls_on())
        if (const Ball* b = ball_in_play(after.balls(), id))
            nearest = std::min(nearest, length(b->position - cue->position));
    if (nearest < 1e9)
        s += 15.0 * std::min(1.0, nearest / (0.5 * t.length));
    const double to_cushion = std::min({cue->position.x, t.length - cue->position.x,
                                        cue->position.y, t.width - cue->position.y}) -
                              R;
    if (to_cushion < 2 * R)
        s += 8;
    if (cue->position.x < snooker_baulk_x(t) &&
        (!baulk_wants_distance || nearest > 0.25 * t.length))
        s += 10;
    return s;
}

bool snooker_frame_lost(const Game& game) {
    if (game.type() != GameType::snooker || game.winner() != 0)
        return false;
    const int me = game.chooser() != 0 ? game.chooser() : game.shooter();
    const int behind = game.score_of(3 - me) - game.score_of(me);
    const auto reds = std::ranges::count_if(game.balls(), [](const Ball& b) {
        return is_snooker_red(b.id) && b.state != MotionState::pocketed;
    });
    // Snookers could still win it, but with the reds nearly gone the frame is as good as lost.
    return reds <= 3 && behind > game.points_remaining();
}

} // namespace termpool
