#pragma once
/// \file
/// The event-based simulator: a World holds a table and balls and is stepped from event to
/// event. Every event time is solved for exactly; there is no frame rate.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <termpool/ball.hpp>
#include <termpool/event.hpp>
#include <termpool/params.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// Version of the physics: what a list of strikes plays into. Raised whenever a change moves
/// an outcome by a single bit (tests/test_determinism.cpp keeps the hashes), so that a record
/// names the physics it was made with. Version 1 is every build before versions were kept;
/// version 2 has -ffp-contract=off and the project's own transcendental functions.
inline constexpr int physics_version = 2;

/// A cue strike: how the cue ball leaves the tip.
struct Strike {
    double speed = 0;     ///< cue-ball speed v, m/s (0..20)
    double angle_deg = 0; ///< direction phi, degrees counter-clockwise from +x
    double side = 0;      ///< tip offset a as a fraction of R, + = right english, |a| <= 0.5
    double follow = 0;    ///< tip offset b as a fraction of R, + = follow, - = draw, |b| <= 0.5
    /// Cue elevation above the cloth, degrees (0..max_cue_elevation_deg): a raised cue with
    /// side spin tilts the spin axis, and the ball curves while it slides (swerve, masse).
    double elevation_deg = 0;
};

/// Largest cue elevation the simulator accepts, degrees.
inline constexpr double max_cue_elevation_deg = 80.0;

/// Largest cue-ball speed the simulator accepts, m/s.
inline constexpr double max_strike_speed = 20.0;

/// The cue ball's state right after the tip leaves it (point-impact model: spin magnitude
/// 5 v offset / (2 R)), squirt and elevation included.
Ball strike_cue_ball(const Ball& cue, const Strike& strike, const PhysicsParams& params);

/// Why `strike` cannot be played under `params`, in words for a player or a scenario's author
/// (speed, tip offset or elevation out of range, or a strike that would need a jump shot);
/// nothing when it can be.
std::optional<std::string> strike_problem(const Strike& strike, const PhysicsParams& params);

/// Squirt: the angle, degrees, by which side spin turns the cue ball off the cue's line, away
/// from the side struck (positive for right english, which sends the ball left). `side` is the
/// tip offset as a fraction of R, `end_mass` the cue's effective end mass (kg); zero end mass
/// means no squirt.
double squirt_angle_deg(double side, double ball_mass, double end_mass);

/// The recorded motion of a shot, from which the state at any time can be sampled.
class Trajectory {
public:
    /// One piece of a ball's motion: its state at `start`, valid until the next piece.
    struct Piece {
        double start; ///< seconds since the strike
        Ball ball;    ///< the state at `start`
    };
    /// An empty trajectory for the given model.
    Trajectory(PhysicsParams params, std::size_t ball_count);
    /// Appends a piece for ball slot `index`; pieces of a slot come in time order.
    void add(std::size_t index, double start, const Ball& ball);
    /// Empty again, for the model `params`, with as many slots (and their memory) as before.
    void restart(const PhysicsParams& params);
    /// The state of every ball at `time` (seconds since the strike), without re-simulating.
    std::vector<Ball> sample(double time) const;
    /// The state of ball slot `index` at `time`; the slot must have a piece (balls with none
    /// are left out of the whole sample above).
    Ball sample(std::size_t index, double time) const;
    /// The state of ball slot `index` just before `time`: its motion up to that instant, before
    /// an event at `time` changed it (the same as `sample` where nothing happens at `time`).
    Ball sample_before(std::size_t index, double time) const;
    /// The pieces of ball slot `index`.
    const std::vector<Piece>& pieces(std::size_t index) const { return pieces_[index]; }
    /// The number of ball slots.
    std::size_t size() const { return pieces_.size(); }
    /// The slot of the ball with id `id`, or nothing when no slot has pieces of it.
    std::optional<std::size_t> slot_of(int id) const;

private:
    PhysicsParams params_;
    std::vector<std::vector<Piece>> pieces_;
};

/// The balls of one event at its instant: each one's state just before the event and just
/// after it was resolved (position, velocity, spin and motion state).
struct EventState {
    Ball ball_before;                 ///< Event::ball before the event
    Ball ball_after;                  ///< Event::ball after it
    std::optional<Ball> other_before; ///< for ball_ball: Event::other before the event
    std::optional<Ball> other_after;  ///< for ball_ball: Event::other after it
};

/// The states of `event`'s balls, read from the shot's recorded `trajectory` without
/// simulating again; nothing when the trajectory holds no pieces of the event's ball.
std::optional<EventState> event_state(const Trajectory& trajectory, const Event& event);

/// Everything a finished shot produced.
struct ShotResult {
    std::vector<Event> events;    ///< in time order
    std::vector<Ball> balls;      ///< final state, in the order the world was given
    double rest_time = 0;         ///< when the last ball stopped
    bool event_limit_hit = false; ///< true if the shot was cut short by `World::max_events`
};

/// A table with balls on it, advanced event by event.
class World {
public:
    /// Safety limit on events per shot; a shot that reaches it is stopped and flagged.
    static constexpr std::size_t max_events = 200000;

    /// A world at time 0. Ball ids must be unique; balls must be on the table
    /// (on_playing_surface, the rule every position the world reaches keeps) and not overlap.
    /// At most max_world_balls balls (std::length_error beyond); its memory grows with the square
    /// of their number (a pair's contact time each).
    World(const Table& table, const PhysicsParams& params, std::vector<Ball> balls);
    ~World();
    /// Worlds are values: copying one copies its state.
    World(const World& other);
    /// Copy assignment, into this world's memory.
    World& operator=(const World& other);
    /// Move construction.
    World(World&&) noexcept;
    /// Move assignment.
    World& operator=(World&&) noexcept;

    /// Puts `balls` on the table at time 0, as a new World on this table would, but in this one's
    /// memory: a search that simulates many shots from one layout allocates nothing per shot.
    /// Recording stops and the trajectory is emptied.
    void reset(const std::vector<Ball>& balls);

    /// Strikes the cue ball (id 0) at the current time. Returns false if there is none.
    bool strike(const Strike& strike);
    /// Advances to the next event and resolves it. Returns nothing once every ball is at rest.
    std::optional<Event> step();
    /// Current time, seconds.
    double time() const;
    /// The balls at the current time.
    std::vector<Ball> balls() const;
    /// The same into `out`, which keeps its memory.
    void balls(std::vector<Ball>& out) const;
    /// True when nothing moves or spins.
    bool at_rest() const;
    /// Records every ball's motion into a Trajectory from now on.
    void record(bool on);
    /// The recorded motion (empty unless `record(true)` was called before stepping).
    const Trajectory& trajectory() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Strikes the cue ball and steps the world until every ball is at rest.
ShotResult simulate_shot(const Table& table, const PhysicsParams& params, std::vector<Ball> balls,
                         const Strike& strike, Trajectory* trajectory = nullptr);

/// The same on `world` as it stands (set out by its constructor, World::reset, or a copy of a
/// world set out once): `result` is overwritten and keeps its memory, and so does the world. For
/// searches that simulate many shots: nothing is allocated per shot once they are warm.
void simulate_shot(World& world, const Strike& strike, ShotResult& result);

/// What keeps a list of balls from being set out on a table (World's precondition).
struct LayoutProblem {
    /// The kinds of problem.
    enum class Kind {
        off_table,          ///< `ball` is not on the playing surface
        overlap,            ///< `ball` overlaps the earlier `other` (by more than 1e-9 m)
        same_id,            ///< `ball` has the id of the earlier `other`
        not_finite,         ///< a coordinate of `ball`'s position, velocity or spin is not finite
        bad_mass,           ///< `ball`'s mass is not a positive finite number
        too_fast,           ///< `ball` moves faster than max_strike_speed, or spins faster than
                            ///< max_ball_spin
        at_rest_but_moving, ///< `ball` is stationary (or spinning) but has a velocity or spin
                            ///< that state does not allow
        too_many,           ///< more than max_world_balls balls
    };
    Kind kind = Kind::off_table; ///< what is wrong
    std::size_t ball = 0;        ///< index of the ball found wrong
    std::size_t other = 0;       ///< index of the earlier ball it conflicts with (overlap, same_id)
};

/// The most balls a World holds.
inline constexpr std::size_t max_world_balls = 32768;

/// The fastest a ball given to a World may spin, rad/s: a cue ball struck at the top speed with
/// the tip at the edge of the ball spins at about 900 rad/s.
inline constexpr double max_ball_spin = 2000.0;

/// The first problem of `balls` in their order (each ball checked against those before it; a
/// pocketed ball is not on the table and is left out of the position checks), or nothing when
/// a World can hold them. Balls touching within 1e-9 m are allowed: a rack's balls are packed
/// that close.
std::optional<LayoutProblem> layout_problem(const Table& table, const std::vector<Ball>& balls,
                                            double radius);

/// The problem in words, as `termpool simulate` says it: "ball 3 at (0.1, 0.2) is off the
/// table", "... overlaps ball 1", "duplicate ball 3", .... `name(index, other)` names the ball
/// at `index` of `balls` ("ball 3"; `other` is true for the earlier ball an overlap or a
/// duplicate names, where a caller may add where it came from).
std::string
layout_problem_text(const LayoutProblem& problem, const std::vector<Ball>& balls,
                    const std::function<std::string(std::size_t index, bool other)>& name);

/// What a caller says when there is no cue ball (id 0) on the table to strike.
inline constexpr const char* no_cue_ball_text = "no cue ball (ball 0) on the table to strike";

/// Kinetic energy of a ball, translation plus rotation (solid sphere), J.
double kinetic_energy(const Ball& ball, double radius);

} // namespace termpool
