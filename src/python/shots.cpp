#include "python/shots.hpp"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <exception>
#include <thread>

namespace termpool::python {

std::optional<std::string> layout_text(const Table& table, const PhysicsParams& physics,
                                       const std::vector<Ball>& balls) {
    const auto problem = layout_problem(table, balls, physics.ball_radius);
    if (!problem)
        return std::nullopt;
    return layout_problem_text(*problem, balls, [&](std::size_t index, bool) {
        return "ball " + std::to_string(balls[index].id);
    });
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
        throw pybind11::value_error(no_cue_ball_text);
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
    // An exception (memory running out) is kept and thrown once every thread has ended: one
    // escaping a thread would end the interpreter.
    std::vector<std::exception_ptr> failures(threads);
    const auto work = [&](std::size_t first) {
        try {
            std::optional<World> world;
            for (std::size_t i = first; i < strikes.size(); i += threads) {
                const std::vector<Ball>& layout = layouts[layouts.size() == 1 ? 0 : i];
                if (world)
                    world->reset(layout);
                else
                    world.emplace(table, physics, layout);
                simulate_shot(*world, strikes[i], shots[i].result);
            }
        } catch (...) {
            failures[first] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> pool;
        for (unsigned t = 1; t < threads; ++t)
            pool.emplace_back(work, t);
        work(0);
    }
    for (const std::exception_ptr& failure : failures)
        if (failure)
            std::rethrow_exception(failure);
    return shots;
}

} // namespace termpool::python
