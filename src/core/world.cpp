// The stepping: the world jumps from event to event, resolves each and searches again what it
// changed. The event schedule and the table-contact search keep where the next contacts are;
// how balls move and where they meet is the cloth model's, chosen once per world.

#include <algorithm>
#include <limits>
#include <termpool/simulator.hpp>

#include "cloth_model.hpp"
#include "collision.hpp"
#include "event_schedule.hpp"
#include "motion_piece.hpp"
#include "reach_box.hpp"
#include "table_contacts.hpp"
#include "wedge.hpp"

namespace termpool {

using core::is_moving;
using core::MotionPiece;
using core::TableEvent;
using core::TableEventKind;

struct World::Impl {
    Table table;
    PhysicsParams params;
    core::ClothModel cloth;     // chosen once, from params.friction
    core::OpenField open_field; // of the table, for balls of params' radius
    std::vector<MotionPiece> pieces;
    std::vector<TableEvent> table_events; // each ball's next event on its own
    core::EventSchedule schedule;         // what happens next, and the pair contacts
    double now = 0;
    std::size_t events = 0;
    std::vector<Event> pending; // reported by the next step before anything is simulated
    bool recording = false;
    bool recorded = false; // the trajectory holds pieces
    Trajectory trajectory;
    // Scratch kept between events, so that stepping allocates nothing once warm: the balls an
    // event changed, and the held balls next to a ball in a wedge.
    std::vector<std::size_t> changed;
    std::vector<std::size_t> wedge_near;
    std::vector<Ball> wedge_held;
    // A moving ball's piece's length, from set_piece to the refresh_table_event that follows it
    // (always, before any search), which sets the ball's box once it knows its next event.
    std::vector<double> piece_duration;

    Impl(const Table& t, const PhysicsParams& p, std::vector<Ball> balls)
        : table(t), params(p), cloth(core::cloth_model(p.friction)),
          open_field(core::open_field(t, p.ball_radius)), pieces(balls.size()),
          table_events(balls.size()), schedule(balls.size(), 2 * p.ball_radius),
          trajectory(p, balls.size()), piece_duration(balls.size()) {
        place(balls);
    }

    // Puts `balls` on the table at time 0; the containers keep their memory.
    void place(const std::vector<Ball>& balls) {
        if (balls.size() != pieces.size()) {
            // The schedule first: it refuses too many balls before anything has changed.
            core::EventSchedule resized(balls.size(), 2 * params.ball_radius);
            Trajectory empty(params, balls.size());
            pieces.resize(balls.size());
            table_events.resize(balls.size());
            piece_duration.resize(balls.size());
            schedule = std::move(resized);
            trajectory = std::move(empty);
            recorded = false;
        }
        if (recorded) {
            recorded = false;
            trajectory = Trajectory(params, balls.size());
        }
        recording = false;
        now = 0;
        events = 0;
        pending.clear();
        schedule.clear();
        for (std::size_t i = 0; i < balls.size(); ++i) {
            set_piece(i, balls[i]);
            refresh_table_event(i);
        }
        // Two balls at rest never meet: only the rows of moving balls need a search.
        for (std::size_t i = 0; i < pieces.size(); ++i)
            if (is_moving(pieces[i].ball))
                refresh_pairs(i, i);
        schedule.earliest(); // brings the schedule up to date now rather than at the first step
    }

    // A copy of `o`, a world of as many balls, into this one's memory (World::operator=). The
    // scratch between events is not copied, nor the trajectory's pieces unless one of the two
    // worlds has recorded: without, both are empty, and only the physics they are for is taken
    // (a search copies worlds that never record before each of its shots).
    void assign(const Impl& o) {
        table = o.table;
        params = o.params;
        cloth = o.cloth;
        open_field = o.open_field;
        pieces = o.pieces;
        table_events = o.table_events;
        schedule = o.schedule;
        now = o.now;
        events = o.events;
        pending = o.pending;
        recording = o.recording;
        if (recorded || o.recorded)
            trajectory = o.trajectory;
        else
            trajectory.restart(o.params);
        recorded = o.recorded;
    }

    std::size_t count() const { return pieces.size(); }

    // A ball at rest is where its piece began, in every model (advance leaves it as it is): it
    // is taken as it is, without the call (a sample's result asks for every ball).
    Ball state_now(std::size_t i) const {
        const MotionPiece& s = pieces[i];
        return in_motion(s.ball) ? core::state_at(s, now, cloth.advance, params) : s.ball;
    }

    void set_piece(std::size_t i, const Ball& ball) {
        MotionPiece& s = pieces[i];
        s.ball = ball;
        s.start = now;
        const double duration = cloth.time_to_transition(ball, params);
        s.end = now + duration;
        s.acceleration = cloth.acceleration(ball, params);
        if (ball.state == MotionState::pocketed)
            schedule.set_reach(i, core::empty_box(), {});
        else if (!is_moving(ball))
            schedule.set_reach(i, reach_of(s, duration), path_of(s, duration));
        else
            piece_duration[i] = duration; // its box: refresh_table_event, which follows
        schedule.set_moving(i, is_moving(ball));
        if (recording)
            trajectory.add(i, now, ball);
    }

    // Finds ball i's next event on its own, just after set_piece(i) (now is the piece's start),
    // and gives a moving ball the box of its path up to it: the ball is recomputed there anyway,
    // so pairs need not look further, and a fast ball's box then spans the stretch it really
    // travels rather than its whole slide.
    void refresh_table_event(std::size_t i) {
        const MotionPiece& s = pieces[i];
        if (!is_moving(s.ball)) {
            // A ball spinning in place stops spinning at its piece's end; one at rest waits.
            table_events[i] = s.ball.state == MotionState::spinning
                                  ? TableEvent{s.end, TableEventKind::transition, 0}
                                  : TableEvent{};
            schedule.set_table_time(i, table_events[i].time);
            return;
        }
        const double duration = piece_duration[i];
        const core::Box reach = reach_of(s, duration);
        // In the open field the search would cull everything and find the transition.
        const core::TableSearch found =
            open_field.holds(reach)
                ? core::TableSearch{{s.end, TableEventKind::transition, 0}, reach}
                : cloth.table_event(s, reach, now, table, params);
        table_events[i] = found.event;
        schedule.set_table_time(i, found.event.time);
        const bool sooner = found.event.time < s.end; // a contact before the transition
        schedule.set_reach(i, found.to_event,
                           path_of(s, sooner ? found.event.time - s.start : duration));
    }

    // The capsule of the piece's centre over its first `duration` seconds, where the schedule
    // searches along paths (many balls).
    core::Capsule path_of(const MotionPiece& s, double duration) const {
        return schedule.searches_paths() ? core::capsule_of(s, duration) : core::Capsule{};
    }

    // Box of the piece's centre over its first `duration` seconds.
    core::Box reach_of(const MotionPiece& s, double duration) const {
        const Ball& b = s.ball;
        if (!is_moving(b))
            return {b.position, b.position};
        return cloth.reach(s, duration, params);
    }

    // Recomputes the pair contacts of ball i, whose table event is already up to date. `done` is
    // a ball that changed in the same event and was refreshed just before.
    void refresh_pairs(std::size_t i, std::size_t done) {
        schedule.refresh(i, done, now, [&](std::size_t k) { return pair_contact(i, k); });
    }

    // Seconds from now to the first contact of balls i and k, or a lower bound on them.
    core::ContactEstimate pair_contact(std::size_t i, std::size_t k) const {
        return cloth.pair_contact(pieces[i], pieces[k], now, pair_horizon(i, k), params);
    }

    // How far ahead a pair's contact is searched: both balls are searched afresh at their next
    // event on their own.
    double pair_horizon(std::size_t i, std::size_t k) const {
        return std::min(table_events[i].time, table_events[k].time) - now;
    }

    // ---- stepping ---------------------------------------------------------------------------

    struct NextEvent {
        double time = std::numeric_limits<double>::infinity();
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
        if (!(next.time < std::numeric_limits<double>::infinity()))
            return std::nullopt;
        if (++events > max_events)
            return std::nullopt;
        now = std::max(now, next.time);
        return next.is_pair ? resolve_pair(next.i, next.j) : resolve_table_event(next.i);
    }

    // The earliest event; ties go to the table, then to the lowest pair (the schedule's order).
    // A pair that holds only a bound is searched when it comes first, and the choice is made
    // again.
    NextEvent earliest_event() {
        for (;;) {
            const core::ScheduledEvent e = schedule.earliest();
            if (!(e.time < std::numeric_limits<double>::infinity()))
                return {};
            if (!e.is_pair())
                return {e.time, e.i(), 0, false};
            if (!schedule.is_bound(e.i(), e.j()))
                return {e.time, e.i(), e.j(), true};
            refine_pair(e.i(), e.j());
        }
    }

    // Replaces the lower bound kept for pair (i, j) by its contact time.
    void refine_pair(std::size_t i, std::size_t j) {
        schedule.set_exact(
            i, j,
            now + cloth.pair_contact_time(pieces[i], pieces[j], now, pair_horizon(i, j), params));
    }

    Event resolve_pair(std::size_t i, std::size_t j) {
        const bool i_was_active = in_motion(pieces[i].ball),
                   j_was_active = in_motion(pieces[j].ball);
        Ball a = state_now(i), b = state_now(j);
        core::resolve_ball_ball(a, b, params, cloth);
        set_piece(i, a);
        set_piece(j, b);
        changed.clear(); // (not assign({i, j}): that costs several times as much)
        changed.push_back(i);
        changed.push_back(j);
        escape_wedge(i, j, changed);
        escape_wedge(j, i, changed);
        refresh_changed();
        report_stop(i, i_was_active);
        report_stop(j, j_was_active);
        return {now, EventKind::ball_ball, std::min(a.id, b.id), std::max(a.id, b.id)};
    }

    // Whether a ball is not at rest: it moves, or it spins in place (and stops later).
    static bool in_motion(const Ball& b) {
        return b.state != MotionState::stationary && b.state != MotionState::pocketed;
    }

    // A contact that leaves a ball at rest (a classic cloth stops a ball slower than its rest
    // speed at once; the physical cloth stops one left with no speed and no spin) is where it
    // stops: the ball gets its stopped event at this instant, after the contact's own events,
    // as a ball that stops on the cloth gets one from its transition (issue 28). Balls held in
    // a wedge were at rest before and are not reported.
    void report_stop(std::size_t i, bool was_active) {
        const Ball& b = pieces[i].ball;
        if (was_active && b.state == MotionState::stationary)
            pending.push_back({now, EventKind::stopped, b.id, 0});
    }

    // Table events first, then pairs, so that each pair search sees both balls' horizons.
    void refresh_changed() {
        for (const std::size_t k : changed)
            refresh_table_event(k);
        for (const std::size_t k : changed)
            refresh_pairs(k, changed.front() == k ? k : changed.front());
    }

    // Ball i, just resolved, may be in a wedge between held balls and cushions (wedge.hpp) on a
    // cloth that holds slow balls: then its contacts are resolved at once, the ones not reported
    // yet (other than with `reported`) become pending events, and the balls changed are added
    // to `changed`.
    void escape_wedge(std::size_t i, std::size_t reported, std::vector<std::size_t>& changed) {
        if (!cloth.holds_slow_balls || !is_moving(pieces[i].ball))
            return;
        Ball mover = pieces[i].ball;
        const double apart = 2 * params.ball_radius + core::wedge_touch_gap;
        std::vector<std::size_t>& near = wedge_near;
        std::vector<Ball>& held = wedge_held;
        near.clear();
        held.clear();
        for (std::size_t k = 0; k < count(); ++k) {
            const Ball& other = pieces[k].ball;
            if (k != i && other.state == MotionState::stationary &&
                length(other.position - mover.position) <= apart) {
                near.push_back(k);
                held.push_back(other);
            }
        }
        if (held.empty())
            return;
        const std::vector<core::CushionTouch> cushions =
            core::touching_cushions(table, mover.position, params.ball_radius);
        if (held.size() + cushions.size() < 2)
            return; // one contact, already resolved: no wedge
        const core::WedgeContacts touched =
            core::escape_wedge(mover, cushions, held, params, cloth);
        set_piece(i, mover);
        for (const Event& c : touched.cushions)
            pending.push_back({now, c.kind, mover.id, c.other});
        for (const std::size_t index : touched.balls) {
            const std::size_t k = near[index];
            if (!(held[index] == pieces[k].ball)) {
                set_piece(k, held[index]);
                if (std::find(changed.begin(), changed.end(), k) == changed.end())
                    changed.push_back(k);
            }
            if (k != reported)
                pending.push_back({now, EventKind::ball_ball, std::min(mover.id, held[index].id),
                                   std::max(mover.id, held[index].id)});
        }
    }

    Event resolve_table_event(std::size_t i) {
        const TableEvent te = table_events[i];
        Ball b = state_now(i);
        Event event{now, EventKind::stopped, b.id, 0};
        switch (te.kind) {
        case TableEventKind::transition:
            b = cloth.apply_transition(b, params);
            event.kind = b.state == MotionState::rolling    ? EventKind::rolling
                         : b.state == MotionState::spinning ? EventKind::spinning
                         : b.state == MotionState::sliding  ? EventKind::sliding
                                                            : EventKind::stopped;
            break;
        case TableEventKind::rail:
        case TableEventKind::jaw_line: {
            const CushionSegment& seg = table.cushions[te.feature];
            core::resolve_cushion(b, cloth.towards_cushion(b, seg), params, cloth);
            event.kind = te.kind == TableEventKind::rail ? EventKind::cushion : EventKind::jaw;
            event.other = te.kind == TableEventKind::rail ? te.feature : seg.pocket;
            break;
        }
        case TableEventKind::jaw_point:
            core::resolve_cushion(b, normalized(table.jaw_points[te.feature] - b.position), params,
                                  cloth);
            event.kind = EventKind::jaw;
            event.other = table.jaw_point_pocket[te.feature];
            break;
        case TableEventKind::capture:
            b.state = MotionState::pocketed;
            b.pocket = te.feature + 1;
            b.velocity = {};
            b.angular_velocity = {};
            event.kind = EventKind::pocket;
            event.other = b.pocket;
            break;
        case TableEventKind::none:
            break;
        }
        set_piece(i, b);
        changed.clear();
        changed.push_back(i);
        const bool contact = te.kind == TableEventKind::rail ||
                             te.kind == TableEventKind::jaw_line ||
                             te.kind == TableEventKind::jaw_point;
        if (contact)
            escape_wedge(i, i, changed);
        refresh_changed();
        if (contact)
            report_stop(i, true); // it had a table event: it was moving
        return event;
    }

    void strike(const Strike& strike, std::size_t cue) {
        Ball b = strike_cue_ball(state_now(cue), strike, params);
        set_piece(cue, b);
        refresh_table_event(cue);
        refresh_pairs(cue, cue);
        if (is_moving(b))
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
    // Into the existing state when it has as many balls, so that its vectors keep their memory
    // (a search copies a world set out once into a scratch world before each of its shots);
    // otherwise, and if that copy fails halfway, a fresh copy.
    if (this == &other)
        return *this;
    if (impl_ && other.impl_ && impl_->count() == other.impl_->count()) {
        try {
            impl_->assign(*other.impl_);
            return *this;
        } catch (...) {
            // Half copied: replaced whole below, or left to the exception if that fails too.
        }
    }
    impl_ = other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr;
    return *this;
}
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::reset(const std::vector<Ball>& balls) {
    impl_->place(balls);
}

bool World::strike(const Strike& strike) {
    for (std::size_t i = 0; i < impl_->count(); ++i) {
        const Ball& b = impl_->pieces[i].ball;
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
    balls(out);
    return out;
}

void World::balls(std::vector<Ball>& out) const {
    out.clear();
    out.reserve(impl_->count());
    for (std::size_t i = 0; i < impl_->count(); ++i)
        out.push_back(impl_->state_now(i));
}

bool World::at_rest() const {
    return std::all_of(impl_->pieces.begin(), impl_->pieces.end(), [](const MotionPiece& s) {
        return s.ball.state == MotionState::stationary || s.ball.state == MotionState::pocketed;
    });
}

void World::record(bool on) {
    impl_->recording = on;
    impl_->recorded = impl_->recorded || on;
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

void simulate_shot(World& world, const Strike& strike, ShotResult& result) {
    world.strike(strike);
    result.events.clear();
    while (const auto event = world.step())
        result.events.push_back(*event);
    result.event_limit_hit = !world.at_rest();
    result.rest_time = world.time();
    world.balls(result.balls);
}

double kinetic_energy(const Ball& b, double radius) {
    if (b.state == MotionState::pocketed)
        return 0;
    const double inertia = 0.4 * b.mass * radius * radius;
    return 0.5 * b.mass * length_squared(b.velocity) +
           0.5 * inertia * dot(b.angular_velocity, b.angular_velocity);
}

} // namespace termpool
