#include "core/pair_cache.hpp"

namespace termpool::core {

PairCache::PairCache(std::size_t balls)
    : reach_(balls), moving_(balls), time_(balls * balls, std::numeric_limits<double>::infinity()),
      bound_(balls * balls, 0), row_min_(balls, std::numeric_limits<double>::infinity()) {}

void PairCache::set_exact(std::size_t i, std::size_t j, double time) {
    const std::size_t n = size();
    time_[i * n + j] = time_[j * n + i] = time;
    bound_[i * n + j] = bound_[j * n + i] = 0;
    for (const std::size_t r : {i, j}) {
        const double* row = time_.data() + r * n;
        row_min_[r] = *std::min_element(row, row + n);
    }
}

std::optional<PairCache::Pair> PairCache::earliest_before(double time) const {
    const std::size_t n = size();
    std::optional<Pair> first;
    for (std::size_t i = 0; i < n; ++i) {
        if (row_min_[i] < time) {
            // Every pair of an earlier ball was already seen in that ball's row.
            const double* row = time_.data() + i * n;
            for (std::size_t j = i + 1; j < n; ++j) {
                if (row[j] < time) {
                    time = row[j];
                    first = Pair{row[j], i, j};
                }
            }
        }
    }
    return first;
}

} // namespace termpool::core
