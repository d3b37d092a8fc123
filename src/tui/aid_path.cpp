// The aid's cue-ball path from the simulator: a World is struck and stepped up to the cue
// ball's first contact, and its recorded motion is sampled into a polyline.

#include "tui/aid_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

namespace termpool::tui {
namespace {

// Events before the cue ball's first contact on a table at rest: it slides, rolls, perhaps
// spins in place and stops. Far more than it needs; the bound keeps a broken table from
// stalling the aid.
constexpr int max_events = 64;

bool ends_cue_path(const Event& e) {
    if (e.ball != 0) // the cue ball is id 0, the lower id of any pair it is in
        return false;
    switch (e.kind) {
    case EventKind::ball_ball:
    case EventKind::cushion:
    case EventKind::jaw:
    case EventKind::pocket:
    case EventKind::spinning:
    case EventKind::stopped:
    case EventKind::off_table:
        return true;
    case EventKind::sliding:
    case EventKind::rolling:
        return false;
    }
    return false;
}

std::optional<Ball> cue_in(const std::vector<Ball>& balls) {
    for (const Ball& b : balls)
        if (b.id == 0)
            return b;
    return std::nullopt;
}

void add_point(std::vector<Vec2>& path, Vec2 p) {
    if (path.empty() || path.back() != p)
        path.push_back(p);
}

// `path` without the points that lie on the line between their neighbours (to a micrometre): a
// straight stretch is drawn as one line, dot for dot as the straight aid draws it.
std::vector<Vec2> without_straight_points(const std::vector<Vec2>& path) {
    constexpr double on_line = 1e-6; // m
    if (path.size() <= 2)
        return path;
    std::vector<Vec2> out{path.front()};
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
        const Vec2 d = normalized(path[i + 1] - out.back());
        if (std::fabs(cross(d, path[i] - out.back())) > on_line)
            out.push_back(path[i]);
    }
    out.push_back(path.back());
    return out;
}

// The start of `path` up to `left` metres along it.
std::vector<Vec2> trimmed(const std::vector<Vec2>& path, double left) {
    if (path.empty())
        return path;
    std::vector<Vec2> out{path.front()};
    for (std::size_t i = 1; i < path.size(); ++i) {
        const double leg = length(path[i] - path[i - 1]);
        if (leg >= left) {
            out.push_back(path[i - 1] + normalized(path[i] - path[i - 1]) * left);
            break;
        }
        out.push_back(path[i]);
        left -= leg;
    }
    return out;
}

} // namespace

AimPreview preview_strike(const Table& table, const PhysicsParams& params,
                          const std::vector<Ball>& balls, const Strike& strike, double aid_length,
                          int rebounds) {
    const std::optional<Ball> cue = cue_in(balls);
    if (!cue || cue->state == MotionState::pocketed)
        return {};
    if (strike_problem(strike, params))
        return preview_shot(table, balls, params.ball_radius, cue->position, strike.angle_deg,
                            aid_length);

    World world(table, params, balls);
    world.record(true);
    world.strike(strike);
    const std::optional<Ball> struck = cue_in(world.balls());
    std::optional<Event> end;
    std::optional<Event> rail; // a kick's first rail
    for (int n = 0, rails = 0; n < max_events && !end; ++n) {
        const std::optional<Event> e = world.step();
        if (!e)
            break;
        if (!ends_cue_path(*e))
            continue;
        // A rail before any ball: a kick, followed on to its next contact when asked.
        if (e->kind == EventKind::cushion && rails < rebounds) {
            ++rails;
            if (!rail)
                rail = e;
            continue;
        }
        end = e;
    }
    const double end_time = end ? end->time : world.time();

    const Trajectory& motion = world.trajectory();
    const auto slot = static_cast<std::size_t>(
        std::find_if(balls.begin(), balls.end(), [](const Ball& b) { return b.id == 0; }) -
        balls.begin());
    const auto cue_at = [&](double t) { return cue_in(motion.sample(t)).value_or(*cue); };
    // The cue ball's centre from the strike up to `until`, in chords.
    const auto path_until = [&](double until) {
        std::vector<Vec2> path;
        const std::vector<Trajectory::Piece>& pieces = motion.pieces(slot);
        for (std::size_t i = 0; i < pieces.size() && pieces[i].start < until; ++i) {
            const double from = pieces[i].start;
            const double to = i + 1 < pieces.size() ? std::min(pieces[i + 1].start, until) : until;
            for (int k = 0; k < aid_chords_per_piece; ++k)
                add_point(path, cue_at(from + (to - from) * k / aid_chords_per_piece).position);
        }
        const Vec2 last = cue_at(until).position;
        add_point(path, last);
        path = without_straight_points(path);
        if (path.size() < 2) // a contact at once: one point twice, as the straight aid has
            path = {cue->position, last};
        return path;
    };
    AimPreview out;
    out.cue_path = path_until(end_time);
    const Vec2 contact = out.cue_path.back();
    if (rail) {
        out.cushion = rail->other;
        out.kick_leg = path_until(rail->time);
    }
    if (!end)
        return out;
    if (end->kind == EventKind::cushion && !rail)
        out.cushion = end->other;
    if (end->kind != EventKind::ball_ball)
        return out;
    // The direction just before the contact: the sample at the contact's time is already the
    // motion after it. A contact at once (a frozen ball) has the strike's own direction.
    const Ball before =
        end_time > 0 ? cue_at(std::nextafter(end_time, 0.0)) : struck.value_or(*cue);
    Vec2 d = normalized(before.velocity);
    if (d == Vec2{})
        d = normalized(contact - cue->position);
    add_contact_lines(out, table, balls, params.ball_radius, contact, d, end->other, aid_length,
                      rebounds);
    return out;
}

AimPreview shown_preview(const AimPreview& full, Assist assist, double R) {
    if (assist == Assist::guided)
        return full;
    AimPreview out;
    out.cushion = full.cushion;
    // The cue ball's path to its first contact: a kick's ends on its rail, and what comes after
    // the rail is not shown.
    out.cue_path = full.kick_leg.empty() ? full.cue_path : full.kick_leg;
    if (!full.kick_leg.empty())
        return out;
    if (assist == Assist::pro)
        return out;
    out.object_ball = full.object_ball;
    out.has_ghost = full.has_ghost;
    out.ghost = full.ghost;
    out.object_path = trimmed(full.object_path, standard_object_diameters * 2 * R);
    return out;
}

} // namespace termpool::tui
