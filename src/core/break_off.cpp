// The snooker break-off: the geometric clip on the end red, then a few nearby strikes tried
// with the simulator, since how far the cue ball comes back depends on the throw and the
// cushions more than on any line drawn.

#include <termpool/break_off.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <termpool/portable_math.hpp>
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

// The red at the end of the back row (the reds furthest up the table) on the cue ball's side.
const Ball* end_red(const std::vector<Ball>& balls, Vec2 cue, double middle_y, double R) {
    double back = -1e300;
    for (const Ball& b : balls)
        if (is_snooker_red(b.id) && b.state != MotionState::pocketed)
            back = std::max(back, b.position.x);
    const double side = cue.y > middle_y ? 1.0 : -1.0; // the yellow's side on a tie
    const Ball* end = nullptr;
    for (const Ball& b : balls)
        if (is_snooker_red(b.id) && b.state != MotionState::pocketed && b.position.x > back - R &&
            (!end || side * b.position.y > side * end->position.y))
            end = &b;
    return end;
}

// The aim that passes `offset` radii outside the red's centre, on the side away from the pack.
double clip_aim_deg(Vec2 cue, const Ball& red, double middle_y, double offset, double R) {
    const Vec2 along = normalized(red.position - cue);
    Vec2 outward{along.y, -along.x};
    if (dot(outward, Vec2{0, red.position.y - middle_y}) < 0)
        outward = -outward;
    return degrees(red.position + outward * (offset * R) - cue);
}

} // namespace

Strike break_off_strike(const Table& table, const PhysicsParams& params,
                        const std::vector<Ball>& balls) {
    const double R = params.ball_radius;
    const double middle_y = table.width / 2;
    const Ball* cue = cue_ball(balls);
    const Ball* red = cue ? end_red(balls, cue->position, middle_y, R) : nullptr;
    if (!cue || !red)
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
            const Strike strike{speed, clip_aim_deg(cue->position, *red, middle_y, offset, R), 0,
                                0};
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
    return {break_off_speed, clip_aim_deg(cue->position, *red, middle_y, plain_offset, R), 0, 0};
}

} // namespace termpool
