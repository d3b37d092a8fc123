// clearly_apart: the test by which a pair's bound, or a jaw point, is taken for no contact
// without the quartic's search. It must never say "apart" where first_contact_time finds a
// contact (the simulation's bits rest on that), and it must say so for most near misses of a
// ball rolling past another at rest, which is what it is for.
#include "support/portable_math.hpp"
#include "support/random.hpp"
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/contact_time.hpp"
#include "core/motion_piece.hpp"
#include "core/pair_contacts.hpp"

using termpool::Vec2;
using termpool::core::clearly_apart;
using termpool::core::first_contact_estimate;
using termpool::core::first_contact_time;
using termpool::core::pair_gap;
using termpool::core::Path;

namespace {

constexpr double R = 0.028575;
constexpr double infinity = std::numeric_limits<double>::infinity();

// Random pairs of paths over random horizons: a ball rolling or sliding past another at rest or
// moving, most passing within a few millimetres of `distance` (a diameter for two balls, a
// radius for a ball and a jaw point).
struct Case {
    Path a, b;
    double horizon;
};

// clearly_apart with the size of a's coordinates for its `place`.
bool told_apart(const Path& a, const Path& b, double distance, double horizon) {
    return clearly_apart(a, b, distance, horizon, std::abs(a.position.x) + std::abs(a.position.y));
}

// A piece of motion whose path from time 0 is `path`.
termpool::core::MotionPiece piece_of(const Path& path) {
    termpool::core::MotionPiece piece;
    piece.ball.position = path.position;
    piece.ball.velocity = path.velocity;
    piece.ball.state = termpool::MotionState::sliding;
    piece.acceleration = path.acceleration;
    return piece;
}

class Cases {
public:
    explicit Cases(double distance) : distance_(distance) {}
    Case next() {
        const Vec2 u = direction();
        const Vec2 side{-u.y, u.x};
        const double speed = log_uniform(0.01, 8);
        const double deceleration = log_uniform(0.05, 5);
        // Passing at a sideways distance from 2 mm less than `distance` to 5 mm more, from up
        // to a metre before the other ball.
        const double offset = distance_ + uniform(-0.002, 0.005);
        const double before = uniform(0, 1);
        Path a{{0, 0}, u * speed, {}, 0};
        const auto kind = random_.below(4);
        if (kind == 0) {
            a.acceleration = u * -deceleration; // rolling: along its velocity
        } else if (kind == 1) {
            a.acceleration = direction() * deceleration; // sliding: any way
        } else {
            // Rolling with the rounding of a computed direction.
            a.acceleration = u * -deceleration + side * (deceleration * uniform(-1e-15, 1e-15));
        }
        Path b{u * before + side * (uniform(0, 1) < 0.5 ? offset : -offset), {}, {}, 0};
        // Somewhere on a 9 ft table (the test's margin grows with the coordinates).
        const Vec2 at{uniform(0, 2.54), uniform(0, 1.27)};
        a.position = a.position + at;
        b.position = b.position + at;
        if (kind == 3) {
            const Vec2 w = direction();
            b.velocity = w * log_uniform(0.01, 3);
            b.acceleration = w * -log_uniform(0.05, 5);
        }
        // Up to the moving ball's stop, or beyond it (a pair's horizon is never beyond, and the
        // test must hold for any).
        const double stop = speed / deceleration;
        const double horizon =
            uniform(0, 1) < 0.8 ? stop * uniform(0.01, 1) : log_uniform(1e-6, 50);
        return {a, b, horizon};
    }

private:
    double uniform(double lo, double hi) { return random_.uniform(lo, hi); }
    double log_uniform(double lo, double hi) {
        return lo * termpool::portable::exp(termpool::portable::log(hi / lo) * uniform(0, 1));
    }
    Vec2 direction() {
        const double angle = uniform(0, 6.283185307179586);
        return {termpool::portable::cos(angle), termpool::portable::sin(angle)};
    }
    double distance_;
    termpool::Random random_{0xc1ea4a9a47ULL}; // the same cases with every standard library
};

} // namespace

TEST_CASE("clearly_apart: never where the quartic finds a contact, and most near misses",
          "[polynomial]") {
    Cases cases(2 * R);
    int contacts = 0, misses = 0, apart = 0, wrong = 0;
    for (int n = 0; n < 200000; ++n) {
        const Case c = cases.next();
        const double found = first_contact_time(pair_gap(c.a, c.b, 2 * R), c.horizon);
        const bool says_apart = told_apart(c.a, c.b, 2 * R, c.horizon);
        // The pair search's estimate: the quadratic bound's answer, or no contact in its place.
        termpool::PhysicsParams params;
        params.ball_radius = R;
        const auto with = termpool::core::physical_pair_contact(piece_of(c.a), piece_of(c.b), 0,
                                                                c.horizon, params);
        const auto without = first_contact_estimate(pair_gap(c.a, c.b, 2 * R), c.horizon);
        const bool same = with.exact == without.exact && with.time == without.time;
        const bool replaced = !without.exact && with.exact && with.time == infinity && says_apart;
        if (!same && !replaced && ++wrong <= 5)
            FAIL_CHECK("the estimate " << with.time << " against " << without.time);
        if (found < infinity) {
            ++contacts;
            if (says_apart && ++wrong <= 5)
                FAIL_CHECK("apart, but a contact at " << found << " s of " << c.horizon);
        } else {
            ++misses;
            apart += says_apart ? 1 : 0;
        }
    }
    INFO(contacts << " contacts, " << misses << " misses, " << apart << " told apart");
    CHECK(wrong == 0);
    // Both outcomes are exercised, and the test tells most misses.
    CHECK(contacts > 10000);
    CHECK(misses > 20000);
    CHECK(apart > misses / 2);
}

TEST_CASE("clearly_apart: a ball rolling past another", "[polynomial]") {
    // Rolling along x at 2 m/s, stopping in 2 s; the other ball at rest 1 m ahead.
    const Path rolling{{0, 0}, {2, 0}, {-1, 0}, 2};
    const auto past = [&](double sideways) { return Path{{1, sideways}, {}, {}, 2}; };
    CHECK(told_apart(rolling, past(2 * R + 0.001), 2 * R, 2));
    CHECK(told_apart(rolling, past(-(2 * R + 0.001)), 2 * R, 2));
    // Within the micrometres of its margin, or touching: the search decides.
    CHECK_FALSE(told_apart(rolling, past(2 * R + 1e-7), 2 * R, 2));
    CHECK_FALSE(told_apart(rolling, past(2 * R - 0.001), 2 * R, 2));
    // No relative motion, a horizon without end, or a distance that is not one: no answer.
    CHECK_FALSE(told_apart(past(1), past(0), 2 * R, 2));
    CHECK_FALSE(told_apart(rolling, past(1), 2 * R, infinity));
    CHECK_FALSE(told_apart(rolling, past(2 * R - 1e-5), -2 * R, 2));
    CHECK_FALSE(told_apart(rolling, past(1), std::nan(""), 2));
}

TEST_CASE("path_point_contact_time: a jaw point is found as the quartic finds it", "[polynomial]") {
    // The point's own answer (with clearly_apart first) against the quartic's search of the same
    // gap, for paths passing a point within a few millimetres of a radius.
    Cases cases(R);
    int found = 0;
    for (int n = 0; n < 50000; ++n) {
        const Case c = cases.next();
        const Path fixed{c.b.position, {}, {}, c.horizon};
        const double direct =
            termpool::core::path_point_contact_time(c.a, c.b.position, R, c.horizon);
        const double searched = first_contact_time(pair_gap(c.a, fixed, R), c.horizon);
        found += searched < infinity ? 1 : 0;
        if (direct != searched) {
            FAIL_CHECK("case " << n << ": " << direct << " against " << searched);
            break;
        }
    }
    CHECK(found > 1000);
}
