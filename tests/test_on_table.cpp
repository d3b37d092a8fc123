// One definition of "on the table": out of the rubber, in front of every capture line, on the
// cloth or in a pocket's mouth; and the cursor that steps over it.
#include "support/random.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <termpool/practice.hpp>
#include <termpool/table.hpp>

using namespace termpool;

namespace {

constexpr double R = 0.028575;

// The capture line's distance in front of `p` for `pocket`, m (negative behind it).
double before_capture(const Pocket& pocket, Vec2 p) {
    return dot(p - pocket.capture_point, pocket.capture_normal);
}

} // namespace

TEST_CASE("a ball on the cloth is on the table, one in a rail is not", "[table][on-table]") {
    const Table table = make_table(TableSize::nine_foot);
    CHECK(on_playing_surface(table, {1.27, 0.635}, R));
    // Frozen to a rail, and round-off from it.
    CHECK(on_playing_surface(table, {1.0, R}, R));
    CHECK(on_playing_surface(table, {1.0, R - 0.5e-9}, R));
    CHECK(on_playing_surface(table, {table.length - R, 0.6}, R));
    CHECK_FALSE(on_playing_surface(table, {1.0, R - 2e-9}, R));
    CHECK_FALSE(on_playing_surface(table, {table.length - R + 2e-9, 0.6}, R));
    CHECK_FALSE(on_playing_surface(table, {0.02, 0.5}, R));
    // Behind the rubber, off the cloth altogether, or not a number.
    CHECK_FALSE(on_playing_surface(table, {-0.05, 0.6}, R));
    CHECK_FALSE(on_playing_surface(table, {1.0, -0.5}, R));
    CHECK_FALSE(on_playing_surface(table, {5.0, 0.6}, R));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(on_playing_surface(table, {nan, 0.6}, R));
    CHECK_FALSE(on_playing_surface(table, {1.0, nan}, R));
}

TEST_CASE("rubber depth is the overlap with the nearest rail, jaw or jaw point",
          "[table][on-table]") {
    const Table table = make_table(TableSize::nine_foot);
    CHECK(rubber_depth(table, {1.0, R}, R) == Approx(0).margin(1e-15));
    CHECK(rubber_depth(table, {1.0, R - 0.001}, R) == Approx(0.001).margin(1e-12));
    CHECK(rubber_depth(table, {1.27, 0.635}, R) < -0.5);
    // Against a jaw point: the left point of side pocket 2, approached from the table.
    const Vec2 point = table.jaw_points[2 * 1 + 1];
    const Vec2 near = point + Vec2{0.6, 0.8} * (R - 0.002);
    CHECK(rubber_depth(table, near, R) == Approx(0.002).margin(1e-12));
    CHECK_FALSE(on_playing_surface(table, near, R));
}

TEST_CASE("a ball short of a pocket's capture line is on the table, one on it is not",
          "[table][on-table]") {
    for (const TableSize size :
         {TableSize::seven_foot, TableSize::eight_foot, TableSize::nine_foot}) {
        const Table table = make_table(size);
        for (const Pocket& pocket : table.pockets) {
            INFO("pocket " << pocket.number);
            // Down the pocket's axis, from the cloth to the capture line and past it.
            const Vec2 axis = -pocket.capture_normal;
            const Vec2 on_line = pocket.capture_point;
            CHECK(on_playing_surface(table, on_line - axis * 0.05, R));
            CHECK(on_playing_surface(table, on_line - axis * 1e-6, R));
            CHECK_FALSE(on_playing_surface(table, on_line, R));
            CHECK_FALSE(on_playing_surface(table, on_line + axis * 1e-6, R));
            // The last point in front of the line still counts.
            Vec2 last = on_line;
            while (before_capture(pocket, last) <= 0)
                last = last - axis * 1e-12;
            CHECK(on_playing_surface(table, last, R));
        }
    }
}

TEST_CASE("a pocket's mouth beyond the cushion noses is on the table", "[table][on-table]") {
    const Table table = make_table(TableSize::nine_foot);
    // Side pocket 2: its capture line is 0.02 m behind the noses.
    CHECK(on_playing_surface(table, {table.length / 2, -0.01}, R));
    CHECK(on_playing_surface(table, {table.length / 2, -0.0199}, R));
    CHECK_FALSE(on_playing_surface(table, {table.length / 2, -0.0201}, R));
    // Beside the mouth, behind the rail: rubber, or behind a jaw.
    CHECK_FALSE(on_playing_surface(table, {table.length / 2 + 0.1, -0.01}, R));
    CHECK_FALSE(on_playing_surface(table, {table.length / 2 + 0.06, -0.015}, R));
    // Side pocket 5 on the far rail.
    CHECK(on_playing_surface(table, {table.length / 2, table.width + 0.01}, R));
    // Corner pocket 3: where the simulator left a ball after a break (issue 13).
    CHECK(on_playing_surface(table, {2.51394579, 0.0473985812}, R));
}

TEST_CASE("every point of a pocket's mouth clear of the jaws is on the table",
          "[table][on-table]") {
    // Sample each pocket's box: a point counts exactly when it is out of the rubber, in front
    // of the capture line, and between both jaws or on the cloth.
    const Table table = make_table(TableSize::eight_foot);
    Random rng(7);
    int in_mouth = 0;
    for (const Pocket& pocket : table.pockets) {
        for (int k = 0; k < 20000; ++k) {
            const Vec2 p{rng.uniform(pocket.region_min.x, pocket.region_max.x),
                         rng.uniform(pocket.region_min.y, pocket.region_max.y)};
            bool between_jaws = true;
            for (const CushionSegment& seg : table.cushions)
                if (seg.pocket == pocket.number)
                    between_jaws = between_jaws && dot(p - seg.start, seg.normal) >= 0;
            const bool on_cloth = p.x >= 0 && p.x <= table.length && p.y >= 0 && p.y <= table.width;
            bool in_front = true;
            for (const Pocket& q : table.pockets)
                in_front = in_front && before_capture(q, p) > 0;
            const bool expected = rubber_depth(table, p, R) <= rubber_tolerance && in_front &&
                                  (on_cloth || between_jaws);
            INFO("pocket " << pocket.number << " at " << p.x << " " << p.y);
            REQUIRE(on_playing_surface(table, p, R) == expected);
            in_mouth += expected && !on_cloth;
        }
    }
    CHECK(in_mouth > 100); // the mouths beyond the noses were really sampled
}

TEST_CASE("ball in hand may go wherever the table holds a ball", "[table][on-table]") {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    const PracticeTable practice(table, params, RackType::eight_ball, 1);
    CHECK(practice.can_put(0, {table.length / 2, -0.01}));
    CHECK_FALSE(practice.can_put(0, {table.length / 2, -0.03}));
    CHECK_FALSE(practice.can_put(0, {0.01, 0.6}));
}

TEST_CASE("the cursor steps over the table and slides along a cushion", "[table][on-table]") {
    const Table table = make_table(TableSize::nine_foot);
    // Free steps on the cloth.
    CHECK(step_on_table(table, {1.0, 0.6}, {0.01, 0}, R) == Vec2{1.0 + 0.01, 0.6});
    // Into a rail: drawn back to touch it, still moving along it.
    const Vec2 slid = step_on_table(table, {1.0, R + 0.005}, {0.01, -0.01}, R);
    CHECK(slid.x == 1.0 + 0.01);
    CHECK(slid.y == R);
    // Into a side pocket's mouth, where a ball may stand, and no further than its capture line.
    const Vec2 mouth = step_on_table(table, {table.length / 2, R}, {0, -0.035}, R);
    CHECK(mouth.y == Approx(R - 0.035));
    CHECK(on_playing_surface(table, mouth, R));
    CHECK(step_on_table(table, mouth, {0, -0.02}, R).y == Approx(R));
    // A random walk never leaves the table.
    Random rng(3);
    Vec2 at{1.0, 0.6};
    for (int k = 0; k < 200000; ++k) {
        const double step = 0.02;
        const Vec2 by = rng.below(2) ? Vec2{rng.below(2) ? step : -step, 0}
                                     : Vec2{0, rng.below(2) ? 2 * step : -2 * step};
        at = step_on_table(table, at, by, R);
        REQUIRE(on_playing_surface(table, at, R));
    }
}
