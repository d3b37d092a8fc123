// The event schedule against a plain model of it: every pair's time in a matrix, candidates by
// testing every box, the earliest event by scanning everything. With few balls (every box
// tested) and with many (the grid, and long paths walked along their capsules) it must choose the
// same event after every change. And the simulator's cost per event through `termpool bench`
// rows is covered by test_simulate_cli.cpp; here, the grid never loses a pair in reach.
#include "support/random.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>

#include "core/ball_grid.hpp"
#include "core/box_lanes.hpp"
#include "core/event_schedule.hpp"
#include "core/pair_times.hpp"

using namespace termpool;
using termpool::core::Box;
using termpool::core::Capsule;
using termpool::core::EventSchedule;
using termpool::core::ScheduledEvent;

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double diameter = 0.05715;

// A ball as the model sees it: its box, its path inside the box, and whether it moves.
struct ModelBall {
    Box box;
    Capsule path;
    bool moving = false;
    int version = 0; // bumped at each change, so that the fake contact times change with it
};

// A made-up contact for pair (i, k): some none, some bounds, some exact, all a pure function of
// the two balls' versions, so that the model and the schedule get the same answers.
core::ContactEstimate fake_contact(std::size_t i, std::size_t k, int vi, int vk) {
    const std::size_t lo = std::min(i, k), hi = std::max(i, k);
    const int vlo = i < k ? vi : vk, vhi = i < k ? vk : vi;
    std::uint64_t h = lo * 1000003u + hi * 10007u + static_cast<std::uint64_t>(vlo) * 131u +
                      static_cast<std::uint64_t>(vhi) * 7u;
    h = Random(h).next();
    if (h % 4 == 0)
        return {infinity, true};
    // Coarse times, so that ties between events happen and their order is tested.
    return {static_cast<double>((h >> 8) % 16) * 0.125, h % 3 != 0};
}

bool boxes_in_reach(const Box& a, const Box& b) {
    return a.min.x - diameter <= b.max.x && b.min.x - diameter <= a.max.x &&
           a.min.y - diameter <= b.max.y && b.min.y - diameter <= a.max.y;
}

// Whether pair (i, k) can touch: boxes in reach, one of them moving, and the paths within a
// diameter (the capsules hold the paths; the model keeps them whole, as boxes' diagonals).
bool in_reach(const ModelBall& a, const ModelBall& b) {
    return (a.moving || b.moving) && boxes_in_reach(a.box, b.box);
}

struct Model {
    std::vector<ModelBall> balls;
    std::map<std::pair<std::size_t, std::size_t>, double> pair_time;
    std::vector<double> table_time;

    double time(std::size_t i, std::size_t k) const {
        const auto it = pair_time.find({std::min(i, k), std::max(i, k)});
        return it == pair_time.end() ? infinity : it->second;
    }
    void set(std::size_t i, std::size_t k, double t) {
        pair_time[{std::min(i, k), std::max(i, k)}] = t;
    }
    void refresh(std::size_t i, std::size_t done, double now) {
        for (std::size_t k = 0; k < balls.size(); ++k) {
            if (k == i || k == done)
                continue;
            double t = infinity;
            if (in_reach(balls[i], balls[k]))
                t = now + fake_contact(i, k, balls[i].version, balls[k].version).time;
            set(i, k, t);
        }
    }
    ScheduledEvent earliest() const {
        ScheduledEvent first{infinity, 0};
        for (std::size_t i = 0; i < balls.size(); ++i) {
            const ScheduledEvent e = ScheduledEvent::table(table_time[i], i);
            if (e.time < infinity && e < first)
                first = e;
        }
        for (const auto& [pair, t] : pair_time) {
            const ScheduledEvent e = ScheduledEvent::pair(t, pair.first, pair.second);
            if (t < infinity && e < first)
                first = e;
        }
        return first;
    }
};

// A box and a capsule along its diagonal covering it: at rest a point, moving a stretch of up to
// `longest` metres (so that some boxes are long enough to be walked along their paths).
void place(Random& rng, ModelBall& b, double table_size, double longest) {
    const Vec2 from{rng.uniform(0, table_size), rng.uniform(0, table_size)};
    Vec2 to = from;
    if (b.moving) {
        const double length =
            rng.uniform(0, 1) < 0.3 ? rng.uniform(0, longest) : rng.uniform(0, 0.1);
        const double angle = rng.uniform(0, 6.283185307179586);
        to = from + Vec2{length * std::cos(angle), length * std::sin(angle)};
    }
    b.box = core::box_of(from, to);
    // A bulge that covers the whole box: the model tests boxes only.
    b.path = {from, to, std::max(b.box.max.x - b.box.min.x, b.box.max.y - b.box.min.y)};
}

void check_against_model(std::size_t count, double table_size, std::uint64_t seed) {
    Random rng(seed);
    EventSchedule schedule(count, diameter);
    if (count == 0) { // nothing to change: nothing is ever scheduled
        CHECK_FALSE(schedule.earliest().time < infinity);
        return;
    }
    Model model;
    model.balls.resize(count);
    model.table_time.assign(count, infinity);
    double now = 0;
    auto contact_for = [&](std::size_t i) {
        return [&, i](std::size_t k) {
            return fake_contact(i, k, model.balls[i].version, model.balls[k].version);
        };
    };
    for (std::size_t i = 0; i < count; ++i) {
        model.balls[i].moving = rng.uniform(0, 1) < 0.5;
        place(rng, model.balls[i], table_size, table_size);
        schedule.set_reach(i, model.balls[i].box, model.balls[i].path);
        schedule.set_moving(i, model.balls[i].moving);
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (model.balls[i].moving) {
            schedule.refresh(i, i, now, contact_for(i));
            model.refresh(i, i, now);
        }
    }
    for (int step = 0; step < 1500; ++step) {
        const ScheduledEvent got = schedule.earliest();
        const ScheduledEvent want = model.earliest();
        INFO("balls " << count << ", seed " << seed << ", step " << step);
        REQUIRE(got.time == want.time);
        REQUIRE(got.order == want.order);
        // A change like the world's: one or two balls take new pieces (new boxes, a new table
        // event) and their pairs are searched again; or a bound is made exact.
        now += 0.01;
        if (got.time < infinity && got.is_pair() && rng.uniform(0, 1) < 0.2) {
            const double exact = got.time + rng.uniform(0, 0.5);
            const double t = rng.uniform(0, 1) < 0.3 ? infinity : exact;
            schedule.set_exact(got.i(), got.j(), t);
            model.set(got.i(), got.j(), t);
            continue;
        }
        const std::size_t a = rng.below(count);
        const std::size_t b = rng.uniform(0, 1) < 0.5 ? a : rng.below(count);
        for (const std::size_t i : {a, b}) {
            ModelBall& ball = model.balls[i];
            ++ball.version;
            ball.moving = rng.uniform(0, 1) < 0.6;
            if (rng.uniform(0, 1) < 0.05) {
                ball.box = core::empty_box(); // pocketed
                ball.moving = false;
                ball.path = {};
            } else {
                place(rng, ball, table_size, table_size);
            }
            model.table_time[i] = rng.uniform(0, 1) < 0.3 ? infinity : now + rng.uniform(0, 2);
            schedule.set_reach(i, ball.box, ball.path);
            schedule.set_moving(i, ball.moving);
            schedule.set_table_time(i, model.table_time[i]);
        }
        schedule.refresh(a, a, now, contact_for(a));
        model.refresh(a, a, now);
        if (b != a) {
            schedule.refresh(b, a, now, contact_for(b));
            model.refresh(b, a, now);
        }
    }
}

// A coordinate of a box corner for the box tests: mostly anywhere in [-spread, spread], some on
// a grid of `step` (so that edges meet exactly, and on the strips' boundaries), some NaN,
// infinite, or far beyond any table.
double box_coordinate(Random& rng, double spread, double step) {
    const double kind = rng.uniform(0, 1);
    return kind < 0.02   ? std::numeric_limits<double>::quiet_NaN()
           : kind < 0.04 ? infinity
           : kind < 0.06 ? -infinity
           : kind < 0.08 ? rng.uniform(-1e12, 1e12)
           : kind < 0.25 ? std::round(rng.uniform(-spread, spread) / step) * step
                         : rng.uniform(-spread, spread);
}

} // namespace

TEST_CASE("event schedule: the earliest event as a plain scan finds it", "[core][schedule]") {
    // Up to 128 balls test every box (four at a time with AVX2; without, 33 to 128 go through
    // the strips), more go through the grid; the tournament's leaves are a power of two (0 and 1
    // ball, 32, 64 and 128 fill them). The strips have a test of their own below.
    for (const std::size_t count : {0, 1, 2, 16, 32, 33, 40, 64, 65, 100, 128, 129, 200}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            // Room per ball as on a pool table, so that boxes meet often but not always.
            const double table_size = 0.45 * std::sqrt(static_cast<double>(count));
            check_against_model(count, table_size, seed * 7919 + count);
        }
    }
}

TEST_CASE("ball grid: a long path's search finds every ball within reach of it",
          "[core][schedule]") {
    // Balls at rest scattered over 10 m; one long path across; every ball whose centre comes
    // within a diameter of the path must be visited.
    Random rng(17);
    constexpr std::size_t count = 400;
    const double margin = 0.5 * diameter * (1 + 1e-6) + 1e-9;
    core::BallGrid grid(count + 1, 4 * diameter, margin);
    std::vector<Box> boxes(count + 1);
    for (std::size_t k = 0; k < count; ++k) {
        const Vec2 p{rng.uniform(0, 10), rng.uniform(0, 10)};
        boxes[k] = {p, p};
        grid.moved(k);
    }
    for (int trial = 0; trial < 200; ++trial) {
        const Vec2 from{rng.uniform(0, 10), rng.uniform(0, 10)};
        const Vec2 to{rng.uniform(0, 10), rng.uniform(0, 10)};
        const double bulge = rng.uniform(0, 1) < 0.5 ? 0 : rng.uniform(0, 0.2);
        // The box of a parabola's chord with its bulge: it holds the path.
        Box box = core::box_of(from, to);
        box.min = box.min - Vec2{bulge, bulge};
        box.max = box.max + Vec2{bulge, bulge};
        boxes[count] = box;
        grid.moved(count);
        std::vector<int> visited(count + 1, 0);
        const Vec2 lo = box.min - Vec2{diameter, diameter}, hi = box.max + Vec2{diameter, diameter};
        for (const std::size_t k : grid.near(count, boxes, Capsule{from, to, bulge}, lo, hi)) {
            ++visited[k];
            // Only boxes that overlap the searched one.
            REQUIRE(core::boxes_within(boxes[k], Box{lo, hi}, 0));
        }
        REQUIRE(visited[count] == 0);                                    // never the ball itself
        REQUIRE(*std::max_element(visited.begin(), visited.end()) <= 1); // each ball once
        const Vec2 d = to - from;
        for (std::size_t k = 0; k < count; ++k) {
            const Vec2 p = boxes[k].min;
            const double s = std::clamp(dot(p - from, d) / dot(d, d), 0.0, 1.0);
            if (length(p - (from + d * s)) <= diameter + bulge) {
                INFO("trial " << trial << ", ball " << k);
                REQUIRE(visited[k]);
            }
        }
    }
}

TEST_CASE("event schedule: a ball size no strip or cell can be sized by tests every box",
          "[core][schedule]") {
    // A zero, negative, subnormal or NaN diameter (World does not refuse one) would make strip
    // and cell indices NaN or run backwards: the schedule tests every box instead, and a search
    // asks for exactly the pairs whose boxes come within a diameter, at every ball count.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double size : {0.0, -0.05, 1e-320, nan}) {
        for (const std::size_t count : {40, 200}) {
            EventSchedule schedule(count, size);
            Random rng(count);
            std::vector<Box> boxes(count);
            for (std::size_t k = 0; k < count; ++k) {
                const Vec2 at{rng.uniform(0, 2), rng.uniform(0, 1)};
                boxes[k] = Box{at, at + Vec2{rng.uniform(0, 0.3), rng.uniform(0, 0.3)}};
                schedule.set_reach(k, boxes[k], Capsule{boxes[k].min, boxes[k].max, 0});
                schedule.set_moving(k, true);
            }
            std::vector<std::size_t> asked;
            schedule.refresh(0, 0, 0, [&](std::size_t k) {
                asked.push_back(k);
                return core::ContactEstimate{infinity, true};
            });
            std::vector<std::size_t> want;
            for (std::size_t k = 1; k < count; ++k)
                if (core::boxes_within(boxes[0], boxes[k], size))
                    want.push_back(k);
            INFO("diameter " << size << ", " << count << " balls");
            CHECK(asked == want);
        }
    }
}

TEST_CASE("event schedule: more balls than its indices hold are refused", "[core][schedule]") {
    CHECK_THROWS_AS(EventSchedule(ScheduledEvent::max_balls + 1, diameter), std::length_error);
}

TEST_CASE("ball grid: a search finds exactly the boxes in reach as boxes move, grow and go",
          "[core][schedule]") {
    // Boxes of every size (a ball at rest, a rolling one, a long path on the wide list, a
    // pocketed one) moved at random; after each change a ball's search is checked against every
    // box, for a ball whose box is short (its cells are walked whole).
    Random rng(29);
    constexpr std::size_t count = 300;
    const double margin = 0.5 * diameter * (1 + 1e-6) + 1e-9;
    core::BallGrid grid(count, 4 * diameter, margin);
    std::vector<Box> boxes(count, core::empty_box());
    auto random_box = [&] {
        const double kind = rng.uniform(0, 1);
        if (kind < 0.05)
            return core::empty_box();
        const Vec2 p{rng.uniform(0, 3), rng.uniform(0, 1.5)};
        const double size = kind < 0.6 ? 0 : kind < 0.95 ? rng.uniform(0, 0.3) : rng.uniform(0, 2);
        return core::box_of(p, p + Vec2{rng.uniform(-size, size), rng.uniform(-size, size)});
    };
    for (std::size_t k = 0; k < count; ++k) {
        boxes[k] = random_box();
        grid.moved(k);
    }
    int checked = 0;
    for (int change = 0; change < 3000; ++change) {
        const auto k = static_cast<std::size_t>(rng.uniform(0, count - 1e-9));
        // Often a small move that keeps the cells (the copies in the buckets change in place).
        if (rng.uniform(0, 1) < 0.5 && boxes[k].min.x <= boxes[k].max.x) {
            const Vec2 step{rng.uniform(-1e-3, 1e-3), rng.uniform(-1e-3, 1e-3)};
            boxes[k] = {boxes[k].min + step, boxes[k].max + step};
        } else {
            boxes[k] = random_box();
        }
        grid.moved(k);
        const auto i = static_cast<std::size_t>(rng.uniform(0, count - 1e-9));
        const Box& box = boxes[i];
        if (!(box.min.x <= box.max.x) || box.max.x - box.min.x > 0.3 || box.max.y - box.min.y > 0.3)
            continue;
        const Vec2 lo = box.min - Vec2{diameter, diameter}, hi = box.max + Vec2{diameter, diameter};
        std::vector<int> found(count, 0);
        for (const std::size_t near : grid.near(i, boxes, Capsule{}, lo, hi))
            ++found[near];
        for (std::size_t other = 0; other < count; ++other) {
            const bool in_reach = other != i && core::boxes_within(boxes[other], Box{lo, hi}, 0);
            INFO("change " << change << ", ball " << i << " and " << other);
            REQUIRE(found[other] == (in_reach ? 1 : 0));
        }
        ++checked;
    }
    CHECK(checked > 1000);
}

TEST_CASE("box lanes: two or four at a time, the same answer as one box at a time",
          "[core][schedule]") {
    // Every count from 0 to 140 (odd tails, more than a word), boxes that touch the searched one
    // exactly at an edge, empty ones, infinite and NaN coordinates. Both ways of testing the
    // boxes, where the processor has the second (AVX2): the bench's machines do.
    Random rng(31);
    if (!core::BoxColumns{}.has_four_lanes())
        WARN("this processor has no AVX2: only the two-lane test is checked (the one it uses)");
    auto coordinate = [&] { return box_coordinate(rng, 2, 1); };
    for (std::size_t count = 0; count <= 140; ++count) {
        core::BoxColumns columns;
        std::vector<Box> boxes;
        for (std::size_t c = 0; c < count; ++c) {
            const Box box = rng.uniform(0, 1) < 0.1
                                ? core::empty_box()
                                : Box{{coordinate(), coordinate()}, {coordinate(), coordinate()}};
            columns.push_back(box);
            boxes.push_back(box);
        }
        for (int query = 0; query < 20; ++query) {
            const Vec2 lo{std::round(rng.uniform(-2, 1)), rng.uniform(-2, 1)};
            const Vec2 hi = lo + Vec2{std::round(rng.uniform(0, 2)), rng.uniform(0, 2)};
            for (std::size_t first = 0; first < count; first += 64) {
                std::vector<std::uint64_t> answers = {columns.overlapping(first, lo, hi),
                                                      columns.overlapping_two_lanes(first, lo, hi)};
#if defined(__x86_64__) && defined(__GNUC__)
                if (columns.has_four_lanes())
                    answers.push_back(columns.overlapping_four_lanes(first, lo, hi));
#endif
                for (const std::uint64_t bits : answers) {
                    for (std::size_t c = first; c < std::min(count, first + 64); ++c) {
                        const Box& b = boxes[c];
                        const bool one = lo.x <= b.max.x && b.min.x <= hi.x && lo.y <= b.max.y &&
                                         b.min.y <= hi.y;
                        INFO("count " << count << ", box " << c);
                        REQUIRE(((bits >> (c - first)) & 1) == (one ? 1u : 0u));
                    }
                    if (std::min(count, first + 64) - first < 64) // nothing beyond
                        REQUIRE(bits >> (std::min(count, first + 64) - first) == 0);
                }
            }
        }
    }
}

TEST_CASE("box lanes: picked by strips, the same balls as every box tested", "[core][schedule]") {
    // Above BoxLanes::strips_above balls the strips pick the boxes to test: as boxes move, grow,
    // go and come back, and after the lanes are cleared and the same boxes entered again, a
    // search finds exactly the boxes that overlap it, whether its box is in order, reversed,
    // far beyond 64 strips, infinite or NaN. Strips are 0.25 wide: corners on a grid of 0.25
    // meet exactly on strip boundaries, and a spread of 3 or 20 gives spans of a few strips to
    // more than 64 (which wrap).
    Random rng(47);
    auto coordinate = [&] { return box_coordinate(rng, rng.uniform(0, 1) < 0.7 ? 3 : 20, 0.25); };
    auto some_box = [&] {
        const double kind = rng.uniform(0, 1);
        if (kind < 0.1)
            return core::empty_box();
        if (kind < 0.4) { // a ball at rest: a point
            const Vec2 at{coordinate(), coordinate()};
            return Box{at, at};
        }
        Vec2 lo{coordinate(), coordinate()};
        Vec2 hi{coordinate(), coordinate()};
        if (rng.uniform(0, 1) < 0.9) // mostly in order, sometimes reversed
            lo = {std::min(lo.x, hi.x), std::min(lo.y, hi.y)},
            hi = {std::max(lo.x, hi.x), std::max(lo.y, hi.y)};
        return Box{lo, hi};
    };
    std::size_t found = 0;
    for (const std::size_t balls : {33, 64, 65, 100, 128}) {
        REQUIRE(balls > core::BoxLanes::strips_above);
        core::BoxLanes lanes(balls, 0.25);
        std::vector<Box> boxes(balls, core::empty_box());
        std::vector<bool> moving(balls, false);
        for (int round = 0; round < 200; ++round) {
            for (int change = 0; change < 10; ++change) {
                const auto k = static_cast<std::size_t>(rng.uniform(0, 1) * balls) % balls;
                boxes[k] = some_box();
                lanes.set_box(k, boxes[k]);
                moving[k] = rng.uniform(0, 1) < 0.5;
                lanes.set_moving(k, moving[k]);
            }
            if (round == 100) { // cleared, then every box entered again
                lanes.clear();
                for (std::size_t k = 0; k < balls; ++k) {
                    lanes.set_box(k, boxes[k]);
                    lanes.set_moving(k, moving[k]);
                }
            }
            const Box query = some_box();
            const core::BoxLanes::Search search = lanes.search(query.min, query.max);
            // The strips pick the boxes exactly when the search box is finite.
            CHECK(search.by_strips == (std::isfinite(query.min.x) && std::isfinite(query.min.y) &&
                                       std::isfinite(query.max.x) && std::isfinite(query.max.y)));
            const bool needs_motion = rng.uniform(0, 1) < 0.3;
            for (std::size_t first = 0; first < balls; first += 64) {
                const std::uint64_t bits = lanes.overlapping(first, search, needs_motion);
                for (std::size_t c = first; c < std::min(balls, first + 64); ++c) {
                    const Box& b = boxes[c];
                    const bool one = query.min.x <= b.max.x && b.min.x <= query.max.x &&
                                     query.min.y <= b.max.y && b.min.y <= query.max.y &&
                                     (!needs_motion || moving[c]);
                    INFO(balls << " balls, round " << round << ", box " << c);
                    REQUIRE(((bits >> (c - first)) & 1) == (one ? 1u : 0u));
                    found += one ? 1 : 0;
                }
            }
        }
    }
    CHECK(found > 1000); // the searches found boxes, not only nothing
}

TEST_CASE("box lanes: the padding beyond the last ball is never in reach", "[core][schedule]") {
    // Even for a search box that reaches everywhere: the padding's empty boxes are (+inf, -inf),
    // which an infinite search box would take in.
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (const std::size_t balls : {1, 7, 63, 64, 65, 70, 128}) {
        core::BoxLanes lanes(balls, 0.1);
        for (std::size_t k = 0; k < balls; ++k) {
            lanes.set_box(k, Box{{0, 0}, {1, 1}});
            lanes.set_moving(k, k % 2 == 0);
        }
        for (std::size_t first = 0; first < balls; first += 64) {
            const std::size_t in_word = std::min<std::size_t>(64, balls - first);
            const std::uint64_t all =
                in_word == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << in_word) - 1;
            INFO(balls << " balls, word from " << first);
            const core::BoxLanes::Search everywhere = lanes.search({-inf, -inf}, {inf, inf});
            CHECK(lanes.overlapping(first, everywhere, false) == all);
            CHECK(lanes.overlapping(first, everywhere, true) == (all & 0x5555555555555555));
        }
    }
}

TEST_CASE("pair times: a copy holds exactly the other's pairs, whatever it held before",
          "[core][schedule]") {
    Random rng(31);
    for (const std::size_t n : {1u, 16u, 65u}) {
        // Random finite and infinite times, some bounds, in a source and in the target it is
        // copied into (of the same size: the sparse copy; and of another size).
        auto fill = [&](core::PairTimes& pairs, std::size_t size) {
            for (int k = 0; k < 200; ++k) {
                const std::size_t i = rng.below(size), j = rng.below(size);
                const double roll = rng.uniform();
                pairs.set(i, j, roll < 0.3 ? infinity : roll < 0.35 ? std::nan("") : roll);
                pairs.set_bound(i, j, rng.uniform() < 0.5);
            }
            pairs.set(0, size - 1, 0.5); // one finite pair at least
        };
        // Both filled, and either with every time +infinity (a world at rest: the copy's
        // shortcuts), the other filled.
        for (const auto& [fill_source, fill_target] :
             {std::pair{true, true}, std::pair{false, true}, std::pair{true, false}}) {
            core::PairTimes source(n);
            if (fill_source)
                fill(source, n);
            CHECK(source.any_finite() == fill_source);
            for (const std::size_t target_size : {n, n + 3}) {
                core::PairTimes target(target_size);
                if (fill_target)
                    fill(target, target_size);
                CHECK(target.any_finite() == fill_target);
                target = source;
                CHECK(target.any_finite() == fill_source);
                INFO(n << " balls into " << target_size << ", filled " << fill_source
                       << fill_target);
                for (std::size_t i = 0; i < n; ++i) {
                    std::vector<std::size_t> want, got;
                    source.visit_finite(i, [&](std::size_t k) { want.push_back(k); });
                    target.visit_finite(i, [&](std::size_t k) { got.push_back(k); });
                    CHECK(got == want);
                    for (std::size_t k = 0; k < n; ++k) {
                        CHECK(target.row(i)[k] == source.row(i)[k]);
                        CHECK(target.row(i)[k] == target.row(k)[i]);
                        if (source.row(i)[k] < infinity)
                            CHECK(target.is_bound(i, k) == source.is_bound(i, k));
                        else
                            CHECK(source.row(i)[k] == infinity); // set() keeps a NaN as nothing
                    }
                }
            }
        }
    }
}
