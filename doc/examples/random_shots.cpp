// Simulates N random shots at the 8-ball rack through the installed library, and prints how
// long they took and a sum over the final positions, which doc/examples/random_shots.py must
// print to the last digit: the Python module is the same simulator.
//
//   g++ -std=c++20 -O2 random_shots.cpp $(pkg-config --cflags --libs termpool) -o random_shots
//   ./random_shots 10000

#include <termpool/termpool.hpp>

#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <string>

namespace {

/// splitmix64: the same stream in C++ and in Python, from which each shot's strike is drawn.
struct Stream {
    std::uint64_t state;
    double next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
};

} // namespace

int main(int argc, char** argv) {
    const long shots = argc > 1 ? std::stol(argv[1]) : 10000;
    const termpool::PhysicsParams physics;
    const termpool::Table table = termpool::make_table(termpool::TableSize::nine_foot);
    const auto balls = termpool::make_rack(table, physics, termpool::RackType::eight_ball);
    Stream stream{2026};
    double sum = 0;
    long events = 0;
    const auto wall = std::chrono::steady_clock::now();
    const std::clock_t cpu = std::clock();
    for (long i = 0; i < shots; ++i) {
        termpool::Strike strike;
        strike.speed = 0.5 + 7.5 * stream.next();
        strike.angle_deg = 360 * stream.next();
        strike.side = 0.6 * (stream.next() - 0.5);
        strike.follow = 0.6 * (stream.next() - 0.5);
        const termpool::ShotResult result = termpool::simulate_shot(table, physics, balls, strike);
        events += static_cast<long>(result.events.size());
        sum += result.balls[0].position.x + result.balls[0].position.y;
    }
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    const double cpu_s = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    char text[32];
    *std::to_chars(text, text + sizeof text - 1, sum).ptr = '\0'; // shortest, as Python's repr
    std::printf("termpool %s: %ld shots, %ld events, cue ball sum %s\n", TERMPOOL_VERSION, shots,
                events, text);
    std::printf("%.3f s wall, %.3f s CPU, %.1f us a shot\n", wall_s, cpu_s,
                1e6 * cpu_s / static_cast<double>(shots));
}
