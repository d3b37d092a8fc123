// The mirror and stronge cushion models. Mirror: the whole motion reflected, spin included, so
// a rolling ball leaves along the mirror line and stays on it (ideal, which keeps the spin,
// curls off it). Stronge: checked against a finely integrated spring contact written here from
// the model's definition (springs, Coulomb's law, restitution), not from its closed forms.
#include "support/random.hpp"
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <variant>

#include "cli/scenario.hpp"
#include "core/collision.hpp"
#include "core/compliant_impact.hpp"
#include "core/physical_cloth.hpp"
#include "physics_helpers.hpp"
#include "stress_shots.hpp"

using namespace termpool;
using termpool::test::ball_at;
using termpool::test::step_until;

namespace {

constexpr double R = 0.028575;
constexpr double degrees = 180.0 / std::numbers::pi;

// Angle of `v` from the normal {0, 1} of the bottom rail, degrees: 30 for a ball leaving it at
// 30 degrees to the normal, towards +x.
double from_normal(Vec2 v) {
    return std::atan2(v.x, v.y) * degrees;
}

// A ball rolling into the bottom rail at `incidence` degrees from its normal, through a world:
// the angle it leaves at, the angle it rolls at once the cloth has had its way, and the worst
// distance of its later centre from the mirror line.
struct Rebound {
    double leaves = 0;
    double rolls = 0;
    double off_line = 0;
};

Rebound rebound(CushionModel model, double incidence) {
    const Table table = make_table(TableSize::nine_foot);
    PhysicsParams p;
    p.cushion = model;
    World world(table, p, {ball_at(0, 0.6, 0.6)});
    world.strike({1.5, -90 + incidence, 0, 0});
    step_until(world, EventKind::rolling);
    const Event hit = step_until(world, EventKind::cushion);
    Rebound r;
    const Ball at_rail = world.balls()[0];
    r.leaves = from_normal(at_rail.velocity);
    const Vec2 line = unit_from_angle((90 - incidence) / degrees); // the mirror line's direction
    auto off_line = [&](Vec2 p) { return std::abs(cross(line, p - at_rail.position)); };
    while (world.balls()[0].state != MotionState::rolling && world.step()) {
    }
    r.rolls = from_normal(world.balls()[0].velocity);
    // Until the next rail: the centre at every event on the way, and where it rests or meets it.
    while (const auto e = world.step()) {
        r.off_line = std::max(r.off_line, off_line(world.balls()[0].position));
        if (e->kind == EventKind::cushion || e->kind == EventKind::jaw)
            break;
    }
    CHECK(hit.time > 0);
    return r;
}

// ---- A spring contact integrated step by step (the stronge model's definition) ----
//
// Units: m / beta_n = 1, k_n = 1 (so w_n = 1), approach speed 1. The normal spring pushes with
// F = d while it compresses and (d - d_p) / e^2 after (d_p = d_max (1 - e^2)), so it gives back
// e^2 of its energy; the tangential spring k_t = 1 / eta^2 pushes with -k_t u while its foot
// sticks, and its foot slides once k_t |u| would exceed mu F. The contact point's tangential
// velocity changes at b F_t (b = beta_t / beta_n).
struct SpringContact {
    double mu, e, r, b;
    double kt() const { return r * r / b; }
};

struct Y {
    double d = 0;  // normal compression
    double vn = 0; // normal velocity of the contact point (negative: closing)
    double vt = 0; // tangential velocity
    double u = 0;  // tangential spring deflection (free while stuck; set by friction in a slip)
};

enum class Mode { stick, slip };

struct Integration {
    const SpringContact& c;
    bool restituting = false;
    double dp = 0; // the normal spring's set once it restitutes
    Mode mode = Mode::stick;
    double sigma = 1; // slip direction

    double normal_force(const Y& y) const { return restituting ? (y.d - dp) / (c.e * c.e) : y.d; }
    double normal_force_rate(const Y& y) const { return restituting ? -y.vn / (c.e * c.e) : -y.vn; }
    Y rate(const Y& y) const {
        const double f = normal_force(y);
        Y dy;
        dy.d = -y.vn;
        dy.vn = f;
        if (mode == Mode::stick) {
            dy.u = y.vt;
            dy.vt = -c.b * c.kt() * y.u;
        } else {
            dy.u = 0; // u follows the friction limit, set after each step
            dy.vt = -c.b * sigma * c.mu * f;
        }
        return dy;
    }
    Y step(const Y& y, double h) const {
        auto add = [](const Y& a, const Y& k, double s) {
            return Y{a.d + s * k.d, a.vn + s * k.vn, a.vt + s * k.vt, a.u + s * k.u};
        };
        const Y k1 = rate(y), k2 = rate(add(y, k1, h / 2)), k3 = rate(add(y, k2, h / 2)),
                k4 = rate(add(y, k3, h));
        Y out{y.d + h / 6 * (k1.d + 2 * k2.d + 2 * k3.d + k4.d),
              y.vn + h / 6 * (k1.vn + 2 * k2.vn + 2 * k3.vn + k4.vn),
              y.vt + h / 6 * (k1.vt + 2 * k2.vt + 2 * k3.vt + k4.vt),
              y.u + h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u)};
        if (mode == Mode::slip)
            out.u = sigma * c.mu * normal_force(out) / c.kt();
        return out;
    }
    // What ends the current phase: it crosses from > 0 to <= 0.
    double normal_event(const Y& y) const { return restituting ? normal_force(y) : -y.vn; }
    double tangential_event(const Y& y) const {
        if (mode == Mode::stick)
            return c.mu * normal_force(y) - c.kt() * std::abs(y.u);
        return sigma * y.vt - c.mu * normal_force_rate(y) / c.kt();
    }
};

// The tangential velocity at separation of the spring contact, for slip = v_t0 / V.
double integrated_impact(const SpringContact& c, double slip) {
    Integration in{c};
    Y y{0, -1, slip, 0};
    // The foot first moves at slip - mu F'(0) / k_t = slip - mu / k_t.
    in.mode = slip <= c.mu / c.kt() ? Mode::stick : Mode::slip;
    // The step, in units of the compression's time; restitution runs 1/e_c times faster.
    constexpr double compression_step = 2e-4;
    for (int guard = 0; guard < 200000; ++guard) {
        // A stick already over its limit slips from here: the limit falls with the normal
        // force, and at small e_c it falls fast while the contact restitutes.
        // (Beyond round-off: a stick that starts at its limit stays one.)
        if (in.mode == Mode::stick && in.tangential_event(y) < -1e-12 * c.mu * in.normal_force(y)) {
            in.mode = Mode::slip;
            in.sigma = y.u < 0 ? -1 : 1;
        }
        const double h = in.restituting ? compression_step * std::max(c.e, 1e-3) : compression_step;
        Y next = in.step(y, h);
        const bool normal = in.normal_event(next) <= 0;
        const bool tangential = in.tangential_event(next) < 0 && in.tangential_event(y) >= -1e-15;
        if (!normal && !tangential) {
            y = next;
            continue;
        }
        // Halve the step to the first event.
        double lo = 0, hi = h;
        for (int i = 0; i < 200; ++i) {
            const double mid = (lo + hi) / 2;
            if (mid <= lo || mid >= hi)
                break;
            const Y at = in.step(y, mid);
            const bool hit = in.normal_event(at) <= 0 ||
                             (in.tangential_event(at) < 0 && in.tangential_event(y) >= -1e-15);
            (hit ? hi : lo) = mid;
        }
        const Y at = in.step(y, hi);
        if (in.normal_event(at) <= 0) {
            y = at;
            if (in.restituting)
                return y.vt; // separated
            in.restituting = true;
            in.dp = y.d * (1 - c.e * c.e);
            if (c.e == 0)
                return y.vt;
            if (in.mode == Mode::slip)
                y.u = in.sigma * c.mu * in.normal_force(y) / c.kt();
            continue;
        }
        y = at;
        if (in.mode == Mode::stick) {
            in.mode = Mode::slip;
            in.sigma = y.u < 0 ? -1 : 1;
        } else {
            in.mode = Mode::stick;
        }
    }
    FAIL("the spring contact did not end");
    return 0;
}

} // namespace

TEST_CASE("mirror cushion: a rolling ball leaves along the mirror line and rolls on it",
          "[physics][cushion]") {
    for (const double incidence : {30.0, 10.0, 45.0, 70.0}) {
        const Rebound r = rebound(CushionModel::mirror, incidence);
        INFO("incidence " << incidence);
        CHECK(r.leaves == Approx(incidence).margin(1e-9));
        CHECK(r.rolls == Approx(incidence).margin(1e-9));
        CHECK(r.off_line < 1e-9);
    }
}

TEST_CASE("ideal cushion keeps the spin: 30 degrees in, 30 out, then it curls to 53.4",
          "[physics][cushion]") {
    const Rebound r = rebound(CushionModel::ideal, 30);
    CHECK(r.leaves == Approx(30).margin(1e-9));
    CHECK(r.rolls == Approx(53.4).margin(0.05));
}

TEST_CASE("mirror cushion reflects the spin as an axial vector", "[physics][cushion]") {
    PhysicsParams p;
    p.cushion = CushionModel::mirror;
    Ball b = ball_at(0, 1, 1);
    b.velocity = {0.3, -1.2};
    b.angular_velocity = {11, -7, 23};
    b.state = MotionState::sliding;
    const double before = kinetic_energy(b, R);
    core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
    // The rail is the plane y = const: velocity y flips; spin keeps y, flips x and z.
    CHECK(b.velocity.x == 0.3);
    CHECK(b.velocity.y == 1.2);
    CHECK(b.angular_velocity.x == -11);
    CHECK(b.angular_velocity.y == -7);
    CHECK(b.angular_velocity.z == -23);
    CHECK(kinetic_energy(b, R) == Approx(before).epsilon(1e-15));
}

TEST_CASE("stronge: the closed forms agree with a finely integrated spring contact",
          "[physics][cushion][stronge]") {
    int cases = 0, stick_first = 0, gross = 0;
    double worst = 0;
    for (const double r : {1.05, 1.3, 1.53, 1.7, 1.87, 1.95}) {
        // Small e_c too: the contact restitutes fast and a stick can end in it.
        for (const double e : {0.0, 0.00246, 0.05, 0.3, 0.6, 0.85, 1.0}) {
            for (const double mu : {0.05, 0.1618, 0.2, 0.6}) {
                for (const double ratio : {0.2, 0.7, 1.1, 1.9, 2.7, 3.3, 4.1, 5.3, 7.0, 15.0}) {
                    const double slip = ratio * mu;
                    INFO("r " << r << " e " << e << " mu " << mu << " slip " << slip);
                    const SpringContact c{mu, e, r, 3.5};
                    const double expected = integrated_impact(c, slip);
                    const core::CompliantImpact got = core::compliant_impact(slip, mu, e, r, 3.5);
                    CHECK(got.normal == e);
                    CHECK(got.tangential == Approx(expected).margin(1e-9));
                    worst = std::max(worst, std::abs(got.tangential - expected));
                    ++cases;
                    stick_first += slip <= mu * 3.5 / (r * r);
                    gross += got.tangential == slip - mu * 3.5 * (1 + e);
                }
            }
        }
    }
    // A stick that starts while the contact restitutes at a tiny e_c and soon exceeds its
    // falling limit (a review found the reference stuck in it): it must slip again.
    const SpringContact late{0.1618, 0.00246, 1.7396, 3.5};
    CHECK(core::compliant_impact(0.5662, 0.1618, 0.00246, 1.7396, 3.5).tangential ==
          Approx(integrated_impact(late, 0.5662)).margin(1e-9));
    INFO("worst difference " << worst);
    CHECK(worst < 1e-9);
    CHECK(cases == 6 * 7 * 4 * 10);
    CHECK(stick_first > 100); // every regime is met
    CHECK(gross > 100);
}

namespace {

// What the stronge cushion should do to `ball` meeting a rail with normal `towards`, built here
// from the integrated contact: the contact at the cushion nose (0.635 of 2R high), its closing
// speed and slip, the impulses that give the contact point the integrated velocities at
// separation, and the cloth taking the vertical part of the velocity change.
Ball stronge_reference(Ball ball, Vec2 towards, const PhysicsParams& p) {
    const double h = p.cushion_height_ratio * 2 * p.ball_radius - p.ball_radius;
    const double across = std::sqrt(p.ball_radius * p.ball_radius - h * h);
    const Vec3 arm{towards.x * across, towards.y * across, h};
    const Vec3 n = arm * (-1 / p.ball_radius);
    const Vec3 vc = lift(ball.velocity) + cross(ball.angular_velocity, arm);
    const double vn = dot(vc, n);
    REQUIRE(vn < 0);
    const Vec3 tangential = vc - n * vn;
    const double vt = std::sqrt(dot(tangential, tangential));
    const SpringContact c{p.cushion_friction, p.cushion_restitution, p.cushion_frequency_ratio,
                          3.5};
    const double vt_end = integrated_impact(c, vt / -vn) * -vn;
    const double m = ball.mass;
    Vec3 impulse = n * (m * (p.cushion_restitution * -vn - vn));
    if (vt > 0)
        impulse = impulse + tangential * (1 / vt) * (m / 3.5 * (vt_end - vt));
    ball.velocity = ball.velocity + planar(impulse) * (1 / m);
    const double inertia = 0.4 * m * p.ball_radius * p.ball_radius;
    ball.angular_velocity = ball.angular_velocity + cross(arm, impulse) * (1 / inertia);
    return ball;
}

double vec_gap(Vec3 a, Vec3 b) {
    return std::sqrt(dot(a - b, a - b));
}

} // namespace

TEST_CASE("stronge cushion: balls at several angles, speeds and spins as the integrated contact "
          "gives",
          "[physics][cushion][stronge]") {
    double worst_velocity = 0, worst_spin = 0;
    int cases = 0;
    for (const double ratio : {1.2, 1.7, 1.9}) {
        for (const double friction : {0.1, 0.2, 0.4}) {
            PhysicsParams p;
            p.cushion = CushionModel::stronge;
            p.cushion_frequency_ratio = ratio;
            p.cushion_friction = friction;
            for (const double incidence : {0.0, 15.0, 30.0, 45.0, 60.0, 80.0}) {
                for (const double speed : {0.2, 1.0, 4.0}) {
                    // No spin, rolling, stunned draw, side spin both ways, a mix.
                    const Vec2 v = unit_from_angle((-90 + incidence) / degrees) * speed;
                    const Vec3 roll{-v.y / R, v.x / R, 0};
                    const std::array<Vec3, 6> spins = {Vec3{},
                                                       roll,
                                                       roll * -1.0,
                                                       Vec3{0, 0, 2 * speed / R},
                                                       Vec3{0, 0, -2 * speed / R},
                                                       roll * 0.5 + Vec3{0, 0, speed / R}};
                    for (const Vec3 w : spins) {
                        Ball b = ball_at(0, 1, R);
                        b.velocity = v;
                        b.angular_velocity = w;
                        b.state = MotionState::sliding;
                        const Ball expected = stronge_reference(b, {0, -1}, p);
                        const double before = kinetic_energy(b, R);
                        core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
                        INFO("w_c " << ratio << " f_c " << friction << " incidence " << incidence
                                    << " speed " << speed << " spin " << w.x << " " << w.y << " "
                                    << w.z);
                        const double dv = length(b.velocity - expected.velocity) / speed;
                        const double dw =
                            vec_gap(b.angular_velocity, expected.angular_velocity) * R / speed;
                        CHECK(dv < 1e-9);
                        CHECK(dw < 1e-9);
                        CHECK(kinetic_energy(b, R) <= before);
                        CHECK(b.velocity.y > 0);
                        worst_velocity = std::max(worst_velocity, dv);
                        worst_spin = std::max(worst_spin, dw);
                        ++cases;
                    }
                }
            }
        }
    }
    INFO("worst relative differences: velocity " << worst_velocity << ", spin " << worst_spin);
    CHECK(cases == 972);
    CHECK(worst_velocity < 1e-9);
    CHECK(worst_spin < 1e-9);
}

TEST_CASE("stronge cushion never adds energy", "[physics][cushion][stronge][property]") {
    Random rng(7);
    int rebounds = 0;
    for (int i = 0; i < 100000; ++i) {
        PhysicsParams p;
        p.cushion = CushionModel::stronge;
        p.cushion_frequency_ratio = rng.uniform(1.0001, 1.9999);
        p.cushion_friction = rng.uniform(0, 1);
        p.cushion_restitution = rng.uniform(0, 1);
        Ball b = test::random_cushion_approach(rng, R);
        const double before = kinetic_energy(b, R);
        core::resolve_cushion(b, {1, 0}, p, core::cloth_model(p.friction));
        CHECK(kinetic_energy(b, R) <= before + 1e-12);
        rebounds += b.velocity.x < 0;
    }
    CHECK(rebounds == 100000);
}

TEST_CASE("stronge cushion: mirror-image shots come off as mirror images", "[physics][cushion]") {
    PhysicsParams p;
    p.cushion = CushionModel::stronge;
    Random rng(11);
    for (int i = 0; i < 1000; ++i) {
        // A ball into the bottom rail, and its image in the plane x = const.
        Ball a = ball_at(0, 1, R);
        a.velocity = {rng.uniform(-3, 3), rng.uniform(-3, -0.1)};
        a.angular_velocity = {rng.uniform(-100, 100), rng.uniform(-100, 100),
                              rng.uniform(-100, 100)};
        a.state = MotionState::sliding;
        Ball b = a;
        b.velocity.x = -a.velocity.x;
        b.angular_velocity = {a.angular_velocity.x, -a.angular_velocity.y, -a.angular_velocity.z};
        const auto cloth = core::cloth_model(p.friction);
        core::resolve_cushion(a, {0, -1}, p, cloth);
        core::resolve_cushion(b, {0, -1}, p, cloth);
        CHECK(b.velocity.x == Approx(-a.velocity.x).margin(1e-12));
        CHECK(b.velocity.y == Approx(a.velocity.y).margin(1e-12));
        CHECK(b.angular_velocity.x == Approx(a.angular_velocity.x).margin(1e-9));
        CHECK(b.angular_velocity.y == Approx(-a.angular_velocity.y).margin(1e-9));
        CHECK(b.angular_velocity.z == Approx(-a.angular_velocity.z).margin(1e-9));
    }
    // Straight in with no side spin: straight out, no side spin made.
    for (const double top : {-50.0, 0.0, 35.0}) {
        Ball b = ball_at(0, 1, R);
        b.velocity = {0, -2};
        b.angular_velocity = {top, 0, 0};
        b.state = MotionState::sliding;
        core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
        CHECK(b.velocity.x == 0);
        CHECK(b.velocity.y > 0);
        CHECK(b.angular_velocity.z == 0);
    }
}

TEST_CASE("stronge cushion: slow rebounds are elastic, as the physical model's",
          "[physics][cushion]") {
    PhysicsParams p;
    p.cushion = CushionModel::stronge;
    Ball b = ball_at(0, 1, R);
    b.velocity = {0.001, -0.003};
    b.state = MotionState::sliding;
    Ball physical = b;
    core::resolve_cushion(b, {0, -1}, p, core::cloth_model(p.friction));
    p.cushion = CushionModel::physical;
    core::resolve_cushion(physical, {0, -1}, p, core::cloth_model(p.friction));
    CHECK(b.velocity == physical.velocity);
    CHECK(b.angular_velocity == physical.angular_velocity);
}

TEST_CASE("scenario: cushion mirror and stronge, and the stronge cushion's w_c",
          "[scenario][cushion]") {
    const auto parse = [](const std::string& text) { return cli::parse_scenario(text); };
    const auto model = [&](const std::string& text) {
        const auto r = parse(text);
        REQUIRE(std::holds_alternative<cli::Scenario>(r));
        return std::get<cli::Scenario>(r).setup.physics;
    };
    CHECK(model("cushion mirror\n").cushion == CushionModel::mirror);
    CHECK(model("cushion stronge\n").cushion == CushionModel::stronge);
    CHECK(model("cushion stronge\nparam w_c 1.53\n").cushion_frequency_ratio == 1.53);
    CHECK(model("").cushion_frequency_ratio == 1.7);
    const auto error = [&](const std::string& text) {
        const auto r = parse(text);
        REQUIRE(std::holds_alternative<cli::ScenarioError>(r));
        return std::get<cli::ScenarioError>(r).message;
    };
    CHECK(error("cushion bouncy\n") ==
          "unknown cushion model 'bouncy' (expected physical, ideal, mirror or stronge)");
    CHECK(error("collision mirror\n") ==
          "unknown collision model 'mirror' (expected physical or ideal)");
    CHECK(error("param w_c 2\n") == "w_c must be between 1 and 2, both excluded (got 2)");
    CHECK(error("param w_c 1\n") == "w_c must be between 1 and 2, both excluded (got 1)");
    CHECK(error("param w_c 0.5\n") == "w_c must be between 1 and 2, both excluded (got 0.5)");
    CHECK(error("param w_c x\n").find("not a number") != std::string::npos);
    CHECK(error("param w_x 1.5\n") ==
          "unknown parameter 'w_x' (expected u_s, u_r, u_sp, e_b, u_b, e_c, f_c, w_c, g, R or m)");
}

TEST_CASE("random shots off mirror and stronge cushions: apart, on the table, no energy made, "
          "deterministic",
          "[physics][stress][cushion]") {
    int failures = 0, long_shots = 0;
    for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
        test::StressShot shot = test::make_stress_shot(seed);
        shot.params.cushion = seed % 2 ? CushionModel::mirror : CushionModel::stronge;
        const test::StressReport r = test::check_stress_shot(shot);
        INFO("seed " << seed << " cushion " << name_of(cushion_model_names, shot.params.cushion)
                     << ": " << test::stress_failure_name(r.failure) << " " << r.detail);
        CHECK(r.failure == test::StressFailure::none);
        failures += r.failure != test::StressFailure::none;
        long_shots += r.events > test::long_shot_events;
    }
    CHECK(failures == 0);
    CHECK(long_shots == 0);
}
