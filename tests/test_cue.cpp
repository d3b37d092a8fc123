// The cue's own effects: squirt against Alciatore's formula, the sign of side spin, the spin axis
// a raised cue tilts, swerve against the closed form of the sliding parabola, and the strikes
// the simulator refuses.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "physics_helpers.hpp"

using namespace termpool;
using termpool::test::ball_at;
using termpool::test::find_ball;
using termpool::test::step_until;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double degree = std::numbers::pi / 180.0;

// TP A.31, written out independently of the code: tan(squirt) for tip offset a = b/R.
double squirt_formula_deg(double a, double ball_mass, double end_mass) {
    const double t =
        2.5 * a * std::sqrt(1 - a * a) / (1 + ball_mass / end_mass + 2.5 * (1 - a * a));
    return std::atan(t) / degree;
}

double heading_deg(Vec2 v) {
    return std::atan2(v.y, v.x) / degree;
}

} // namespace

TEST_CASE("squirt follows the analytical formula for both shafts", "[cue][squirt]") {
    const double m = 0.170;
    for (const double end_mass : {standard_shaft_end_mass, low_deflection_end_mass}) {
        for (const double a : {-0.5, -0.3, -0.1, 0.05, 0.2, 0.4, 0.5}) {
            CHECK(squirt_angle_deg(a, m, end_mass) ==
                  Approx(squirt_formula_deg(a, m, end_mass)).epsilon(1e-12));
        }
    }
    // The figures the parameters are documented with, at half a tip.
    CHECK(squirt_angle_deg(0.5, m, standard_shaft_end_mass) == Approx(2.5).margin(0.05));
    CHECK(squirt_angle_deg(0.5, m, low_deflection_end_mass) == Approx(1.5).margin(0.05));
    CHECK(squirt_angle_deg(0.3, m, 0) == 0);
    CHECK(squirt_angle_deg(0, m, standard_shaft_end_mass) == 0);
}

TEST_CASE("right english sends a level-cued ball left of the aim line by the squirt angle",
          "[cue][squirt]") {
    PhysicsParams p;
    for (const double end_mass : {standard_shaft_end_mass, low_deflection_end_mass, 0.0}) {
        p.cue_end_mass = end_mass;
        for (const double aim : {0.0, 37.0, 200.0}) {
            for (const double a : {0.5, 0.25, -0.4}) {
                const Ball cue = ball_at(0, 1.0, 0.6, 0.17);
                const Ball b = strike_cue_ball(cue, {2.0, aim, a, 0}, p);
                const double expected = end_mass > 0 ? squirt_formula_deg(a, 0.17, end_mass) : 0;
                // Counter-clockwise is left: the ball leaves at aim + squirt.
                CHECK(heading_deg(b.velocity) - aim + (aim > 180 ? 360 : 0) ==
                      Approx(expected).margin(1e-9));
                CHECK(length(b.velocity) == Approx(2.0).epsilon(1e-14));
            }
        }
    }
    // A heavier cue ball squirts less: the end mass is a smaller part of what the tip pushes.
    CHECK(squirt_angle_deg(0.4, 0.20, standard_shaft_end_mass) <
          squirt_angle_deg(0.4, 0.17, standard_shaft_end_mass));
}

TEST_CASE("right english turns the ball counter-clockwise seen from above", "[cue][spin]") {
    PhysicsParams p;
    p.cue_end_mass = 0; // without squirt the spin is the point impact's 5 v a / (2 R)
    const double v = 1.5;
    const double a = 0.4;
    const Ball b = strike_cue_ball(ball_at(0, 1, 0.6), {v, 90, a, 0}, p);
    // Aiming along +y, right of centre seen from behind is +x: r x J = (R a x) x (J y) = +z.
    CHECK(b.angular_velocity.z == Approx(5 * v * a / (2 * p.ball_radius)).epsilon(1e-12));
    CHECK(std::abs(b.angular_velocity.x) < 1e-9);
    CHECK(std::abs(b.angular_velocity.y) < 1e-9);
    // Squirt's sideways push at the back of the ball takes a little of that spin away.
    p.cue_end_mass = standard_shaft_end_mass;
    const Ball squirted = strike_cue_ball(ball_at(0, 1, 0.6), {v, 90, a, 0}, p);
    CHECK(squirted.angular_velocity.z > 0);
    CHECK(squirted.angular_velocity.z < b.angular_velocity.z);
}

TEST_CASE("right english off a cushion opens the angle to the player's right", "[cue][spin]") {
    PhysicsParams p;
    p.cue_end_mass = 0; // squirt would change the angle of approach as well
    // Up the table at 60 degrees into the far long cushion (y = width); the player's right is
    // (sin 60, -cos 60): rebounds there run along +x.
    const auto rebound_heading = [&](double side) {
        World world(table, p, {ball_at(0, 1.0, table.width - 0.4)});
        world.strike({1.5, 60, side, 0});
        step_until(world, EventKind::cushion);
        const Ball cue = find_ball(world.balls(), 0);
        REQUIRE(cue.velocity.y < 0);
        return heading_deg(cue.velocity); // about -60: the mirror of the approach
    };
    const double plain = rebound_heading(0);
    const double right = rebound_heading(0.4);
    const double left = rebound_heading(-0.4);
    // Right english: running english here, the ball comes off longer, nearer +x.
    CHECK(right > plain + 3);
    CHECK(left < plain - 3);
}

TEST_CASE("a raised cue tilts the spin axis and takes the vertical part into the slate",
          "[cue][elevation]") {
    PhysicsParams p;
    p.cue_end_mass = 0;
    const double v = 1.2;
    const double a = 0.3;
    for (const double elevation : {0.0, 20.0, 45.0, 70.0}) {
        const double e = elevation * degree;
        const Ball b = strike_cue_ball(ball_at(0, 1, 0.6), {v, 0, a, 0, elevation}, p);
        CHECK(b.velocity.x == Approx(v * std::cos(e)).epsilon(1e-14));
        CHECK(std::abs(b.velocity.y) < 1e-15);
        // r x J / I for the tip at R a to the right (-y) of the cue's axis (cos e, 0, -sin e):
        // the axis across the cue, upwards and tilted forward, (sin e, 0, cos e).
        const double w = 5 * v * a / (2 * p.ball_radius);
        CHECK(b.angular_velocity.x == Approx(w * std::sin(e)).margin(1e-12));
        CHECK(std::abs(b.angular_velocity.y) < 1e-12);
        CHECK(b.angular_velocity.z == Approx(w * std::cos(e)).epsilon(1e-12));
    }
    // Straight down through the centre: no spin at all, the ball slides off at v cos e.
    const Ball centre = strike_cue_ball(ball_at(0, 1, 0.6), {1.0, 0, 0, 0, 50}, p);
    CHECK(std::abs(centre.angular_velocity.x) + std::abs(centre.angular_velocity.y) +
              std::abs(centre.angular_velocity.z) <
          1e-12);
    // Follow across a raised cue is about the horizontal axis across the shot.
    const Ball follow = strike_cue_ball(ball_at(0, 1, 0.6), {1.0, 0, 0, 0.3, 40}, p);
    CHECK(follow.angular_velocity.y > 0);
    CHECK(std::abs(follow.angular_velocity.x) < 1e-12);
}

TEST_CASE("swerve: side with elevation slides on the closed-form parabola", "[cue][swerve]") {
    PhysicsParams p; // standard shaft: squirt first, then the curve
    const Ball start = ball_at(0, 0.4, 0.6);
    for (const double elevation : {15.0, 35.0, 60.0}) {
        for (const double side : {0.4, -0.25}) {
            const Strike strike{1.2, 10, side, 0.1, elevation};
            REQUIRE_FALSE(strike_problem(strike, p));
            const Ball b0 = strike_cue_ball(start, strike, p);
            // The slip of the contact point, v + w x (-R z), and the friction against it.
            const Vec2 slip{b0.velocity.x - p.ball_radius * b0.angular_velocity.y,
                            b0.velocity.y + p.ball_radius * b0.angular_velocity.x};
            const double mu_g = p.sliding_friction * p.gravity;
            const Vec2 acc = normalized(slip) * -mu_g;
            const double slide_time = 2 * length(slip) / (7 * mu_g);
            // The slip is not along the velocity: the ball curves towards the side struck.
            const double turn = cross(b0.velocity, acc);
            CHECK(turn * side < 0);
            World world(table, p, {start});
            world.record(true);
            world.strike(strike);
            while (world.step()) {
            }
            const Trajectory& path = world.trajectory();
            for (const double f : {0.1, 0.35, 0.6, 0.9, 0.999}) {
                const double t = f * slide_time;
                const Ball at = path.sample(t)[0];
                const Vec2 want = b0.position + b0.velocity * t + acc * (0.5 * t * t);
                CHECK(length(at.position - want) < 1e-12);
                CHECK(at.state == MotionState::sliding);
            }
            // Curvature at the start, |v x a| / |v|^3, from the closed form against the path's
            // own: the sideways offset after a short time is kappa |v|^2 t^2 / 2.
            const double kappa = std::abs(turn) / std::pow(length(b0.velocity), 3);
            const double t = 1e-3 * slide_time;
            const Vec2 along = normalized(b0.velocity);
            const Vec2 offset = path.sample(t)[0].position - b0.position;
            CHECK(std::abs(cross(along, offset)) ==
                  Approx(0.5 * kappa * length_squared(b0.velocity) * t * t).epsilon(1e-6));
        }
    }
}

TEST_CASE("masse: at a high elevation the path bends through a large angle", "[cue][swerve]") {
    PhysicsParams p;
    p.cue_end_mass = 0;
    World world(table, p, {ball_at(0, 0.6, 0.6)});
    const Strike strike{1.2, 0, 0.5, 0, 75};
    REQUIRE_FALSE(strike_problem(strike, p));
    world.strike(strike);
    step_until(world, EventKind::rolling);
    const Ball rolled = find_ball(world.balls(), 0);
    // Right english with the cue raised curves the ball to the right (-y, aiming along +x).
    CHECK(heading_deg(rolled.velocity) < -45);
}

TEST_CASE("classic cloths keep no spin: a raised cue only slows the ball", "[cue][classic]") {
    PhysicsParams p;
    p.friction = {FrictionKind::constant, 0, 0.5, 0.005};
    const Ball b = strike_cue_ball(ball_at(0, 1, 0.6), {2.0, 0, 0.3, 0.2, 40}, p);
    CHECK(b.angular_velocity == Vec3{});
    // Squirt still turns it (left, for right english): that is the cue's doing, not the cloth's.
    CHECK(heading_deg(b.velocity) > 0);
    CHECK(b.velocity.x == Approx(2.0 * std::cos(40 * degree)).epsilon(1e-3));
}

TEST_CASE("strike_problem names what is out of range", "[cue][refuse]") {
    const PhysicsParams p;
    CHECK_FALSE(strike_problem({2, 0, 0.5, -0.5, 0}, p));
    CHECK_FALSE(strike_problem({max_strike_speed, 0, 0, 0, 0}, p));
    CHECK_FALSE(strike_problem({0.5, 0, 0, 0, max_cue_elevation_deg}, p));
    CHECK(strike_problem({20.5, 0, 0, 0, 0}, p).value_or("").find("speed") == 0);
    CHECK(strike_problem({-1, 0, 0, 0, 0}, p).value_or("").find("speed") == 0);
    CHECK(strike_problem({1, 0, 0.6, 0, 0}, p).value_or("").find("side") == 0);
    CHECK(strike_problem({1, 0, 0, -0.51, 0}, p).value_or("").find("follow") == 0);
    CHECK(strike_problem({1, 0, 0, 0, -1}, p).value_or("").find("elevation") == 0);
    CHECK(strike_problem({1, 0, 0, 0, 81}, p).value_or("").find("elevation") == 0);
    CHECK(strike_problem({NAN, 0, 0, 0, 0}, p).value_or("").find("finite") != std::string::npos);
    CHECK(strike_problem({1, 0, 0, 0, INFINITY}, p));
}

TEST_CASE("a strike that would make the ball jump off the slate is refused, with its limit",
          "[cue][refuse]") {
    const PhysicsParams p;
    // Rebound e = 0.5 of v sin(e) may lift the centre at most R: v <= sqrt(2 g R) / (0.5 sin e).
    const double limit = std::sqrt(2 * p.gravity * p.ball_radius) / (0.5 * std::sin(60 * degree));
    CHECK(limit == Approx(1.73).margin(0.005));
    CHECK_FALSE(strike_problem({limit * 0.999, 0, 0, 0, 60}, p));
    const std::optional<std::string> why = strike_problem({limit * 1.001, 0, 0, 0, 60}, p);
    REQUIRE(why);
    CHECK(why->find("jump") != std::string::npos);
    CHECK(why->find("at most 1.73 m/s") != std::string::npos);
    // A level cue never jumps the ball, whatever the speed.
    CHECK_FALSE(strike_problem({max_strike_speed, 0, 0.5, 0.5, 0}, p));
}
