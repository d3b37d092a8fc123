#include "collision.hpp"

#include "../support/portable_math.hpp"
#include <algorithm>
#include <cmath>

#include "classic_motion.hpp"
#include "compliant_impact.hpp"
#include "physical_cloth.hpp"

namespace termpool::core {
namespace {

double effective_restitution(double restitution, double approach_speed, const PhysicsParams& p) {
    return approach_speed < p.elastic_below_speed ? 1.0 : restitution;
}

double moment_of_inertia(double mass, double radius) {
    return 0.4 * mass * radius * radius;
}

// Friction impulse at a contact whose points slip at `slip` (3D), limited by Coulomb's law and by
// the impulse that stops the slip. `inverse_mass_tangent` is the slip change per unit impulse.
Vec3 friction_impulse(Vec3 slip, double normal_impulse, double friction,
                      double inverse_mass_tangent) {
    const double slip_speed = std::sqrt(dot(slip, slip));
    if (slip_speed == 0)
        return {};
    const double stick = slip_speed / inverse_mass_tangent;
    const double magnitude = std::min(friction * normal_impulse, stick);
    return slip * (-magnitude / slip_speed);
}

// The relative velocity `w` of two things in contact, turned so that they part along `n` at
// min_separation_speed at least, with its length kept where its sideways part allows: rounding
// (or a push's end state) can leave a pair touching with no speed to part, and found in contact
// again at once. `deficit` gets what |w|^2 had to grow by when turning was not enough, m^2/s^2.
Vec2 turned_to_part(Vec2 w, Vec2 n, double& deficit) {
    const double normal = dot(w, n);
    const Vec2 sideways = w - n * normal;
    const double sideways_squared = dot(sideways, sideways);
    const double target = min_separation_speed;
    const double left = sideways_squared + normal * normal - target * target;
    deficit = left < 0 ? -left : 0;
    const double keep = sideways_squared > 0 && left > 0 ? std::sqrt(left / sideways_squared) : 0;
    return n * target + sideways * keep;
}

// The energy `energy` (J) that parting needed and turning could not give, taken from the
// common motion (velocity `common`, mass `mass`) where it has that much: parting never adds
// energy unless the two were at rest together, and then at most 1/2 mu min_separation_speed^2.
Vec2 paid_from(Vec2 common, double mass, double energy) {
    const double have = 0.5 * mass * dot(common, common);
    if (energy <= 0 || have <= 0)
        return common;
    return common * std::sqrt(std::max(0.0, 1 - energy / have));
}

// The friction impulse of a ball-ball contact with normal impulse `normal_impulse`. Its
// horizontal part throws the object ball (from cut and from side spin).
void apply_ball_friction(Ball& a, Ball& b, Vec2 n, double normal_impulse, const PhysicsParams& p) {
    const double R = p.ball_radius;
    // Slip of the two surfaces at the contact, including the vertical part that top and bottom
    // spin make; only the tangential part matters. The normal impulse leaves it unchanged, so
    // its length is the sliding speed at impact, which sets the friction.
    const Vec3 n3 = lift(n);
    const Vec3 va = lift(a.velocity) + cross(a.angular_velocity, n3 * R);
    const Vec3 vb = lift(b.velocity) + cross(b.angular_velocity, n3 * -R);
    Vec3 slip = va - vb;
    slip = slip - n3 * dot(slip, n3);
    const double friction = ball_friction_at(p.ball_friction, std::sqrt(dot(slip, slip)));
    if (!(friction > 0))
        return;
    const double inv_a = 1.0 / a.mass, inv_b = 1.0 / b.mass;
    const double inverse_tangent = 3.5 * (inv_a + inv_b);
    const Vec3 impulse = friction_impulse(slip, normal_impulse, friction, inverse_tangent);
    // The vertical part of the impulse would lift or press the balls; the cloth takes it.
    a.velocity += planar(impulse) * inv_a;
    b.velocity -= planar(impulse) * inv_b;
    const Vec3 torque = cross(n3 * R, impulse);
    a.angular_velocity += torque * (1.0 / moment_of_inertia(a.mass, R));
    b.angular_velocity += torque * (1.0 / moment_of_inertia(b.mass, R));
}

// Two balls that meet slower than `elastic_below_speed` while the cloth drives one into the other
// (a ball with top spin catching up with the one ahead) would bounce ever more often, each
// slide-to-roll transition taking a little more of their relative speed. In reality they stay
// pressed together until both roll at one speed: the cloth acts at each ball's contact point, so
// the pair's angular momentum about those points along the line of centres is what survives.
// The push is resolved at once to that end state; it only removes energy.
void resolve_push(Ball& a, Ball& b, Vec2 n, const PhysicsParams& p) {
    const double R = p.ball_radius;
    const Vec2 roll_axis = perpendicular(n); // spin about it rolls a ball along n
    auto rolling_momentum = [&](const Ball& ball) {
        return ball.mass *
               (dot(ball.velocity, n) + 0.4 * R * dot(planar(ball.angular_velocity), roll_axis));
    };
    const double common = (rolling_momentum(a) + rolling_momentum(b)) / (1.4 * (a.mass + b.mass));
    for (Ball* ball : {&a, &b}) {
        ball->velocity += n * (common - dot(ball->velocity, n));
        const double spin = dot(planar(ball->angular_velocity), roll_axis);
        ball->angular_velocity += lift(roll_axis * (common / R - spin));
    }
}

// Turns a ball's velocity and horizontal spin together (so neither its energy nor its slip speed
// changes) until its velocity along n is `target`, as far as its speed allows.
void turn_towards(Ball& ball, Vec2 n, double target) {
    const double speed = length(ball.velocity);
    if (speed == 0)
        return;
    target = std::clamp(target, -speed, speed);
    const Vec2 t = perpendicular(n);
    const double sideways = std::sqrt(std::max(0.0, speed * speed - target * target));
    const Vec2 turned = n * target + t * std::copysign(sideways, dot(ball.velocity, t));
    const double angle = portable::atan2(cross(ball.velocity, turned), dot(ball.velocity, turned));
    const double c = portable::cos(angle), s = portable::sin(angle);
    const Vec2 w = planar(ball.angular_velocity);
    ball.velocity = turned;
    ball.angular_velocity.x = c * w.x - s * w.y;
    ball.angular_velocity.y = s * w.x + c * w.y;
}

// After a push two balls rolling in different directions are still pressed together by their
// rolling resistance, and would meet again and again. They part at `push_parting_speed`, the
// parting taken from their sideways motion by turning it, which costs no energy.
void part_pushed_balls(Ball& a, Ball& b, Vec2 n) {
    const double needed = push_parting_speed - dot(b.velocity - a.velocity, n);
    if (needed <= 0)
        return;
    const double room_b = length(b.velocity) - dot(b.velocity, n);
    const double room_a = length(a.velocity) + dot(a.velocity, n);
    double share_b = std::min(needed / 2, room_b);
    const double share_a = std::min(needed - share_b, room_a);
    share_b = std::min(needed - share_a, room_b);
    turn_towards(b, n, dot(b.velocity, n) + share_b);
    turn_towards(a, n, dot(a.velocity, n) - share_a);
}

// The mirror image of the ball's motion in the cushion's plane (normal n): the velocity, a
// polar vector, loses twice its part along n; the spin, an axial vector, keeps its part along n
// and reverses the rest. A rolling ball stays rolling, along the mirror line, and side spin
// turns the other way, as in a mirror.
void mirror_in_cushion(Ball& ball, Vec2 n, double approach) {
    ball.velocity -= n * (2 * approach);
    const Vec3 axis = lift(n);
    ball.angular_velocity = axis * (2 * dot(ball.angular_velocity, axis)) - ball.angular_velocity;
}

// Stronge's compliant impact (compliant_impact.hpp) at the cushion nose, where the physical
// model puts its impulse: the contact point's velocity splits into the closing speed along the
// line to the centre and a slip across it, whose direction the impact keeps (the springs and
// friction all act along it); the impulses that give the contact point its velocity at
// separation are applied to the ball, the vertical part of the velocity change taken by the
// cloth as in the physical model. A nose that meets no closing speed (one at the very top of
// the ball, or one closing too slowly to divide by) reflects the velocity, as the ideal model
// does.
void resolve_stronge_cushion(Ball& ball, Vec2 towards, double approach, const PhysicsParams& p) {
    const double R = p.ball_radius;
    const double m = ball.mass;
    const double sin_theta = std::clamp(2 * p.cushion_height_ratio - 1, -1.0, 1.0);
    const double cos_theta = std::sqrt(1 - sin_theta * sin_theta);
    const Vec3 arm = lift(towards * (R * cos_theta), R * sin_theta); // centre to contact
    const Vec3 push = arm * (-1.0 / R); // the cushion's normal, into the ball
    const Vec3 contact_velocity = lift(ball.velocity) + cross(ball.angular_velocity, arm);
    const double closing = -dot(contact_velocity, push);
    const Vec3 slip = contact_velocity + push * closing; // the part across the normal
    const double slip_speed = std::sqrt(dot(slip, slip));
    // So slow a closing that the slip over it is no number (a grazing touch at a subnormal
    // speed) reflects as well.
    if (!(closing > 0) || !std::isfinite(slip_speed / closing)) {
        ball.velocity -= towards * (2 * approach);
        return;
    }
    // A solid ball's contact point moves by P / m under a normal impulse P and by 3.5 P / m
    // under a tangential one.
    constexpr double inertia_ratio = 3.5;
    const CompliantImpact end =
        compliant_impact(slip_speed / closing, p.cushion_friction, p.cushion_restitution,
                         p.cushion_frequency_ratio, inertia_ratio);
    Vec3 impulse = push * (m * (1 + end.normal) * closing);
    if (slip_speed > 0)
        impulse +=
            slip * (m / inertia_ratio * (end.tangential * closing - slip_speed) / slip_speed);
    ball.velocity += planar(impulse) * (1.0 / m);
    ball.angular_velocity += cross(arm, impulse) * (1.0 / moment_of_inertia(m, R));
}

bool pressed_together(const Ball& a, const Ball& b, Vec2 n, const PhysicsParams& p) {
    return dot(physical_acceleration(a, p) - physical_acceleration(b, p), n) > 0;
}

} // namespace

void resolve_ball_ball(Ball& a, Ball& b, const PhysicsParams& p, const ClothModel& cloth) {
    const Vec2 n = normalized(b.position - a.position);
    const double approach = dot(a.velocity - b.velocity, n);
    const double inv_a = 1.0 / a.mass, inv_b = 1.0 / b.mass;
    const bool ideal = p.collision == CollisionModel::ideal;

    if (approach > 0) {
        const double e = ideal ? 1.0 : effective_restitution(p.ball_restitution, approach, p);
        const double normal_impulse = (1 + e) * approach / (inv_a + inv_b);
        a.velocity -= n * (normal_impulse * inv_a);
        b.velocity += n * (normal_impulse * inv_b);

        if (!ideal)
            apply_ball_friction(a, b, n, normal_impulse, p);
    }
    if (approach < p.elastic_below_speed)
        cloth.slow_pair_contact(a, b, n, p);
    if (dot(b.velocity - a.velocity, n) < min_separation_speed) {
        const double mass = a.mass + b.mass;
        const double reduced = a.mass * b.mass / mass;
        double deficit = 0;
        const Vec2 w = turned_to_part(b.velocity - a.velocity, n, deficit);
        const Vec2 common = paid_from((a.velocity * a.mass + b.velocity * b.mass) * (1 / mass),
                                      mass, 0.5 * reduced * deficit);
        a.velocity = common - w * (b.mass / mass);
        b.velocity = common + w * (a.mass / mass);
    }
    cloth.settle_motion_state(a, p);
    cloth.settle_motion_state(b, p);
}

void resolve_cushion(Ball& ball, Vec2 towards, const PhysicsParams& p, const ClothModel& cloth) {
    const double R = p.ball_radius;
    const double m = ball.mass;
    const double approach = dot(ball.velocity, towards);
    const bool slow = approach < p.elastic_below_speed;

    if (approach > 0 && p.cushion == CushionModel::mirror) {
        mirror_in_cushion(ball, towards, approach);
    } else if (approach > 0 && p.cushion == CushionModel::stronge && !slow) {
        resolve_stronge_cushion(ball, towards, approach, p);
    } else if (approach > 0 && (p.cushion == CushionModel::ideal || slow)) {
        ball.velocity -= towards * (2 * approach);
    } else if (approach > 0) {
        // The cushion nose touches the ball above its equator, at angle theta.
        const double sin_theta = std::clamp(2 * p.cushion_height_ratio - 1, -1.0, 1.0);
        const double cos_theta = std::sqrt(1 - sin_theta * sin_theta);
        const Vec3 arm = lift(towards * (R * cos_theta), R * sin_theta); // centre to contact
        const Vec3 push = arm * (-1.0 / R); // direction of the cushion's push on the ball
        const Vec3 contact_velocity = lift(ball.velocity) + cross(ball.angular_velocity, arm);
        const double closing = -dot(contact_velocity, push);
        const double normal_impulse = (1 + p.cushion_restitution) * m * closing;
        Vec3 slip = contact_velocity - push * dot(contact_velocity, push);
        const Vec3 impulse = push * normal_impulse +
                             friction_impulse(slip, normal_impulse, p.cushion_friction, 3.5 / m);
        ball.velocity += planar(impulse) * (1.0 / m);
        ball.angular_velocity += cross(arm, impulse) * (1.0 / moment_of_inertia(m, R));
    }

    if (slow)
        cloth.slow_cushion_contact(ball, towards, p);

    if (-dot(ball.velocity, towards) < min_separation_speed) {
        double deficit = 0; // a cushion has no motion to pay from: at most 1/2 m s_min^2 added
        ball.velocity = turned_to_part(ball.velocity, towards * -1.0, deficit);
    }
    cloth.settle_motion_state(ball, p);
}

void resolve_physical_push(Ball& a, Ball& b, Vec2 n, const PhysicsParams& p) {
    physical_settle_motion_state(a, p);
    physical_settle_motion_state(b, p);
    if (pressed_together(a, b, n, p)) {
        resolve_push(a, b, n, p);
        physical_settle_motion_state(a, p);
        physical_settle_motion_state(b, p);
        if (pressed_together(a, b, n, p))
            part_pushed_balls(a, b, n);
    }
}

// A slow contact with spin that drives the ball back into the cushion would repeat without end;
// the cloth's friction takes out that part of the slip at once (this only removes energy).
void resolve_physical_slow_cushion(Ball& ball, Vec2 towards, const PhysicsParams& p) {
    const double R = p.ball_radius;
    const double m = ball.mass;
    const Vec2 slip = slip_velocity(ball, R);
    const double pressing = dot(slip, towards);
    if (pressing < 0) {
        const Vec2 impulse = towards * (-2.0 * m / 7.0 * pressing);
        ball.velocity += impulse * (1.0 / m);
        const Vec3 torque = cross(Vec3{0, 0, -R}, lift(impulse));
        ball.angular_velocity += torque * (1.0 / moment_of_inertia(m, R));
    }
    const double still_approaching = dot(ball.velocity, towards);
    if (still_approaching > 0)
        ball.velocity -= towards * (2 * still_approaching);
}

// A classic cloth slows each ball straight back along its way, so two moving balls that touch
// slowly while heading different ways (or one decaying faster than the other's constant A) can be
// driven into each other again at once, and again, ever more often: a cluster that never ends.
// As in the physical model they are pushed instead: first to one speed along the line of centres
// (momentum kept, energy only lost), then, if the cloth still presses them together, parted by
// turning their motion (which costs no energy).
void resolve_classic_push(Ball& a, Ball& b, Vec2 n, const PhysicsParams& p, const ClassicLaw& law) {
    for (Ball* ball : {&a, &b}) {
        if (length(ball->velocity) <= p.friction.rest_speed)
            ball->velocity = {}; // it stops here (settle_motion_state): it presses nothing
    }
    // A ball that stands is never driven back into one that leaves it along a straight line.
    auto pressed = [&] {
        return length(a.velocity) > 0 && length(b.velocity) > 0 &&
               dot(classic_acceleration(a.velocity, law) - classic_acceleration(b.velocity, law),
                   n) > 0;
    };
    if (!pressed())
        return;
    const double common =
        (a.mass * dot(a.velocity, n) + b.mass * dot(b.velocity, n)) / (a.mass + b.mass);
    a.velocity += n * (common - dot(a.velocity, n));
    b.velocity += n * (common - dot(b.velocity, n));
    if (pressed())
        part_pushed_balls(a, b, n);
}

} // namespace termpool::core
