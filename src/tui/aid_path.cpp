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

} // namespace

AimPreview preview_strike(const Table& table, const PhysicsParams& params,
                          const std::vector<Ball>& balls, const Strike& strike, double aid_length) {
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
    for (int n = 0; n < max_events && !end; ++n) {
        const std::optional<Event> e = world.step();
        if (!e)
            break;
        if (ends_cue_path(*e))
            end = e;
    }
    const double end_time = end ? end->time : world.time();

    const Trajectory& motion = world.trajectory();
    const auto slot = static_cast<std::size_t>(
        std::find_if(balls.begin(), balls.end(), [](const Ball& b) { return b.id == 0; }) -
        balls.begin());
    const auto cue_at = [&](double t) { return cue_in(motion.sample(t)).value_or(*cue); };
    AimPreview out;
    const std::vector<Trajectory::Piece>& pieces = motion.pieces(slot);
    for (std::size_t i = 0; i < pieces.size() && pieces[i].start < end_time; ++i) {
        const double from = pieces[i].start;
        const double to =
            i + 1 < pieces.size() ? std::min(pieces[i + 1].start, end_time) : end_time;
        for (int k = 0; k < aid_chords_per_piece; ++k)
            add_point(out.cue_path, cue_at(from + (to - from) * k / aid_chords_per_piece).position);
    }
    const Vec2 contact = cue_at(end_time).position;
    add_point(out.cue_path, contact);
    out.cue_path = without_straight_points(out.cue_path);
    if (out.cue_path.size() < 2) // a contact at once: one point twice, as the straight aid has
        out.cue_path = {cue->position, contact};
    if (!end)
        return out;
    if (end->kind == EventKind::cushion)
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
    add_contact_lines(out, table, balls, params.ball_radius, contact, d, end->other, aid_length);
    return out;
}

} // namespace termpool::tui
