#include "../support/random.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <termpool/rack.hpp>
#include <termpool/snooker_layout.hpp>
#include <utility>

namespace termpool {
namespace {

// Spots of a triangle (rows of 1..5; 10-ball: 1..4) or diamond (1,2,3,2,1) with the apex on
// the foot spot (snooker: a triangle whose apex is a gap above the pink), rows growing away
// from the head of the table.
std::vector<Vec2> rack_spots(const Table& table, double spacing, RackType type) {
    const int rows_eight[] = {1, 2, 3, 4, 5};
    const int rows_nine[] = {1, 2, 3, 2, 1};
    const int rows_ten[] = {1, 2, 3, 4, 0};
    const int* rows = type == RackType::nine_ball  ? rows_nine
                      : type == RackType::ten_ball ? rows_ten
                                                   : rows_eight;
    const Vec2 apex = type == RackType::snooker
                          ? snooker_spot(table, snooker_pink) + Vec2{spacing, 0}
                          : table.foot_spot();
    const double row_step = spacing * std::numbers::sqrt3 / 2;
    std::vector<Vec2> spots;
    for (int r = 0; r < 5; ++r) {
        for (int j = 0; j < rows[r]; ++j)
            spots.push_back({apex.x + r * row_step, apex.y + (j - (rows[r] - 1) / 2.0) * spacing});
    }
    return spots;
}

// Pushes overlapping balls apart, a pair at a time, until none overlap (jitter can make them).
// The first `fixed` balls stay where they are (snooker's colours on their spots): a ball that
// overlaps one of them is moved the whole way.
void separate(std::vector<Ball>& balls, double radius, std::size_t fixed = 0) {
    const double apart = 2 * radius + 1e-7;
    for (int pass = 0; pass < 100; ++pass) {
        bool moved = false;
        for (std::size_t i = 0; i < balls.size(); ++i) {
            for (std::size_t j = i + 1; j < balls.size(); ++j) {
                const Vec2 d = balls[j].position - balls[i].position;
                const double distance = length(d);
                if (distance >= apart || distance == 0)
                    continue;
                if (j < fixed)
                    continue;
                if (i < fixed) {
                    balls[j].position += d * ((apart - distance) / distance);
                    moved = true;
                    continue;
                }
                const Vec2 push = d * ((apart - distance) / (2 * distance));
                balls[i].position -= push;
                balls[j].position += push;
                moved = true;
            }
        }
        if (!moved)
            return;
    }
}

template <class T> void shuffle(std::vector<T>& v, Random& rng) {
    for (std::size_t i = v.size(); i > 1; --i)
        std::swap(v[i - 1], v[rng.below(i)]);
}

// Ball numbers in spot order.
std::vector<int> rack_order(RackType type, std::optional<std::uint64_t> seed) {
    if (type == RackType::snooker) {
        // The reds are alike; shuffled all the same, as the pool racks are, so that a seed
        // decides which id is where.
        std::vector<int> reds;
        for (int id = snooker_first_red; id <= snooker_last_red; ++id)
            reds.push_back(id);
        if (seed) {
            Random rng(*seed);
            shuffle(reds, rng);
        }
        return reds;
    }
    if (type == RackType::nine_ball) {
        std::vector<int> order{1, 2, 3, 4, 9, 5, 6, 7, 8};
        if (seed) {
            Random rng(*seed);
            std::vector<int> free{2, 3, 4, 5, 6, 7, 8};
            shuffle(free, rng);
            std::size_t k = 0;
            for (int& n : order)
                if (n != 1 && n != 9)
                    n = free[k++];
        }
        return order;
    }
    if (type == RackType::ten_ball) {
        // Spot 4 is the middle of the third row; spots 6 and 9 are the back corners.
        std::vector<int> order{1, 4, 5, 6, 10, 7, 2, 8, 9, 3};
        if (seed) {
            Random rng(*seed);
            std::vector<int> free{4, 5, 6, 7, 8, 9};
            shuffle(free, rng);
            std::size_t k = 0;
            for (int& n : order)
                if (n >= 4 && n <= 9)
                    n = free[k++];
            if (rng.below(2) == 0)
                std::swap(order[6], order[9]);
        }
        return order;
    }
    // Spot 4 is the centre of the third row; spots 10 and 14 are the back corners.
    std::vector<int> order{1, 9, 2, 10, 8, 3, 11, 4, 12, 5, 6, 13, 14, 7, 15};
    if (!seed)
        return order;
    Random rng(*seed);
    std::vector<int> solids{1, 2, 3, 4, 5, 6, 7}, stripes{9, 10, 11, 12, 13, 14, 15};
    shuffle(solids, rng);
    shuffle(stripes, rng);
    const bool solid_left = rng.below(2) == 0;
    order[10] = solid_left ? solids.back() : stripes.back();
    order[14] = solid_left ? stripes.back() : solids.back();
    solids.pop_back();
    stripes.pop_back();
    std::vector<int> rest = solids;
    rest.insert(rest.end(), stripes.begin(), stripes.end());
    shuffle(rest, rng);
    std::size_t k = 0;
    for (std::size_t s = 0; s < order.size(); ++s)
        if (s != 4 && s != 10 && s != 14)
            order[s] = rest[k++];
    return order;
}

// The colours on their spots and the cue ball in the D, midway between the brown and the
// yellow on the baulk line, where a break is commonly played from.
std::vector<Ball> snooker_fixed_balls(const Table& table, const PhysicsParams& params) {
    std::vector<Ball> balls;
    for (int id = snooker_yellow; id <= snooker_black; ++id) {
        Ball b;
        b.id = id;
        b.mass = params.ball_mass;
        b.position = snooker_spot(table, id);
        balls.push_back(b);
    }
    Ball cue;
    cue.id = 0;
    cue.mass = params.cue_mass();
    cue.position = (snooker_spot(table, snooker_brown) + snooker_spot(table, snooker_yellow)) * 0.5;
    balls.push_back(cue);
    return balls;
}

// Ascending ids, as a pool rack comes out (cue ball first): the reds after the cue ball, the
// colours last.
void sort_by_id(std::vector<Ball>& balls) {
    std::sort(balls.begin(), balls.end(), [](const Ball& a, const Ball& b) { return a.id < b.id; });
}

} // namespace

int rack_last_ball(RackType type) {
    switch (type) {
    case RackType::eight_ball:
        break;
    case RackType::nine_ball:
        return 9;
    case RackType::ten_ball:
        return 10;
    case RackType::snooker:
        return snooker_black;
    }
    return 15;
}

std::vector<Ball> make_rack(const Table& table, const PhysicsParams& params, RackType type,
                            std::optional<std::uint64_t> seed) {
    const std::vector<Vec2> spots = rack_spots(table, 2 * params.ball_radius + rack_gap, type);
    const std::vector<int> order = rack_order(type, seed);
    // The jitter uses its own stream so that it does not change the order for a seed.
    Random jitter(seed.value_or(0) ^ 0x5eedf00dULL);
    std::vector<Ball> balls;
    if (type == RackType::snooker) {
        balls = snooker_fixed_balls(table, params);
    } else {
        Ball cue;
        cue.id = 0;
        cue.mass = params.cue_mass();
        cue.position = table.head_spot();
        balls.push_back(cue);
    }
    const std::size_t fixed = type == RackType::snooker ? balls.size() : 0;
    for (std::size_t s = 0; s < spots.size(); ++s) {
        Ball b;
        b.id = order[s];
        b.mass = params.ball_mass;
        b.position = spots[s];
        if (seed) {
            const double angle = jitter.uniform(0, 2 * std::numbers::pi);
            const double radius = rack_jitter * std::sqrt(jitter.uniform());
            b.position += unit_from_angle(angle) * radius;
        }
        balls.push_back(b);
    }
    if (seed)
        separate(balls, params.ball_radius, fixed);
    if (type == RackType::snooker)
        sort_by_id(balls);
    return balls;
}

} // namespace termpool
