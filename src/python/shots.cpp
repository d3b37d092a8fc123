#include "python/shots.hpp"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <charconv>
#include <thread>

namespace termpool::python {

namespace {

/// The shortest text that reads back as `v`, as simulate writes numbers (-0 as 0).
std::string number_text(double v) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v == 0 ? 0.0 : v).ptr;
    return std::string(buffer, end);
}

std::string position_text(Vec2 p) {
    return "(" + number_text(p.x) + ", " + number_text(p.y) + ")";
}

} // namespace

std::optional<std::string> layout_text(const Table& table, const PhysicsParams& physics,
                                       const std::vector<Ball>& balls) {
    const auto problem = layout_problem(table, balls, physics.ball_radius);
    if (!problem)
        return std::nullopt;
    const Ball& ball = balls[problem->ball];
    const std::string at =
        "ball " + std::to_string(ball.id) + " at " + position_text(ball.position);
    const std::string other = "ball " + std::to_string(balls[problem->other].id);
    switch (problem->kind) {
    case LayoutProblem::Kind::off_table:
        return at + " is off the table";
    case LayoutProblem::Kind::overlap:
        return at + " overlaps " + other;
    case LayoutProblem::Kind::same_id:
        return "duplicate ball " + std::to_string(ball.id);
    }
    return std::nullopt;
}

void check_strike(const PhysicsParams& physics, const Strike& strike) {
    if (const auto problem = strike_problem(strike, physics))
        throw pybind11::value_error(*problem);
}

void check_layout(const Table& table, const PhysicsParams& physics,
                  const std::vector<Ball>& balls) {
    if (const auto problem = layout_text(table, physics, balls))
        throw pybind11::value_error(*problem);
    const bool cue = std::any_of(balls.begin(), balls.end(), [](const Ball& b) {
        return b.id == 0 && b.state != MotionState::pocketed;
    });
    if (!cue)
        throw pybind11::value_error("no cue ball (ball 0) on the table to strike");
}

std::vector<Shot> simulate_batch(const Table& table, const PhysicsParams& physics,
                                 const std::vector<std::vector<Ball>>& layouts,
                                 const std::vector<Strike>& strikes, unsigned threads) {
    std::vector<Shot> shots(strikes.size());
    if (strikes.empty())
        return shots;
    if (threads == 0)
        threads = std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, strikes.size()));
    // Each thread takes every threads-th strike and keeps one World: a reset puts a layout out
    // in the world's own memory, so that a long batch allocates only for its results.
    const auto work = [&](std::size_t first) {
        std::optional<World> world;
        for (std::size_t i = first; i < strikes.size(); i += threads) {
            const std::vector<Ball>& layout = layouts[layouts.size() == 1 ? 0 : i];
            if (world)
                world->reset(layout);
            else
                world.emplace(table, physics, layout);
            simulate_shot(*world, strikes[i], shots[i].result);
        }
    };
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work, t);
    work(0);
    return shots;
}

} // namespace termpool::python
