// The hall's small helpers for its loop: the work crew that saves a round's tables side by
// side, and the histogram its figures are counted in.
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

#include "hall/latency_histogram.hpp"
#include "hall/work_crew.hpp"

using termpool::hall::LatencyHistogram;
using termpool::hall::WorkCrew;

TEST_CASE("work crew: every job of every batch runs once", "[hall]") {
    for (const int helpers : {0, 1, 3}) {
        WorkCrew crew(helpers);
        for (const std::size_t count : {0, 1, 2, 7, 100}) {
            for (int batch = 0; batch < 20; ++batch) {
                std::vector<std::atomic<int>> runs(count);
                crew.run(count, [&](std::size_t i) { ++runs[i]; });
                for (std::size_t i = 0; i < count; ++i)
                    REQUIRE(runs[i] == 1);
            }
        }
    }
}

TEST_CASE("work crew: run returns only once every job has returned", "[hall]") {
    WorkCrew crew(3);
    std::atomic<int> finished{0};
    crew.run(8, [&](std::size_t) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        ++finished;
    });
    CHECK(finished == 8);
}

TEST_CASE("latency histogram: percentiles within a bucket of the truth", "[hall]") {
    LatencyHistogram h;
    CHECK(h.percentile_ms(0.5) == 0);
    for (int i = 1; i <= 1000; ++i)
        h.add(std::chrono::microseconds(i * 10)); // 0.01 ms to 10 ms
    CHECK(h.count() == 1000);
    CHECK(h.percentile_ms(0.5) >= 5.0);
    CHECK(h.percentile_ms(0.5) <= 5.0 * 1.1);
    CHECK(h.percentile_ms(0.99) >= 9.9);
    CHECK(h.percentile_ms(0.99) <= 9.9 * 1.1);
    CHECK(h.percentile_ms(1.0) >= 10.0);
    h.add(std::chrono::hours(1)); // beyond the last bucket: counted in it
    CHECK(h.count() == 1001);
}
