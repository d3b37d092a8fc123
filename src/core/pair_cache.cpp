#include "pair_cache.hpp"

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

} // namespace termpool::core
