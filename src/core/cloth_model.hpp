#pragma once
// What differs between the cloth models, as one table of functions chosen once per world, shot
// or sample by cloth_model(), so that no other physics code tests the friction kind.
//
// The physical model moves a ball's centre on parabolas (constant acceleration while it slides
// or rolls) and keeps its spin; contacts are roots of polynomials. The classic models, the seed
// report's decay, constant and combined, move it on straight lines without spin at a speed that
// follows their law; contacts are solved exactly in each phase of the law (classic_contacts.hpp).

#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>

#include "motion_piece.hpp"
#include "polynomial.hpp"
#include "reach_box.hpp"
#include "table_contacts.hpp"

namespace termpool::core {

/// One cloth model's functions.
struct ClothModel {
    // ---- a ball on its own

    /// Seconds until the ball's motion state changes by itself (slide to roll, roll to stop,
    /// spin to rest, a classic ball's stop), +infinity for a ball that never changes.
    double (*time_to_transition)(const Ball& ball, const PhysicsParams& params);
    /// The ball `dt` seconds later, 0 <= dt <= time_to_transition; the motion state is unchanged.
    AdvanceFn advance;
    /// The ball after its transition: `ball` must be the state at the transition time.
    Ball (*apply_transition)(const Ball& ball, const PhysicsParams& params);
    /// Puts a ball whose velocities were just changed (strike, collision) into the motion state
    /// that matches them.
    void (*settle_motion_state)(Ball& ball, const PhysicsParams& params);
    /// The centre's constant acceleration in the ball's current motion state: a MotionPiece's
    /// parabola (zero for a classic ball, whose path is a straight line).
    Vec2 (*acceleration)(const Ball& ball, const PhysicsParams& params);

    // ---- what contacts leave

    /// Whether the model keeps a ball's spin (the classic ones do not: the tip gives none).
    bool keeps_spin;
    /// Whether a ball pushed slower than the rest speed stops at once (the classic models): a
    /// ball at rest is then a wall to a slow push, and a ball can be caught in the wedge between
    /// it and a cushion (wedge.hpp).
    bool holds_slow_balls;
    /// The cloth's part in a slow contact of two balls (`n` from a to b), after the impulse:
    /// balls the cloth drives into each other are pushed rather than bounced.
    void (*slow_pair_contact)(Ball& a, Ball& b, Vec2 n, const PhysicsParams& params);
    /// The cloth's part in a slow cushion contact, after the impulse: spin that would drive the
    /// ball back into the cushion is taken out.
    void (*slow_cushion_contact)(Ball& ball, Vec2 towards_cushion, const PhysicsParams& params);
    /// The unit vector from the centre of a ball touching the rail or jaw line `seg` to the
    /// contact, as the model's search (table_event) finds contacts: across the line.
    Vec2 (*towards_cushion)(const Ball& ball, const CushionSegment& seg);

    // ---- where the next contacts are

    /// Box of a moving ball's centre over the first `duration` seconds of its piece.
    Box (*reach)(const MotionPiece& piece, double duration, const PhysicsParams& params);
    /// Seconds from `now` to the first contact of two pieces' balls within `horizon`, or a lower
    /// bound on it (not `exact`) when that is much cheaper.
    ContactEstimate (*pair_contact)(const MotionPiece& a, const MotionPiece& b, double now,
                                    double horizon, const PhysicsParams& params);
    /// The contact itself, for a pair whose pair_contact was a bound.
    double (*pair_contact_time)(const MotionPiece& a, const MotionPiece& b, double now,
                                double horizon, const PhysicsParams& params);
    /// A moving ball's next event on its own: its transition or an earlier table contact,
    /// searched where `reach` (the box of its piece up to then) comes near, at the piece's start
    /// (`now`); and the box of its path up to the event.
    TableSearch (*table_event)(const MotionPiece& piece, const Box& reach, double now,
                               const Table& table, const PhysicsParams& params);
};

/// The model `friction` names: the one place the physics looks at the friction kind.
ClothModel cloth_model(const FrictionModel& friction);

/// The physical model (physical_cloth.cpp).
ClothModel physical_cloth();
/// The classic models, one per law (classic_cloth.cpp).
ClothModel decay_cloth();
/// \copydoc decay_cloth
ClothModel constant_cloth();
/// \copydoc decay_cloth
ClothModel combined_cloth();

} // namespace termpool::core
