#pragma once
/// \file
/// How long something took, counted in a fixed set of buckets: a server that runs for weeks
/// keeps its figures in constant memory. Eight buckets an octave from 1 microsecond, so a
/// percentile reads within 9% of the true time.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace termpool::hall {

/// Durations counted by size; percentiles read back.
class LatencyHistogram {
public:
    /// Counts one duration.
    void add(std::chrono::steady_clock::duration d) {
        const double us = std::chrono::duration<double, std::micro>(d).count();
        const double bucket = us <= 1 ? 0 : std::floor(std::log2(us) * per_octave);
        ++counts_[static_cast<std::size_t>(std::min<double>(bucket, buckets - 1))];
        ++total_;
    }
    /// Durations counted.
    std::uint64_t count() const { return total_; }
    /// The duration in milliseconds below which a fraction `q` (0 to 1) of those counted fall
    /// (the top of its bucket); 0 when none were counted.
    double percentile_ms(double q) const {
        const auto wanted = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(total_)));
        std::uint64_t seen = 0;
        for (std::size_t b = 0; b < buckets; ++b) {
            seen += counts_[b];
            if (seen >= wanted && seen > 0)
                return std::exp2(static_cast<double>(b + 1) / per_octave) / 1000;
        }
        return 0;
    }

private:
    static constexpr int per_octave = 8;
    static constexpr std::size_t buckets = 8 * 28; // up to 2^28 us, about 4.5 minutes
    std::array<std::uint64_t, buckets> counts_{};
    std::uint64_t total_ = 0;
};

} // namespace termpool::hall
