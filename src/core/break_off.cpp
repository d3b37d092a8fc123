// The snooker break-off: the geometric clip on the end red, then a few nearby strikes tried
// with the simulator, since how far the cue ball comes back depends on the throw and the
// cushions more than on any line drawn.

#include <termpool/break_off.hpp>

#include "../support/portable_math.hpp"
#include <cmath>
#include <numbers>
#include <optional>
#include <termpool/rules.hpp>
#include <termpool/snooker_layout.hpp>

namespace termpool {
namespace {

// The candidates: the line of aim this many radii outside the red's centre (2 grazes it), and
// these speeds. Soft enough that the pack barely opens, firm enough to come back to baulk.
constexpr double clip_offsets[] = {1.3, 1.4, 1.5, 1.6, 1.7, 1.75, 1.8, 1.85, 1.9};
constexpr double clip_speeds[] = {2.5, 2.75, 3.0, 3.25, 3.5, 3.75, 4.0};
constexpr double plain_offset = 1.75;
// Metres of the cue ball's end position worth one m/s away from break_off_speed: a softer
// break-off is taken when the cue ball comes back about as far.
constexpr double metres_per_speed = 0.2;

double degrees(Vec2 v) {
    return portable::atan2(v.y, v.x) * 180 / std::numbers::pi;
}

const Ball* cue_ball(const std::vector<Ball>& balls) {
    for (const Ball& b : balls)
        if (b.id == 0 && b.state != MotionState::pocketed)
            return &b;
    return nullptr;
}

// The middle of the pack across the table: the mean of the reds' y.
double pack_middle_y(const std::vector<Ball>& balls) {
    double sum = 0;
    int n = 0;
    for (const Ball& b : balls)
        if (is_snooker_red(b.id) && b.state != MotionState::pocketed)
            sum += b.position.y, ++n;
    return n > 0 ? sum / n : 0;
}

} // namespace

const Ball* break_off_red(const std::vector<Ball>& balls, double R) {
    const Ball* cue = cue_ball(balls);
    if (!cue)
        return nullptr;
    double back = -1e300;
    for (const Ball& b : balls)
        if (is_snooker_red(b.id) && b.state != MotionState::pocketed)
            back = std::max(back, b.position.x);
    // The back row (within a radius of the red furthest up the table), its end on the cue
    // ball's side of the pack; the yellow's side (low y) when the cue ball is in the middle.
    const double side = cue->position.y > pack_middle_y(balls) ? 1.0 : -1.0;
    const Ball* end = nullptr;
    for (const Ball& b : balls)
        if (is_snooker_red(b.id) && b.state != MotionState::pocketed && b.position.x > back - R &&
            (!end || side * b.position.y > side * end->position.y))
            end = &b;
    return end;
}

double break_off_aim_deg(const std::vector<Ball>& balls, double R, double offset_radii) {
    const Ball* cue = cue_ball(balls);
    const Ball* red = break_off_red(balls, R);
    if (!cue || !red)
        return 0;
    // Outside the red: on the side away from the middle of the pack.
    const Vec2 along = normalized(red->position - cue->position);
    Vec2 outward{along.y, -along.x};
    if (dot(outward, Vec2{0, red->position.y - pack_middle_y(balls)}) < 0)
        outward = -outward;
    return degrees(red->position + outward * (offset_radii * R) - cue->position);
}

Strike break_off_strike(const Table& table, const PhysicsParams& params,
                        const std::vector<Ball>& balls) {
    const double R = params.ball_radius;
    if (!break_off_red(balls, R))
        return {break_off_speed, 0, 0, 0};
    const Game start = Game::from_snooker_position(table, params, balls, 1, SnookerState{});
    const double baulk_x = snooker_baulk_x(table);
    struct Best {
        Strike strike;
        double score = 0;
        bool in_baulk = false;
    };
    std::optional<Best> best;
    for (const double offset : clip_offsets)
        for (const double speed : clip_speeds) {
            const Strike strike{speed, break_off_aim_deg(balls, R, offset), 0, 0};
            Game trial = start;
            ShotResult result;
            const Verdict verdict = trial.play(strike, {}, &result);
            if (verdict.foul != Foul::none || !is_snooker_red(verdict.first_contact))
                continue;
            const Ball* end = cue_ball(result.balls);
            if (!end)
                continue;
            const bool in_baulk = end->position.x <= baulk_x;
            const double score =
                end->position.x + metres_per_speed * std::abs(speed - break_off_speed);
            // Back in baulk first; then the cue ball nearest the baulk cushion, softer on a tie.
            if (!best || (in_baulk && !best->in_baulk) ||
                (in_baulk == best->in_baulk && score < best->score))
                best = Best{strike, score, in_baulk};
        }
    if (best)
        return best->strike;
    return {break_off_speed, break_off_aim_deg(balls, R, plain_offset), 0, 0};
}

} // namespace termpool
