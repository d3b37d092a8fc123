// Aim, power and spin arithmetic, and the straight-line geometry of the aiming aid.

#include "tui/aim.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace termpool::tui {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

double degrees(double radians) {
    return radians * 180.0 / std::numbers::pi;
}
double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

double wrap_degrees(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d < 0)
        d += 360.0;
    // fmod of a tiny negative number plus 360 rounds to 360 itself.
    return d >= 360.0 ? 0.0 : d;
}

// Smallest t >= 0 at which p + t d (d a unit vector) is `radius` from `centre` while
// approaching it; infinity when it never is.
double cast_circle(Vec2 p, Vec2 d, Vec2 centre, double radius) {
    const Vec2 to = centre - p;
    const double along = dot(to, d);
    if (along <= 0)
        return inf; // behind, or moving away
    const double miss2 = length_squared(to) - along * along;
    const double r2 = radius * radius;
    if (miss2 >= r2)
        return inf;
    return std::max(0.0, along - std::sqrt(r2 - miss2));
}

// Smallest t >= 0 at which p + t d crosses segment a-b from the side `normal` points to.
double cast_segment(Vec2 p, Vec2 d, Vec2 a, Vec2 b, Vec2 normal) {
    const double closing = dot(d, normal);
    if (closing >= 0)
        return inf; // parallel or leaving
    const double t = std::max(0.0, dot(a - p, normal) / closing);
    const Vec2 hit = p + d * t;
    const Vec2 ab = b - a;
    const double u = dot(hit - a, ab) / length_squared(ab);
    return u >= 0 && u <= 1 ? t : inf;
}

struct Hit {
    double t = inf;
    int ball = -1;    // index into balls
    int cushion = -1; // index into table.cushions, or 18 + jaw point
};

// The first thing a ball of radius R centred at p meets moving along d: another ball (skipping
// ids in `ignore`), a cushion or jaw moved R out, or a jaw point.
Hit cast(const Table& table, const std::vector<Ball>& balls, double R, Vec2 p, Vec2 d, int ignore_a,
         int ignore_b) {
    Hit hit;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Ball& b = balls[i];
        if (b.id == ignore_a || b.id == ignore_b || b.state == MotionState::pocketed)
            continue;
        const double t = cast_circle(p, d, b.position, 2 * R);
        if (t < hit.t)
            hit = {t, static_cast<int>(i), -1};
    }
    for (std::size_t k = 0; k < table.cushions.size(); ++k) {
        const CushionSegment& c = table.cushions[k];
        const Vec2 shift = c.normal * R;
        const double t = cast_segment(p, d, c.start + shift, c.end + shift, c.normal);
        if (t < hit.t)
            hit = {t, -1, static_cast<int>(k)};
    }
    for (std::size_t k = 0; k < table.jaw_points.size(); ++k) {
        const double t = cast_circle(p, d, table.jaw_points[k], R);
        if (t < hit.t)
            hit = {t, -1, static_cast<int>(table.cushions.size() + k)};
    }
    return hit;
}

// Where p + t d leaves the box between the cushion noses (p inside): the end of a path that
// runs into a pocket's mouth between the jaws. Infinity when p is outside.
double leave_box(const Table& table, Vec2 p, Vec2 d) {
    if (p.x < 0 || p.y < 0 || p.x > table.length || p.y > table.width)
        return inf;
    double t = inf;
    if (d.x > 0)
        t = std::min(t, (table.length - p.x) / d.x);
    if (d.x < 0)
        t = std::min(t, -p.x / d.x);
    if (d.y > 0)
        t = std::min(t, (table.width - p.y) / d.y);
    if (d.y < 0)
        t = std::min(t, -p.y / d.y);
    return t;
}

// The path from p along d up to the first contact, at most `max_length` long; a leg that
// ends on a cushion (not a jaw) goes on off it, mirrored, `rebounds` times.
std::vector<Vec2> short_path(const Table& table, const std::vector<Ball>& balls, double R, Vec2 p,
                             Vec2 d, int ignore_a, int ignore_b, double max_length,
                             int rebounds = 0) {
    std::vector<Vec2> path{p};
    for (int leg = 0; leg <= rebounds; ++leg) {
        const Hit hit = cast(table, balls, R, p, d, ignore_a, ignore_b);
        const double t = std::isfinite(hit.t) ? hit.t : leave_box(table, p, d);
        const double run = std::isfinite(t) ? std::min(t, max_length) : max_length;
        p = p + d * run;
        path.push_back(p);
        const bool rail = hit.ball < 0 && hit.cushion >= 0 &&
                          hit.cushion < static_cast<int>(table.cushions.size());
        if (!rail || run < t)
            break;
        const Vec2 n = table.cushions[static_cast<std::size_t>(hit.cushion)].normal;
        d = d - n * (2 * dot(d, n));
    }
    return path;
}

} // namespace

double aim_from_pointer(Vec2 cue, Vec2 pointer) {
    const Vec2 d = pointer - cue;
    if (d.x == 0 && d.y == 0)
        return 0;
    return wrap_degrees(degrees(std::atan2(d.y, d.x)));
}

double turn(double deg, double delta) {
    return wrap_degrees(std::round(wrap_degrees(deg + delta) * 1e6) / 1e6);
}

double power_from_distance(double metres) {
    if (!(metres > 0))
        return 0;
    return std::min(1.0, metres / full_power_distance);
}

double power_from_time(double seconds, double period) {
    if (!(period > 0) || !std::isfinite(seconds))
        return 0;
    const double phase = std::fmod(std::fabs(seconds), period) / period;
    return phase < 0.5 ? 2 * phase : 2 - 2 * phase;
}

double speed_from_power(double power, bool is_break) {
    const double p = std::isfinite(power) ? std::clamp(power, 0.0, 1.0) : 0.0;
    const double top = is_break ? max_break_speed : max_shot_speed;
    return min_shot_speed + p * (top - min_shot_speed);
}

double power_from_speed(double speed, bool is_break) {
    const double top = is_break ? max_break_speed : max_shot_speed;
    const double p = (speed - min_shot_speed) / (top - min_shot_speed);
    return std::isfinite(p) ? std::clamp(p, 0.0, 1.0) : 0.0;
}

double clamp_spin(double offset) {
    if (!std::isfinite(offset))
        return 0;
    return std::round(std::clamp(offset, -max_spin, max_spin) * 1e6) / 1e6;
}

AimPreview preview_shot(const Table& table, const std::vector<Ball>& balls, double R, Vec2 cue,
                        double aim_deg, double aid_length) {
    AimPreview out;
    const Vec2 d = unit_from_angle(radians(aim_deg));
    const Hit hit = cast(table, balls, R, cue, d, 0, 0);
    if (!std::isfinite(hit.t)) {
        // Straight into a pocket between the jaws: the path ends in the mouth. Off the table
        // (which the game never asks for) it is a short stub.
        const double t = leave_box(table, cue, d);
        out.cue_path = {cue, cue + d * (std::isfinite(t) ? t : aid_length)};
        return out;
    }
    const Vec2 contact = cue + d * hit.t;
    out.cue_path = {cue, contact};
    if (hit.ball < 0) {
        out.cushion = hit.cushion < static_cast<int>(table.cushions.size()) ? hit.cushion : -1;
        return out;
    }
    add_contact_lines(out, table, balls, R, contact, d,
                      balls[static_cast<std::size_t>(hit.ball)].id, aid_length);
    return out;
}

void add_contact_lines(AimPreview& out, const Table& table, const std::vector<Ball>& balls,
                       double R, Vec2 contact, Vec2 d, int object_id, double aid_length,
                       int rebounds) {
    const auto object =
        std::find_if(balls.begin(), balls.end(), [&](const Ball& b) { return b.id == object_id; });
    if (object == balls.end())
        return;
    out.object_ball = object_id;
    out.has_ghost = true;
    out.ghost = contact;
    // The object ball leaves along the line of centres; the cue ball keeps the rest of its
    // velocity, which is at right angles to it (the tangent line).
    const Vec2 n = normalized(object->position - contact);
    out.object_path =
        short_path(table, balls, R, object->position, n, 0, object_id, aid_length, rebounds);
    const Vec2 tangent = d - n * dot(d, n);
    if (length(tangent) > 1e-6) {
        out.deflect_path = short_path(table, balls, R, contact, normalized(tangent), 0, object_id,
                                      aid_length, rebounds);
    }
}

namespace {

// The id of the first ball a cue ball sent from `cue` at `aim_deg` meets, -1 for none.
int first_ball_hit(const Table& table, const std::vector<Ball>& balls, double R, Vec2 cue,
                   double aim_deg) {
    const Hit hit = cast(table, balls, R, cue, unit_from_angle(radians(aim_deg)), 0, 0);
    return hit.ball >= 0 ? balls[static_cast<std::size_t>(hit.ball)].id : -1;
}

// An aim that meets ball `target` before any other ball: at its centre if that is clear, else
// across its silhouette from the middle outwards. Nothing when every line is blocked.
std::optional<double> clear_aim_at(const Table& table, const std::vector<Ball>& balls, double R,
                                   Vec2 cue, const Ball& target) {
    const Vec2 to_ball = target.position - cue;
    const double distance = length(to_ball);
    const double centre = aim_from_pointer(cue, target.position);
    if (distance <= 2 * R)
        return centre;
    const double half_width = degrees(std::asin(2 * R / distance));
    constexpr int steps = 8;
    for (int k = 0; k <= steps; ++k)
        for (const int sign : {1, -1}) {
            const double aim = turn(centre, sign * half_width * 0.95 * k / steps);
            if (first_ball_hit(table, balls, R, cue, aim) == target.id)
                return aim;
            if (k == 0)
                break;
        }
    return std::nullopt;
}

// One-rail kicks at ball `target` for a cue ball that has no straight line to it: for each
// rail, aim at the target's mirror image in the line the cue ball's centre meets the rail on,
// and keep the aim when the cue ball reaches that rail first and then the target before any
// other ball. The shortest such path, or nothing. (The real rebound differs a little from the
// mirror, so this is the shot a player would try, not a promise.)
std::optional<std::pair<double, double>> kick_aim_at(const Table& table,
                                                     const std::vector<Ball>& balls, double R,
                                                     Vec2 cue, const Ball& target) {
    std::optional<std::pair<double, double>> best; // aim, path length
    for (int k = 0; k < 6; ++k) {
        const CushionSegment& rail = table.cushions[static_cast<std::size_t>(k)];
        const Vec2 on_line = rail.start + rail.normal * R;
        const Vec2 image =
            target.position - rail.normal * (2 * dot(target.position - on_line, rail.normal));
        const double aim = aim_from_pointer(cue, image);
        const Vec2 d = unit_from_angle(radians(aim));
        const Hit first = cast(table, balls, R, cue, d, 0, 0);
        if (first.ball >= 0 || first.cushion != k || !std::isfinite(first.t))
            continue;
        const Vec2 bounce = cue + d * first.t;
        const Vec2 out = d - rail.normal * (2 * dot(d, rail.normal));
        const Hit second = cast(table, balls, R, bounce, out, 0, 0);
        if (second.ball < 0 || balls[static_cast<std::size_t>(second.ball)].id != target.id)
            continue;
        const double path = first.t + second.t;
        if (!best || path < best->second)
            best = std::pair{aim, path};
    }
    return best;
}

} // namespace

std::vector<TargetChoice> rank_targets(const Table& table, const std::vector<Ball>& balls, double R,
                                       Vec2 cue, const std::vector<int>& legal) {
    // Weights: one degree of cut counts as much as 5 cm of travel; a side pocket entered at
    // an angle is harder still, and beyond 60 degrees from square the ball hits the jaw. A
    // pocket whose path another ball blocks costs as much as a thin cut. A target is only
    // offered along a line on which the cue ball meets it first, so that shooting the proposed
    // aim never fouls by hitting another ball first; a target hidden behind other balls is
    // offered as a one-rail kick, and one with no line at all comes last.
    constexpr double per_metre = 20.0;
    constexpr double max_cut = 80.0;
    constexpr double side_limit = 60.0;
    constexpr double blocked_pocket = 60.0;
    constexpr double no_pocket = 1000.0, kick_only = 1500.0, no_clear_line = 2000.0;
    std::vector<TargetChoice> out;
    for (const Ball& b : balls) {
        if (b.id == 0 || b.state == MotionState::pocketed)
            continue;
        if (std::find(legal.begin(), legal.end(), b.id) == legal.end())
            continue;
        const Vec2 to_ball = b.position - cue;
        const std::optional<double> direct = clear_aim_at(table, balls, R, cue, b);
        TargetChoice best{b.id, 0, direct.value_or(aim_from_pointer(cue, b.position)),
                          (direct ? no_pocket : no_clear_line) + per_metre * length(to_ball),
                          direct ? TargetLine::straight : TargetLine::none};
        if (!direct)
            if (const auto kick = kick_aim_at(table, balls, R, cue, b))
                best = {b.id, 0, kick->first, kick_only + per_metre * kick->second,
                        TargetLine::kick};
        for (const Pocket& pocket : table.pockets) {
            const Vec2 to_pocket = pocket.position - b.position;
            const double pocket_distance = length(to_pocket);
            if (pocket_distance < 1e-9)
                continue;
            const Vec2 u = to_pocket / pocket_distance;
            const Vec2 ghost = b.position - u * (2 * R);
            const Vec2 shot = ghost - cue;
            const double shot_length = length(shot);
            if (shot_length < 1e-9)
                continue;
            const double cut =
                degrees(std::acos(std::clamp(dot(shot / shot_length, u), -1.0, 1.0)));
            if (cut > max_cut)
                continue;
            double score = cut + per_metre * (shot_length + pocket_distance);
            const bool side = pocket.number == 2 || pocket.number == 5;
            if (side) {
                const double off_square = degrees(std::acos(std::clamp(std::fabs(u.y), 0.0, 1.0)));
                if (off_square > side_limit)
                    continue;
                score += off_square / 2;
            }
            if (score >= best.difficulty)
                continue;
            const double aim = aim_from_pointer(cue, ghost);
            if (first_ball_hit(table, balls, R, cue, aim) != b.id)
                continue;
            const Hit on_the_way = cast(table, balls, R, b.position, u, 0, b.id);
            if (on_the_way.ball >= 0 && on_the_way.t < pocket_distance)
                score += blocked_pocket;
            if (score < best.difficulty)
                best = {b.id, pocket.number, aim, score, TargetLine::straight};
        }
        out.push_back(best);
    }
    std::stable_sort(out.begin(), out.end(), [](const TargetChoice& a, const TargetChoice& b) {
        return a.difficulty != b.difficulty ? a.difficulty < b.difficulty : a.ball < b.ball;
    });
    return out;
}

std::vector<TargetChoice> rank_openings(const Table& table, const std::vector<Ball>& balls,
                                        double R, Vec2 cue, const std::vector<int>& legal,
                                        Assist assist) {
    std::vector<TargetChoice> out = rank_targets(table, balls, R, cue, legal);
    if (assist == Assist::guided)
        return out;
    // A full hit: the aim shows the ball, and the cut is the player's to find. A kick is aimed
    // at the ball's image, and a ball with no line at its centre, already.
    for (TargetChoice& t : out) {
        if (t.line != TargetLine::straight)
            continue;
        const auto ball =
            std::find_if(balls.begin(), balls.end(), [&](const Ball& b) { return b.id == t.ball; });
        if (ball != balls.end())
            t.aim_deg = clear_aim_at(table, balls, R, cue, *ball)
                            .value_or(aim_from_pointer(cue, ball->position));
    }
    return out;
}

std::vector<int> targets_easiest_first(const Table& table, const std::vector<Ball>& balls, double R,
                                       Vec2 cue, const std::vector<int>& legal) {
    std::vector<int> ids;
    for (const TargetChoice& t : rank_targets(table, balls, R, cue, legal))
        ids.push_back(t.ball);
    return ids;
}

} // namespace termpool::tui
