#pragma once
// The contact times of every pair of n balls: a symmetric table kept in both orders, so that a
// ball's row holds all its pairs, with a bit per pair where the time is finite (few are: balls
// far apart or at rest never meet) and, where it is, whether it is only a lower bound. A copy
// into a table of the same size writes only the finite pairs: a search copies a world at rest,
// where there are none, before each of its shots.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace termpool::core {

/// Pair times of `balls` balls, every one +infinity at first.
class PairTimes {
public:
    explicit PairTimes(std::size_t balls)
        : n_(balls), words_((balls + 63) / 64), time_(balls * balls, infinity),
          bound_(balls * balls, 0), finite_(balls * words_, 0) {}
    PairTimes(const PairTimes&) = default;
    PairTimes(PairTimes&&) noexcept = default;
    PairTimes& operator=(PairTimes&&) noexcept = default;
    /// The same pairs as `other`; into a table of the same size, only the finite ones are
    /// written, after ours are cleared.
    PairTimes& operator=(const PairTimes& other);

    /// Ball i's row: the time of pair (i, k) at [k].
    const double* row(std::size_t i) const { return time_.data() + i * n_; }
    /// Sets pair (i, k)'s time (a time not below +infinity, NaN too, is +infinity) and returns
    /// the time kept.
    double set(std::size_t i, std::size_t k, double time);
    /// Whether pair (i, k) holds only a lower bound on its contact; meaningful where its time is
    /// finite (every finite time is set with its flag).
    bool is_bound(std::size_t i, std::size_t k) const { return bound_[i * n_ + k] != 0; }
    void set_bound(std::size_t i, std::size_t k, bool bound) {
        bound_[i * n_ + k] = bound_[k * n_ + i] = bound ? 1 : 0;
    }
    /// Calls `visit(k)` for each pair (i, k) with a finite time, k ascending; `visit` may set
    /// pair (i, k).
    template <class Visit> void visit_finite(std::size_t i, Visit visit) const;
    /// Every time +infinity again, keeping the memory.
    void clear();
    /// Whether any pair's time is finite.
    bool any_finite() const;

private:
    static constexpr double infinity = std::numeric_limits<double>::infinity();
    std::size_t n_;
    std::size_t words_; // words of finite_ per row
    std::vector<double> time_;
    std::vector<std::uint8_t> bound_;
    // A bit per pair (rows of words_ words), set where the time is finite: a search walks only
    // these to clear the pairs it no longer reaches, and a row's minimum is found among them.
    std::vector<std::uint64_t> finite_;
};

template <class Visit> void PairTimes::visit_finite(std::size_t i, Visit visit) const {
    const std::uint64_t* row_bits = finite_.data() + i * words_;
    for (std::size_t w = 0; w < words_; ++w) {
        // A copy of the word: `visit` may clear bits of it.
        for (std::uint64_t bits = row_bits[w]; bits != 0; bits &= bits - 1)
            visit(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
    }
}

inline double PairTimes::set(std::size_t i, std::size_t k, double time) {
    const bool finite = time < infinity;
    const double kept = finite ? time : infinity;
    time_[i * n_ + k] = time_[k * n_ + i] = kept;
    const std::uint64_t bit_k = std::uint64_t{1} << (k % 64), bit_i = std::uint64_t{1} << (i % 64);
    std::uint64_t& word_ik = finite_[i * words_ + k / 64];
    std::uint64_t& word_ki = finite_[k * words_ + i / 64];
    if (finite) {
        word_ik |= bit_k;
        word_ki |= bit_i;
    } else {
        word_ik &= ~bit_k;
        word_ki &= ~bit_i;
    }
    return kept;
}

inline bool PairTimes::any_finite() const {
    std::uint64_t any = 0;
    for (const std::uint64_t word : finite_)
        any |= word;
    return any != 0;
}

inline void PairTimes::clear() {
    if (!any_finite())
        return; // (a world at rest: one pass over the bits, not one per row)
    for (std::size_t i = 0; i < n_; ++i)
        visit_finite(i, [&](std::size_t k) { time_[i * n_ + k] = infinity; });
    std::fill(finite_.begin(), finite_.end(), 0);
}

inline PairTimes& PairTimes::operator=(const PairTimes& other) {
    if (this == &other)
        return *this;
    if (n_ != other.n_) {
        PairTimes copy(other);
        return *this = std::move(copy);
    }
    clear();
    if (!other.any_finite())
        return *this; // every time +infinity, as ours now are
    for (std::size_t i = 0; i < n_; ++i) {
        other.visit_finite(i, [&](std::size_t k) {
            time_[i * n_ + k] = other.time_[i * n_ + k];
            bound_[i * n_ + k] = other.bound_[i * n_ + k];
        });
    }
    finite_ = other.finite_;
    return *this;
}

} // namespace termpool::core
