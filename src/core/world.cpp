#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <termpool/simulator.hpp>

#include "core/collision.hpp"
#include "core/contact_time.hpp"
#include "core/motion.hpp"

namespace termpool {
namespace {

using core::Path;
constexpr double infinity = std::numeric_limits<double>::infinity();

bool moves(const Ball& b) {
    return b.state == MotionState::sliding || b.state == MotionState::rolling;
}

// What a ball will do next on its own, against the table (pair contacts are kept apart).
enum class BoundaryKind { none, transition, rail, jaw_line, jaw_point, capture };

struct BoundaryEvent {
    double time = infinity;
    BoundaryKind kind = BoundaryKind::none;
    int feature = 0; // rail or jaw segment index into Table::cushions, jaw point, or pocket index
};

// A ball's current piece of motion, from `start` to `end` (absolute times).
struct Slot {
    Ball ball; // state at `start`
    double start = 0;
    double end = infinity; // next transition
    Vec2 acceleration;     // physical model: constant over the piece
};

struct Box {
    Vec2 min, max;
};

// Range of x0 + v t + a t^2 / 2 over [0, T].
void extend_range(double x0, double v, double a, double T, double& lo, double& hi) {
    auto at = [&](double t) { return x0 + v * t + 0.5 * a * t * t; };
    lo = hi = x0;
    const double end = at(T);
    lo = std::min(lo, end);
    hi = std::max(hi, end);
    if (a != 0) {
        const double t_turn = -v / a;
        if (t_turn > 0 && t_turn < T) {
            lo = std::min(lo, at(t_turn));
            hi = std::max(hi, at(t_turn));
        }
    }
}

// Box of a centre moving along `path` for `duration` seconds.
Box path_box(const Path& path, double duration) {
    Box box;
    extend_range(path.position.x, path.velocity.x, path.acceleration.x, duration, box.min.x,
                 box.max.x);
    extend_range(path.position.y, path.velocity.y, path.acceleration.y, duration, box.min.y,
                 box.max.y);
    return box;
}

// The box with corners a and b.
Box box_of(Vec2 a, Vec2 b) {
    return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}

bool boxes_within(const Box& a, const Box& b, double margin) {
    return a.min.x - margin <= b.max.x && b.min.x - margin <= a.max.x &&
           a.min.y - margin <= b.max.y && b.min.y - margin <= a.max.y;
}

} // namespace

struct World::Impl {
    Table table;
    PhysicsParams params;
    std::vector<Slot> slots;
    std::vector<BoundaryEvent> boundary;
    // Box of each slot's path, up to the ball's next table contact, and whether the ball moves:
    // short arrays of their own, so that the pair search over all balls culls without touching
    // the slots. A pocketed ball's box is empty (min > max): every overlap test with it fails.
    std::vector<Box> reach;
    std::vector<std::uint8_t> moving;
    // Contact time of every pair, kept in both orders ([i * n + j] == [j * n + i]) so that a
    // ball's row holds all its pairs.
    std::vector<double> pair_time;
    // 1 where pair_time holds only a lower bound on the contact (same layout): the search is put
    // off until the bound is the earliest of all events, and most never get that far.
    std::vector<std::uint8_t> pair_bound;
    // Earliest contact in each ball's row, so that finding the next event scans n values rather
    // than all n^2 / 2 pairs.
    std::vector<double> row_min;
    double now = 0;
    std::size_t events = 0;
    std::vector<Event> pending; // reported by the next step before anything is simulated
    bool recording = false;
    Trajectory trajectory;

    Impl(const Table& t, const PhysicsParams& p, std::vector<Ball> balls)
        : table(t), params(p), trajectory(p, balls.size()) {
        slots.resize(balls.size());
        boundary.resize(balls.size());
        reach.resize(balls.size());
        moving.resize(balls.size());
        pair_time.assign(balls.size() * balls.size(), infinity);
        pair_bound.assign(balls.size() * balls.size(), 0);
        row_min.assign(balls.size(), infinity);
        for (std::size_t i = 0; i < balls.size(); ++i) {
            set_slot(i, balls[i]);
            refresh_boundary(i);
        }
        // Two balls at rest never meet: only the rows of moving balls need a search.
        for (std::size_t i = 0; i < slots.size(); ++i)
            if (moving[i])
                refresh_pairs(i, i);
    }

    std::size_t count() const { return slots.size(); }
    bool classic_model() const { return core::is_classic_friction(params); }

    Ball state_now(std::size_t i) const {
        const Slot& s = slots[i];
        return core::advance(s.ball, std::min(now, s.end) - s.start, params);
    }

    Path path_now(std::size_t i) const {
        const Slot& s = slots[i];
        const double t = now - s.start;
        return {s.ball.position + s.ball.velocity * t + s.acceleration * (0.5 * t * t),
                s.ball.velocity + s.acceleration * t, s.acceleration, s.end - now};
    }

    void set_slot(std::size_t i, const Ball& ball) {
        Slot& s = slots[i];
        s.ball = ball;
        s.start = now;
        const double duration = core::time_to_transition(ball, params);
        s.end = now + duration;
        s.acceleration = classic_model() ? Vec2{} : core::physical_acceleration(ball, params);
        reach[i] = ball.state == MotionState::pocketed
                       ? Box{{infinity, infinity}, {-infinity, -infinity}}
                       : slot_box(s, duration);
        moving[i] = moves(ball);
        if (recording)
            trajectory.add(i, now, ball);
    }

    // Finds ball i's next contact with the table, then shrinks its box to the path up to that
    // contact: the ball is recomputed there anyway, so pairs need not look further, and a fast
    // ball's box then spans the stretch it really travels rather than its whole slide.
    void refresh_boundary(std::size_t i) {
        boundary[i] = next_boundary(i);
        const Slot& s = slots[i];
        if (moves(s.ball) && boundary[i].time < s.end)
            reach[i] = slot_box(s, boundary[i].time - s.start);
    }

    // Box of the slot's centre over the first `duration` seconds of its piece.
    Box slot_box(const Slot& s, double duration) const {
        const Ball& b = s.ball;
        if (!moves(b))
            return {b.position, b.position};
        if (classic_model()) // straight lines
            return box_of(b.position, core::advance(b, duration, params).position);
        return path_box({b.position, b.velocity, s.acceleration, duration}, duration);
    }

    // Recomputes the pair contacts of ball i, whose boundary is already up to date. `done` is a
    // ball that changed in the same event and was refreshed just before: their pair is current.
    void refresh_pairs(std::size_t i, std::size_t done) {
        // Locals rather than members: the solver calls in the loop would otherwise make the
        // compiler reload every vector and recompute the ball count on each pass.
        const std::size_t n = count();
        const double diameter = 2 * params.ball_radius;
        const Box* boxes = reach.data();
        const std::uint8_t* moves_now = moving.data();
        const Vec2 lo = boxes[i].min - Vec2{diameter, diameter};
        const Vec2 hi = boxes[i].max + Vec2{diameter, diameter};
        // A ball at rest can only be hit by a moving one.
        const std::uint8_t needs_motion = moves_now[i] ? 0 : 1;
        double* times = pair_time.data();
        std::uint8_t* bounds = pair_bound.data();
        double* row = times + i * n;
        const Path path = path_now(i);
        double earliest = infinity;
        for (std::size_t k = 0; k < n; ++k) {
            if (k == i)
                continue;
            if (k != done) {
                // Bitwise & rather than &&: one branch per ball instead of five unpredictable ones.
                const Box& box = boxes[k];
                const bool candidate = (moves_now[k] >= needs_motion) & (lo.x <= box.max.x) &
                                       (box.min.x <= hi.x) & (lo.y <= box.max.y) &
                                       (box.min.y <= hi.y);
                double time = infinity;
                if (candidate) {
                    const core::ContactEstimate estimate = pair_contact(i, k, path);
                    time = now + estimate.time;
                    // (The flag of a pair out of reach does not matter: it is never chosen.)
                    bounds[i * n + k] = bounds[k * n + i] = estimate.exact ? 0 : 1;
                }
                if (time != row[k]) { // most pairs stay out of reach: infinity before and after
                    // Row k gets the same time; its minimum is kept up to date.
                    double* row_k = times + k * n;
                    const double old = row[k];
                    row[k] = row_k[i] = time;
                    if (time <= row_min[k]) {
                        row_min[k] = time;
                    } else if (old == row_min[k]) {
                        row_min[k] = *std::min_element(row_k, row_k + n);
                    }
                }
            }
            earliest = std::min(earliest, row[k]);
        }
        row_min[i] = earliest;
    }

    // ---- contacts between two balls -------------------------------------------------------

    // Seconds from now to the first contact of balls i and k, or a lower bound on them;
    // `pa` is ball i's path from now.
    core::ContactEstimate pair_contact(std::size_t i, std::size_t k, const Path& pa) const {
        if (classic_model())
            return {classic_pair_contact(i, k, pair_horizon(i, k)), true};
        return core::path_path_contact_estimate(pa, path_now(k), 2 * params.ball_radius,
                                                pair_horizon(i, k));
    }

    // How far ahead a pair's contact is searched: both balls are searched afresh at their next
    // table event.
    double pair_horizon(std::size_t i, std::size_t k) const {
        return std::min(boundary[i].time, boundary[k].time) - now;
    }

    // Replaces the lower bound kept for pair (i, j) by its contact time.
    void refine_pair(std::size_t i, std::size_t j) {
        const std::size_t n = count();
        const double time =
            now + core::path_path_contact_time(path_now(i), path_now(j), 2 * params.ball_radius,
                                               pair_horizon(i, j));
        pair_time[i * n + j] = pair_time[j * n + i] = time;
        pair_bound[i * n + j] = pair_bound[j * n + i] = 0;
        for (const std::size_t r : {i, j}) {
            const double* row = pair_time.data() + r * n;
            row_min[r] = *std::min_element(row, row + n);
        }
    }

    double classic_pair_contact(std::size_t i, std::size_t k, double horizon) const {
        const Ball a = state_now(i), b = state_now(k);
        const double diameter = 2 * params.ball_radius;
        auto gap = [&](double t) {
            const Ball pa = core::advance(a, t, params), pb = core::advance(b, t, params);
            const Vec2 d = pb.position - pa.position;
            const double dist = length(d);
            return std::pair{dist - diameter, dot(d, pb.velocity - pa.velocity) / dist};
        };
        auto bound = [&](double t) {
            return length(core::advance(a, t, params).velocity) +
                   length(core::advance(b, t, params).velocity);
        };
        return core::advance_until_contact(gap, bound, horizon);
    }

    // ---- contacts with the table ------------------------------------------------------------

    BoundaryEvent next_boundary(std::size_t i) const {
        const Slot& s = slots[i];
        BoundaryEvent best;
        if (!moves(s.ball)) {
            if (s.ball.state == MotionState::spinning)
                best = {s.end, BoundaryKind::transition, 0};
            return best;
        }
        best = {s.end, BoundaryKind::transition, 0};
        const double R = params.ball_radius;
        const double horizon = s.end - now;
        auto consider = [&](double dt, BoundaryKind kind, int feature) {
            if (now + dt < best.time)
                best = {now + dt, kind, feature};
        };

        if (classic_model()) {
            const Ball b = state_now(i);
            for (int c = 0; c < 18; ++c) {
                const CushionSegment& seg = table.cushions[c];
                if (seg.pocket != 0 && !near_pocket(reach[i], seg.pocket - 1))
                    continue;
                consider(classic_segment_contact(b, seg, horizon),
                         c < 6 ? BoundaryKind::rail : BoundaryKind::jaw_line, c);
            }
            for (int p = 0; p < 6; ++p) {
                if (!near_pocket(reach[i], p))
                    continue;
                const Pocket& pocket = table.pockets[p];
                consider(
                    classic_line_contact(b, pocket.capture_point, pocket.capture_normal, horizon),
                    BoundaryKind::capture, p);
            }
            return best;
        }

        const Path path = path_now(i);
        for (int c = 0; c < 6; ++c) {
            const CushionSegment& seg = table.cushions[c];
            if (!box_reaches_line(reach[i], seg.start, seg.normal, R))
                continue;
            const double dt = core::path_line_contact_time(path, seg.start, seg.normal, R, horizon);
            if (now + dt < best.time && hits_segment(path, dt, seg))
                consider(dt, BoundaryKind::rail, c);
        }
        // Nothing of the table is met after the first rail hit, so the pockets are searched only
        // up to it: for a fast ball that path's box is far smaller than the whole slide's.
        const double until_rail = std::min(horizon, best.time - now);
        const Box to_rail = path_box(path, until_rail);
        for (int p = 0; p < 6; ++p) {
            if (!near_pocket(to_rail, p))
                continue;
            // A pocket's region is wide; each jaw face and point is solved for only when the
            // path's box comes within R of it (the point is a quartic, the dearest solve here).
            for (int side = 0; side < 2; ++side) {
                const int c = 6 + 2 * p + side;
                const CushionSegment& seg = table.cushions[c];
                if (boxes_within(to_rail, box_of(seg.start, seg.end), R)) {
                    const double dt =
                        core::path_line_contact_time(path, seg.start, seg.normal, R, until_rail);
                    if (now + dt < best.time && hits_segment(path, dt, seg))
                        consider(dt, BoundaryKind::jaw_line, c);
                }
                const int point = 2 * p + side;
                const Vec2 jaw = table.jaw_points[point];
                if (boxes_within(to_rail, {jaw, jaw}, R))
                    consider(core::path_point_contact_time(path, jaw, R, until_rail),
                             BoundaryKind::jaw_point, point);
            }
            const Pocket& pocket = table.pockets[p];
            if (box_reaches_line(to_rail, pocket.capture_point, pocket.capture_normal, 0))
                consider(core::path_line_contact_time(path, pocket.capture_point,
                                                      pocket.capture_normal, 0, until_rail),
                         BoundaryKind::capture, p);
        }
        return best;
    }

    bool near_pocket(const Box& box, int p) const {
        const Pocket& pocket = table.pockets[p];
        return boxes_within(box, {pocket.region_min, pocket.region_max}, params.ball_radius);
    }

    // Whether any point of the slot's box is within `offset` of the line (rails are axis-aligned,
    // but this works for any line).
    static bool box_reaches_line(const Box& box, Vec2 point, Vec2 normal, double offset) {
        const Vec2 corner{normal.x > 0 ? box.min.x : box.max.x,
                          normal.y > 0 ? box.min.y : box.max.y};
        return dot(corner - point, normal) <= offset;
    }

    static bool hits_segment(const Path& path, double dt, const CushionSegment& seg) {
        if (!(dt < infinity))
            return false;
        const Vec2 at = path.position + path.velocity * dt + path.acceleration * (0.5 * dt * dt);
        const Vec2 along = seg.end - seg.start;
        const double u = dot(at - seg.start, along);
        return u >= 0 && u <= length_squared(along);
    }

    double classic_segment_contact(const Ball& b, const CushionSegment& seg, double horizon) const {
        const double R = params.ball_radius;
        auto gap = [&](double t) {
            const Ball moved = core::advance(b, t, params);
            const Vec2 d = moved.position - closest_on_segment(seg, moved.position);
            const double dist = length(d);
            return std::pair{dist - R, dot(d, moved.velocity) / dist};
        };
        auto bound = [&](double t) { return length(core::advance(b, t, params).velocity); };
        return core::advance_until_contact(gap, bound, horizon);
    }

    double classic_line_contact(const Ball& b, Vec2 point, Vec2 normal, double horizon) const {
        auto gap = [&](double t) {
            const Ball moved = core::advance(b, t, params);
            return std::pair{dot(moved.position - point, normal), dot(moved.velocity, normal)};
        };
        auto bound = [&](double t) { return length(core::advance(b, t, params).velocity); };
        return core::advance_until_contact(gap, bound, horizon);
    }

    static Vec2 closest_on_segment(const CushionSegment& seg, Vec2 p) {
        const Vec2 along = seg.end - seg.start;
        const double u = std::clamp(dot(p - seg.start, along) / length_squared(along), 0.0, 1.0);
        return seg.start + along * u;
    }

    // ---- stepping ---------------------------------------------------------------------------

    struct NextEvent {
        double time = infinity;
        std::size_t i = 0, j = 0;
        bool is_pair = false;
    };

    std::optional<Event> step() {
        if (!pending.empty()) {
            const Event e = pending.front();
            pending.erase(pending.begin());
            return e;
        }
        const NextEvent next = earliest_event();
        if (!(next.time < infinity))
            return std::nullopt;
        if (++events > max_events)
            return std::nullopt;
        now = std::max(now, next.time);
        return next.is_pair ? resolve_pair(next.i, next.j) : resolve_boundary(next.i);
    }

    // The earliest event; ties go to the table, then to the lowest pair. A pair that holds only
    // a bound is searched when it comes first, and the choice is made again.
    NextEvent earliest_event() {
        NextEvent first_boundary;
        for (std::size_t i = 0; i < count(); ++i) {
            if (boundary[i].time < first_boundary.time)
                first_boundary = {boundary[i].time, i, 0, false};
        }
        for (;;) {
            NextEvent next = first_boundary;
            for (std::size_t i = 0; i < count(); ++i) {
                if (row_min[i] < next.time) {
                    // Every pair of an earlier ball was already seen in that ball's row.
                    const double* row = &pair_time[i * count()];
                    for (std::size_t j = i + 1; j < count(); ++j) {
                        if (row[j] < next.time)
                            next = {row[j], i, j, true};
                    }
                }
            }
            if (!next.is_pair || !pair_bound[next.i * count() + next.j])
                return next;
            refine_pair(next.i, next.j);
        }
    }

    Event resolve_pair(std::size_t i, std::size_t j) {
        Ball a = state_now(i), b = state_now(j);
        core::resolve_ball_ball(a, b, params);
        set_slot(i, a);
        set_slot(j, b);
        refresh_boundary(i);
        refresh_boundary(j);
        refresh_pairs(i, i);
        refresh_pairs(j, i);
        return {now, EventKind::ball_ball, std::min(a.id, b.id), std::max(a.id, b.id)};
    }

    Event resolve_boundary(std::size_t i) {
        const BoundaryEvent be = boundary[i];
        Ball b = state_now(i);
        Event event{now, EventKind::stopped, b.id, 0};
        switch (be.kind) {
        case BoundaryKind::transition:
            b = core::apply_transition(b, params);
            event.kind = b.state == MotionState::rolling    ? EventKind::rolling
                         : b.state == MotionState::spinning ? EventKind::spinning
                         : b.state == MotionState::sliding  ? EventKind::sliding
                                                            : EventKind::stopped;
            break;
        case BoundaryKind::rail:
        case BoundaryKind::jaw_line: {
            const CushionSegment& seg = table.cushions[be.feature];
            const Vec2 towards = classic_model()
                                     ? normalized(closest_on_segment(seg, b.position) - b.position)
                                     : -seg.normal;
            core::resolve_cushion(b, towards, params);
            event.kind = be.kind == BoundaryKind::rail ? EventKind::cushion : EventKind::jaw;
            event.other = be.kind == BoundaryKind::rail ? be.feature : seg.pocket;
            break;
        }
        case BoundaryKind::jaw_point:
            core::resolve_cushion(b, normalized(table.jaw_points[be.feature] - b.position), params);
            event.kind = EventKind::jaw;
            event.other = table.jaw_point_pocket[be.feature];
            break;
        case BoundaryKind::capture:
            b.state = MotionState::pocketed;
            b.pocket = be.feature + 1;
            b.velocity = {};
            b.angular_velocity = {};
            event.kind = EventKind::pocket;
            event.other = b.pocket;
            break;
        case BoundaryKind::none:
            break;
        }
        set_slot(i, b);
        refresh_boundary(i);
        refresh_pairs(i, i);
        return event;
    }

    void strike(const Strike& strike, std::size_t cue) {
        Ball b = strike_cue_ball(state_now(cue), strike, params);
        set_slot(cue, b);
        refresh_boundary(cue);
        refresh_pairs(cue, cue);
        if (moves(b))
            pending.push_back(
                {now, b.state == MotionState::rolling ? EventKind::rolling : EventKind::sliding,
                 b.id, 0});
    }
};

World::World(const Table& table, const PhysicsParams& params, std::vector<Ball> balls)
    : impl_(std::make_unique<Impl>(table, params, std::move(balls))) {}
World::~World() = default;
World::World(const World& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
World& World::operator=(const World& other) {
    if (this != &other)
        impl_ = std::make_unique<Impl>(*other.impl_);
    return *this;
}
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

bool World::strike(const Strike& strike) {
    for (std::size_t i = 0; i < impl_->count(); ++i) {
        const Ball& b = impl_->slots[i].ball;
        if (b.id == 0 && b.state != MotionState::pocketed) {
            impl_->strike(strike, i);
            return true;
        }
    }
    return false;
}

std::optional<Event> World::step() {
    return impl_->step();
}
double World::time() const {
    return impl_->now;
}

std::vector<Ball> World::balls() const {
    std::vector<Ball> out;
    out.reserve(impl_->count());
    for (std::size_t i = 0; i < impl_->count(); ++i)
        out.push_back(impl_->state_now(i));
    return out;
}

bool World::at_rest() const {
    return std::all_of(impl_->slots.begin(), impl_->slots.end(), [](const Slot& s) {
        return s.ball.state == MotionState::stationary || s.ball.state == MotionState::pocketed;
    });
}

void World::record(bool on) {
    impl_->recording = on;
    if (on) {
        for (std::size_t i = 0; i < impl_->count(); ++i)
            impl_->trajectory.add(i, impl_->now, impl_->state_now(i));
    }
}

const Trajectory& World::trajectory() const {
    return impl_->trajectory;
}

ShotResult simulate_shot(const Table& table, const PhysicsParams& params, std::vector<Ball> balls,
                         const Strike& strike, Trajectory* trajectory) {
    World world(table, params, std::move(balls));
    if (trajectory)
        world.record(true);
    world.strike(strike);
    ShotResult result;
    result.events.reserve(256); // a break takes about 140 events; growing costs several copies
    while (const auto event = world.step())
        result.events.push_back(*event);
    result.event_limit_hit = !world.at_rest();
    result.rest_time = world.time();
    result.balls = world.balls();
    if (trajectory)
        *trajectory = world.trajectory();
    return result;
}

double kinetic_energy(const Ball& b, double radius) {
    if (b.state == MotionState::pocketed)
        return 0;
    const double inertia = 0.4 * b.mass * radius * radius;
    return 0.5 * b.mass * length_squared(b.velocity) +
           0.5 * inertia * dot(b.angular_velocity, b.angular_velocity);
}

} // namespace termpool
