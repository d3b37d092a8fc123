#pragma once
/// \file
/// Physical constants and model choices of the simulator, and the names a scenario, a record
/// and the command line give them.

#include <termpool/enum_names.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace termpool {

/// How two balls exchange momentum at contact.
enum class CollisionModel {
    physical, ///< restitution e_b plus ball-ball friction u_b (cut- and spin-induced throw)
    ideal,    ///< the seed report's elastic, frictionless impulse along the line of centres
};

/// The ball-ball models' names, as a scenario's `collision` line gives them.
inline constexpr NameRow<CollisionModel> collision_model_names[] = {
    {CollisionModel::physical, "physical"},
    {CollisionModel::ideal, "ideal"},
};
static_assert(names_in_order(collision_model_names));

/// Which law gives the ball-ball friction u_b of a contact.
enum class BallFrictionModel {
    fit,      ///< u_b = a + b e^(-c v_rel): measured throw, large when slow, small when fast
    constant, ///< u_b the same at every sliding speed
};

/// The ball-ball friction laws' names, as a scenario's `throw` line and `termpool experiment
/// throw --model` give them.
inline constexpr NameRow<BallFrictionModel> ball_friction_model_names[] = {
    {BallFrictionModel::fit, "fit"},
    {BallFrictionModel::constant, "constant"},
};
static_assert(names_in_order(ball_friction_model_names));

/// Ball-ball friction against the relative sliding speed v_rel (m/s) of the two surfaces where
/// they touch. The defaults are Alciatore's fit to measured throw (as pooltool uses it): u_b is
/// about 0.118 for surfaces barely sliding and tends to 0.00995 for fast ones, which is why slow
/// cuts throw several degrees and fast ones well under one.
struct BallFriction {
    BallFrictionModel model = BallFrictionModel::fit; ///< which law
    double a = 9.951e-3;                              ///< fit: u_b of very fast slides
    double b = 0.108;                                 ///< fit: what a slow slide adds to a
    double c = 1.088;                                 ///< fit: s/m, how soon the excess fades
    double constant = 0.05;                           ///< constant model: u_b
    /// Same law and same numbers.
    bool operator==(const BallFriction&) const = default;
};

/// u_b of `friction` for surfaces sliding over each other at `sliding_speed` m/s (>= 0).
double ball_friction_at(const BallFriction& friction, double sliding_speed);

/// How a ball leaves a cushion or a pocket jaw.
enum class CushionModel {
    physical, ///< impulse at the cushion nose with restitution e_c and friction f_c, spin-aware
    /// the seed report's reflection of the velocity alone: the normal velocity flips, the spin is
    /// kept, so a rolling ball curls off the mirror line as the cloth turns its old spin
    ideal,
    /// a true mirror image of the ball's motion: the velocity reflected and the spin with it (an
    /// axial vector: its part along the rail's normal kept, the rest reversed), so a rolling ball
    /// leaves rolling along the mirror line and stays on it
    mirror,
    /// Stronge's compliant frictional impact at the cushion nose: normal and tangential springs
    /// (frequency ratio w_c), restitution e_c, Coulomb friction f_c, with stick and slip
    stronge,
};

/// The cushion models' names, as a scenario's `cushion` line gives them.
inline constexpr NameRow<CushionModel> cushion_model_names[] = {
    {CushionModel::physical, "physical"},
    {CushionModel::ideal, "ideal"},
    {CushionModel::mirror, "mirror"},
    {CushionModel::stronge, "stronge"},
};
static_assert(names_in_order(cushion_model_names));

/// Effective end mass of a standard cue shaft, kg: about 2.5 degrees of squirt at half a tip of
/// side.
inline constexpr double standard_shaft_end_mass = 0.0078;
/// Effective end mass of a low-deflection shaft, kg: about 1.5 degrees at half a tip.
inline constexpr double low_deflection_end_mass = 0.0044;

/// The cues that have a name, by their end mass (kg), as `--cue`, a record's and a scenario's
/// `cue` line give them; any other end mass is written as its number.
inline constexpr NameRow<double> cue_names[] = {
    {standard_shaft_end_mass, "standard"},
    {low_deflection_end_mass, "low-deflection"},
    {0.0, "none"}, // no squirt at all
};

/// How a ball slows down on the cloth. Decay, constant and combined are the classic models (the
/// seed report's): they move balls on straight lines, without spin.
enum class FrictionKind {
    physical, ///< sliding, rolling and spinning with u_s, u_r, u_sp (default)
    decay,    ///< classic model: speed shrinks by e^(-K t); no spin
    constant, ///< classic model: constant deceleration A; no spin
    combined, ///< classic model: whichever of decay and constant slows more; no spin
};

/// The cloth models' names, the first word of their text form (`format_friction`).
inline constexpr NameRow<FrictionKind> friction_kind_names[] = {
    {FrictionKind::physical, "physical"},
    {FrictionKind::decay, "decay"},
    {FrictionKind::constant, "constant"},
    {FrictionKind::combined, "combined"},
};
static_assert(names_in_order(friction_kind_names));

/// The cloth model and, for the classic models, their constants.
struct FrictionModel {
    FrictionKind kind = FrictionKind::physical; ///< which model
    double decay_rate = 0;                      ///< K in 1/s (decay, combined)
    double deceleration = 0;                    ///< A in m/s^2 (constant, combined)
    double rest_speed = 0.005;                  ///< classic models: below this speed a ball stops
    bool operator==(const FrictionModel&) const = default; ///< exact equality
};

/// Everything the simulator needs besides the table and the balls.
struct PhysicsParams {
    double ball_radius = 0.028575; ///< R
    double ball_mass = 0.170;      ///< default mass m of a ball
    /// Mass of the cue ball in racks and ball in hand (kg); 0 means `ball_mass`. Bar tables
    /// often have a heavier one.
    double cue_ball_mass = 0;
    /// The mass a rack gives the cue ball.
    double cue_mass() const { return cue_ball_mass > 0 ? cue_ball_mass : ball_mass; }
    double sliding_friction = 0.2;       ///< u_s, ball-cloth while sliding
    double rolling_friction = 0.01;      ///< u_r, rolling resistance
    double spin_friction = 0.0127;       ///< u_sp, z-spin decays at 5 g u_sp / (2 R)
    double ball_restitution = 0.95;      ///< e_b
    BallFriction ball_friction;          ///< u_b, ball-ball, against the sliding speed
    double cushion_restitution = 0.85;   ///< e_c
    double cushion_friction = 0.2;       ///< f_c
    double cushion_height_ratio = 0.635; ///< cushion nose height as a fraction of 2R
    double gravity = 9.81;               ///< g
    /// w_c of the stronge cushion: the ratio w_t / w_n of the tangential and normal vibration
    /// frequencies of the ball on the cushion's springs, between 1 and 2 (both excluded). 1.7
    /// is pooltool's value; a sphere of Poisson's ratio 0 to 0.5 gives 1.87 to 1.53.
    double cushion_frequency_ratio = 1.7;
    /// The cue's effective end mass, kg: the lighter, the less squirt; 0 turns squirt off.
    double cue_end_mass = standard_shaft_end_mass;
    /// Below this approach speed (m/s) collisions are elastic. Real restitution tends to 1 at low
    /// speed, and it keeps balls pressed together by friction from bouncing ever more often.
    double elastic_below_speed = 0.005;
    CollisionModel collision = CollisionModel::physical; ///< ball-ball model
    CushionModel cushion = CushionModel::physical;       ///< ball-cushion and ball-jaw model
    FrictionModel friction;                              ///< cloth model
    /// Exact equality (the same physics to the bit, NaN excepted).
    bool operator==(const PhysicsParams&) const = default;
};

/// The constants of PhysicsParams that a scenario's `param NAME VALUE` line, the Python module
/// and a researcher's script set by their short names: u_s, u_r, u_sp, e_b, u_b, e_c, f_c, w_c,
/// g, R and m. (u_b sets the constant ball-ball friction and the constant law with it.)
inline constexpr std::string_view physics_parameter_names[] = {
    "u_s", "u_r", "u_sp", "e_b", "u_b", "e_c", "f_c", "w_c", "g", "R", "m"};

/// Sets the constant named `name` (physics_parameter_names) of `params` to `value`, or says why
/// not in the words of `termpool simulate` ("unknown parameter 'mu' (expected ...)", "e_b must
/// be between 0 and 1 (got 1.5)"), leaving `params` as it was.
std::optional<std::string> set_physics_parameter(PhysicsParams& params, std::string_view name,
                                                 double value);

/// The value of the constant named `name` in `params` (u_b: the constant law's u_b, or the fit's
/// at zero sliding speed); nothing for an unknown name.
std::optional<double> physics_parameter(const PhysicsParams& params, std::string_view name);

} // namespace termpool
