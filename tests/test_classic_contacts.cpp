// The classic cloth models' exact contact solves (src/core/classic_contacts.cpp), against
// brute-force scans, and whole classic shots: the reproducers that used to end overlapped, inside
// a rail or in an endless cluster, and random shots checked after every event.
#include "support/random.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <termpool/rack.hpp>

#include "cli/scenario.hpp"
#include "core/classic_contacts.hpp"
#include "core/cloth_model.hpp"
#include "physics_helpers.hpp"

using namespace termpool;
using namespace termpool::core;
using termpool::test::ball_at;
using termpool::test::total_energy;

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double R = 0.028575;

// ---- brute force

// The first sample of `gap` (m, as a function of t) that is <= 0 while closing, on `n` steps
// over [0, horizon]: the contact lies between the sample before it and it. `closest` gets the
// smallest gap seen, so that near-grazing cases can be told apart.
struct Scan {
    double before = -1, at = infinity;
    double closest = infinity;
};

template <class Gap> Scan scan(Gap gap, double horizon, int n = 20000) {
    Scan s;
    double previous = gap(0);
    s.closest = previous;
    if (previous <= 0 && gap(1e-9 * horizon) < previous) {
        s.before = 0;
        s.at = 0;
        return s;
    }
    for (int k = 1; k <= n; ++k) {
        const double t = horizon * k / n;
        const double g = gap(t);
        s.closest = std::min(s.closest, g);
        if (g <= 0 && g < previous && s.at == infinity) {
            s.before = horizon * (k - 1) / n;
            s.at = t;
        }
        previous = g;
    }
    return s;
}

// The centre of a decaying ball, as the closed form gives it.
Vec2 decaying_at(const DecayingPath& a, double K, double t) {
    return a.position + a.velocity * ((1 - std::exp(-K * t)) / K);
}

Vec2 path_at(const Path& p, double t) {
    return p.position + p.velocity * t + p.acceleration * (0.5 * t * t);
}

// Either the scan and the solve agree on a contact (the solve between the scan's samples,
// touching there), or neither finds one; a case that only grazes (the scan's closest gap within
// `grazing` of zero) may go either way.
template <class Gap> void check_against_scan(Gap gap, double solved, double horizon) {
    const Scan s = scan(gap, horizon);
    INFO("solved " << solved << " scan " << s.before << ".." << s.at << " closest " << s.closest);
    const double grazing = 1e-6; // m
    if (std::abs(s.closest) < grazing)
        return;
    if (s.at == infinity) {
        CHECK(solved == infinity);
        return;
    }
    REQUIRE(solved < infinity);
    CHECK(solved >= s.before - 1e-12);
    CHECK(solved <= s.at + 1e-12);
    CHECK(std::abs(gap(solved)) < 1e-10);
}

Vec2 random_vec(Random& rng, double size) {
    return {rng.uniform(-size, size), rng.uniform(-size, size)};
}

// A decelerating centre: at most `speed` m/s, its parabola valid until it stops.
Path random_decelerating(Random& rng, double A, double* stop) {
    const Vec2 v = random_vec(rng, 2);
    const double speed = length(v);
    *stop = speed / A;
    return {random_vec(rng, 0.5), v, v * (-A / speed), *stop};
}

// ---- whole shots

// The law's motion as the world moves its balls.
ClassicMotion motion_of(const ClothModel& cloth, const PhysicsParams& p) {
    const FrictionModel& f = p.friction;
    ClassicLaw law;
    if (f.kind != FrictionKind::constant)
        law.decay_rate = f.decay_rate;
    if (f.kind != FrictionKind::decay)
        law.deceleration = f.deceleration;
    return {law, cloth.advance, &p};
}

double deepest_overlap(const std::vector<Ball>& balls) {
    double deepest = -infinity;
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j) {
            if (balls[i].state == MotionState::pocketed || balls[j].state == MotionState::pocketed)
                continue;
            deepest = std::max(deepest, 2 * R - length(balls[i].position - balls[j].position));
        }
    return deepest;
}

// Runs the shot, checking after every event that no ball overlaps another by more than 1e-9 m,
// every ball not pocketed is on the table (on_playing_surface), and no energy appears; returns
// the number of events.
std::size_t run_checked(const Table& table, const PhysicsParams& p, const std::vector<Ball>& balls,
                        const Strike& strike) {
    World world(table, p, balls);
    world.strike(strike);
    double energy = total_energy(world.balls(), R);
    std::size_t events = 0;
    while (const auto e = world.step()) {
        ++events;
        const std::vector<Ball> now = world.balls();
        INFO("event " << events << " at " << e->time << " " << event_kind_name(e->kind) << " "
                      << e->ball << " " << e->other);
        REQUIRE(deepest_overlap(now) < 1e-9);
        for (const Ball& b : now)
            if (b.state != MotionState::pocketed)
                REQUIRE(on_playing_surface(table, b.position, R));
        const double e_now = total_energy(now, R);
        REQUIRE(e_now <= energy + 1e-12);
        energy = e_now;
    }
    REQUIRE(world.at_rest());
    return events;
}

std::size_t run_scenario(const std::string& text) {
    const auto parsed = cli::parse_scenario(text);
    REQUIRE(std::holds_alternative<cli::Scenario>(parsed));
    const cli::Scenario& s = std::get<cli::Scenario>(parsed);
    REQUIRE(s.strike);
    return run_checked(s.table, s.setup.physics, s.balls, *s.strike);
}

} // namespace

TEST_CASE("two decaying centres touch where a scan finds them", "[physics][classic][contact]") {
    Random rng(11);
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const double K = rng.uniform(0.3, 3);
        const DecayingPath a{random_vec(rng, 0.3), random_vec(rng, 3)};
        const DecayingPath b{random_vec(rng, 0.3), random_vec(rng, 1)};
        const double horizon = rng.uniform(0.1, 3);
        const double D = 2 * R;
        if (length(a.position - b.position) < D)
            continue;
        const double solved = decaying_pair_contact_time(a, b, K, D, horizon);
        hits += solved < infinity;
        check_against_scan(
            [&](double t) { return length(decaying_at(a, K, t) - decaying_at(b, K, t)) - D; },
            solved, horizon);
    }
    CHECK(hits > 20);
}

TEST_CASE("a decaying centre meets a line where a scan finds it", "[physics][classic][contact]") {
    Random rng(12);
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const double K = rng.uniform(0.3, 3);
        const DecayingPath a{{rng.uniform(0.1, 1), rng.uniform(0.1, 1)}, random_vec(rng, 3)};
        const Vec2 normal = normalized(random_vec(rng, 1));
        const Vec2 point{0, 0};
        if (dot(a.position - point, normal) < R)
            continue;
        const double horizon = rng.uniform(0.1, 3);
        const double solved = decaying_line_contact_time(a, K, point, normal, R, horizon);
        hits += solved < infinity;
        check_against_scan([&](double t) { return dot(decaying_at(a, K, t) - point, normal) - R; },
                           solved, horizon);
    }
    CHECK(hits > 20);
}

TEST_CASE("a decaying and a decelerating centre touch where a scan finds them, in few steps",
          "[physics][classic][contact]") {
    Random rng(13);
    int hits = 0, most_steps = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const double K = rng.uniform(0.3, 3), A = rng.uniform(0.1, 2);
        const DecayingPath a{random_vec(rng, 0.3), random_vec(rng, 3)};
        double stop = 0;
        const Path b = random_decelerating(rng, A, &stop);
        const double horizon = std::min(stop, rng.uniform(0.1, 3));
        const double D = 2 * R;
        if (length(a.position - b.position) < D)
            continue;
        int steps = 0;
        const double solved = mixed_pair_contact_time(a, K, b, D, horizon, &steps);
        most_steps = std::max(most_steps, steps);
        hits += solved < infinity;
        check_against_scan(
            [&](double t) { return length(decaying_at(a, K, t) - path_at(b, t)) - D; }, solved,
            horizon);
    }
    CHECK(hits > 20);
    CHECK(most_steps < 200);
}

TEST_CASE("a near-tangent mixed pair is settled in few steps", "[physics][classic][contact]") {
    // a overtakes b on a parallel line 2R + miss beside it: the closest approach is 2R + miss.
    const double K = 1.5, A = 0.8;
    for (int k = -10; k <= 10; ++k) {
        const double miss = 1e-7 * k;
        const DecayingPath a{{-0.2, 0}, {2, 0}};
        const Path b{{0, 2 * R + miss}, {0.5, 0}, {-A, 0}, 0.5 / A};
        int steps = 0;
        const double solved = mixed_pair_contact_time(a, K, b, 2 * R, b.duration, &steps);
        INFO("miss " << miss << " steps " << steps << " solved " << solved);
        CHECK(steps < 200);
        if (k < 0) {
            REQUIRE(solved < infinity);
            CHECK(std::abs(length(decaying_at(a, K, solved) - path_at(b, solved)) - 2 * R) < 1e-12);
        } else if (k > 0) {
            CHECK(solved == infinity);
        }
    }
}

TEST_CASE("classic balls of every law meet where a scan of their own motion finds them",
          "[physics][classic][contact]") {
    Random rng(14);
    for (const FrictionKind kind :
         {FrictionKind::decay, FrictionKind::constant, FrictionKind::combined}) {
        PhysicsParams p;
        p.friction = {kind, 1.6, 1.2, 0.005};
        const ClothModel cloth = cloth_model(p.friction);
        const ClassicMotion motion = motion_of(cloth, p);
        int hits = 0;
        for (int trial = 0; trial < 200; ++trial) {
            Ball a = ball_at(1, rng.uniform(0, 1), rng.uniform(0, 1));
            Ball b = ball_at(2, rng.uniform(0, 1), rng.uniform(0, 1));
            if (length(a.position - b.position) < 2 * R)
                continue;
            // Half of them aimed at b (give or take a ball), to meet more often.
            a.velocity = trial % 2 ? random_vec(rng, 4)
                                   : normalized(b.position - a.position + random_vec(rng, 0.06)) *
                                         rng.uniform(0.5, 4);
            a.state = MotionState::rolling;
            if (trial % 3 != 0) { // else b stands
                b.velocity = random_vec(rng, 2);
                b.state = MotionState::rolling;
            }
            const double horizon =
                std::min(cloth.time_to_transition(a, p), cloth.time_to_transition(b, p));
            const double solved = classic_pair_contact_time(a, b, 2 * R, horizon, motion);
            hits += solved < infinity;
            INFO("law " << static_cast<int>(kind) << " trial " << trial);
            check_against_scan(
                [&](double t) {
                    return length(cloth.advance(a, t, p).position -
                                  cloth.advance(b, t, p).position) -
                           2 * R;
                },
                solved, horizon);
            const Vec2 point{0.5, 0.5};
            if (length(a.position - point) > R)
                check_against_scan(
                    [&](double t) { return length(cloth.advance(a, t, p).position - point) - R; },
                    classic_point_contact_time(a, point, R, horizon, motion), horizon);
        }
        CHECK(hits > 40);
    }
}

TEST_CASE("the classic reproducers end with no overlap, nothing in a rail, and few events",
          "[physics][classic][regression]") {
    SECTION("r1: constant law, ideal collisions, a break") {
        run_scenario(
            "table 9ft\nfriction constant 1.1200\ncollision ideal\ncushion physical\n"
            "rack 8ball 8451133229269434514\nstrike 18.989906 75.6025943 0.2298 -0.2188\n");
    }
    SECTION("r2: a ball 1 um off a rail pushed along it") {
        run_scenario("table 8ft\nfriction combined 1.0972 0.2092\ncollision physical\n"
                     "cushion ideal\n"
                     "ball 0 0.028576000 0.839706411\nball 10 1.064409924 0.526279173 mass=0.2123\n"
                     "ball 15 1.750553301 0.723931221\nball 4 1.213345958 0.683450261\n"
                     "ball 6 0.393000368 0.156219236\nball 12 1.006102427 0.955070366\n"
                     "ball 13 1.689470009 1.063048376\nball 5 1.684021671 0.251832698\n"
                     "ball 9 0.038575000 0.233931163\nball 14 0.028575001 0.458038354\n"
                     "strike 0.548353 270.0000001 0.0000 0.2142\n");
    }
    SECTION("r3: a ball wedged between a standing one and one the cloth drives into it") {
        const std::size_t events =
            run_scenario("table 9ft\nfriction combined 1.6612 1.5345\ncollision physical\n"
                         "cushion ideal\nrack 8ball 9217187264908196596\n"
                         "strike 8.144664 35.6319234 0.3526 0.4000\n");
        CHECK(events < 1000); // 11,824 before the cluster was resolved as a push
    }
}

TEST_CASE("a ball driven into the wedge between a rail and a ball the cloth holds leaves it in "
          "one event",
          "[physics][classic][regression][wedge]") {
    // The soak's three shots of more than 5000 events: a ball pushed along a rail into a ball
    // at rest beside it, which a push slower than the rest speed cannot move, bounced between
    // the two every 1e-14 s (5,787, 7,176 and 62,532 events).
    SECTION("soak seed 1852272: frozen to a rail and a ball, driven along the rail") {
        const std::size_t events =
            run_scenario("table 8ft\n"
                         "friction decay 2.3878304650096287\n"
                         "collision physical\n"
                         "cushion ideal\n"
                         "ball 0 2.311425 0.4831547587663409 mass=0.17\n"
                         "ball 1 2.254275020395798 0.4831064758567747 mass=0.17\n"
                         "ball 2 1.019375311186035 1.141425 mass=0.22533371746172398\n"
                         "ball 3 0.028575 0.45971571904448766 mass=0.13072591763530797\n"
                         "ball 4 0.25365115058707144 1.0974683309616957 mass=0.17\n"
                         "ball 5 2.328208641857644 1.1414249989999998 mass=0.17\n"
                         "ball 6 1.863492138794338 0.8577404402430674 mass=0.1531531763146404\n"
                         "ball 7 0.3057239028151445 0.079823369616517 mass=0.17\n"
                         "ball 8 1.0947120157209642 0.8877156560192402 mass=0.17\n"
                         "ball 9 1.3281878426260512 1.141425 mass=0.222815321382199\n"
                         "ball 10 2.1336724841335726 1.1414249989999998 mass=0.24738413598391068\n"
                         "ball 11 0.25658057356751496 0.10899623037371875 mass=0.17\n"
                         "strike 1.3138994485762878 272.58454198786086 -0.37309409558222495 "
                         "-0.31878144516749307 45.46907484250184\n");
        CHECK(events < 50);
    }
    SECTION("soak seed 1406983") {
        const std::size_t events =
            run_scenario("table 8ft\n"
                         "friction combined 2.949034451651609 0.7940122016718368\n"
                         "collision physical\n"
                         "cushion ideal\n"
                         "ball 0 0.60451670929032 0.3814810658403636 mass=0.17\n"
                         "ball 1 0.028575 0.035785366674465316 mass=0.17\n"
                         "ball 2 0.609888558907997 0.4383780415595094 mass=0.16305714671724675\n"
                         "ball 3 0.5996645615208736 0.3245374168351984 mass=0.17\n"
                         "ball 4 0.07264249459034056 0.07217463067953014 mass=0.17\n"
                         "ball 5 0.22949836585451389 0.028575001 mass=0.17\n"
                         "ball 6 0.028575001 0.5668197610978934 mass=0.16364925354538667\n"
                         "strike 0.7876089063808713 345.616456416866 0.41812973763112526 "
                         "0.1378779632810334 74.61825314023108\n");
        CHECK(events < 200);
    }
    SECTION("soak seed 1271510") {
        const std::size_t events =
            run_scenario("table 9ft\n"
                         "friction combined 1.0397477301696771 0.6442295144376209\n"
                         "collision ideal\n"
                         "cushion ideal\n"
                         "ball 0 0.028575001 0.6590948987097035 mass=0.21653345246225528\n"
                         "ball 1 0.08507241606754844 0.6504830054808513 mass=0.17\n"
                         "ball 2 0.4018890100961796 1.1305972995122118 mass=0.17\n"
                         "ball 3 2.068856950084554 0.13133540462282772 mass=0.17\n"
                         "ball 4 0.9966010451763023 0.8534393648805438 mass=0.17\n"
                         "ball 5 0.1391806626757955 0.6688792078955106 mass=0.17\n"
                         "ball 6 0.028575 0.4759545725370679 mass=0.17\n"
                         "ball 7 0.514179842108637 0.028575001 mass=0.17\n"
                         "ball 8 0.9792844754077383 1.241424999 mass=0.1428091648467034\n"
                         "ball 9 0.399416545668052 0.8592147912965753 mass=0.17\n"
                         "ball 10 2.114721506230759 0.16543181358054043 mass=0.17\n"
                         "ball 11 2.1662596080296956 1.0110658296001207 mass=0.17\n"
                         "strike 0.5294165700755937 265.62859946562554 0.02074248751396801 "
                         "-0.1975705188376673 77.68473059078804\n");
        CHECK(events < 200);
    }
    SECTION("elastic contacts, a ball frozen to the rail and to a ball just below it") {
        // The wedge is 1.75e-3 rad wide. Each turn the held ball takes the mover's speed
        // towards it and the cloth stops it, so the mover is jammed; before, the shot never
        // ended (200,000 events, the world's limit).
        const std::size_t events = run_scenario(
            "table 9ft\nfriction decay 0.5\ncollision ideal\ncushion ideal\n"
            "ball 0 2.511425 0.6\nball 1 2.454275087489131 0.5999\nstrike 1 270 0 0\n");
        CHECK(events < 20);
    }
}

TEST_CASE("random classic shots keep every ball apart and out of the rubber after every event",
          "[physics][classic][property]") {
    const TableSize sizes[] = {TableSize::seven_foot, TableSize::eight_foot, TableSize::nine_foot};
    std::size_t most_events = 0;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        Random rng(seed);
        PhysicsParams p;
        p.friction = test::random_classic_friction(rng, seed % 3);
        if (rng.below(2) == 0)
            p.collision = CollisionModel::ideal;
        if (rng.below(2) == 0)
            p.cushion = CushionModel::ideal;
        const Table table = make_table(sizes[rng.below(3)]);
        std::vector<Ball> balls;
        if (rng.below(3) == 0) {
            balls = make_rack(table, p, rng.below(2) ? RackType::eight_ball : RackType::nine_ball,
                              seed);
        } else {
            // Balls anywhere, some frozen to another ball or to a rail (touching, or 1 nm off).
            const int count = 2 + static_cast<int>(rng.below(10));
            for (int id = 0; id < count; ++id) {
                for (int attempt = 0; attempt < 100; ++attempt) {
                    Ball b = ball_at(id, rng.uniform(R, table.length - R),
                                     rng.uniform(R, table.width - R));
                    const double off = rng.below(2) ? 0 : 1e-9;
                    switch (rng.below(4)) {
                    case 0:
                        b.position.y = rng.below(2) ? R + off : table.width - R - off;
                        break;
                    case 1:
                        b.position.x = rng.below(2) ? R + off : table.length - R - off;
                        break;
                    case 2:
                        if (!balls.empty()) {
                            const Ball& other = balls[rng.below(balls.size())];
                            const double angle = rng.uniform(0, 2 * 3.141592653589793);
                            b.position = other.position +
                                         Vec2{std::cos(angle), std::sin(angle)} * (2 * R + off);
                        }
                        break;
                    default:
                        break;
                    }
                    if (rubber_depth(table, b.position, R) > 0 || b.position.x < R ||
                        b.position.x > table.length - R || b.position.y < R ||
                        b.position.y > table.width - R)
                        continue;
                    auto all = balls;
                    all.push_back(b);
                    if (deepest_overlap(all) <= 0) {
                        balls.push_back(b);
                        break;
                    }
                }
            }
        }
        const Strike strike{rng.uniform(0, 20), rng.uniform(0, 360), rng.uniform(-0.5, 0.5),
                            rng.uniform(-0.5, 0.5)};
        INFO("seed " << seed);
        most_events = std::max(most_events, run_checked(table, p, balls, strike));
    }
    CHECK(most_events < 3000);
}
