#pragma once
// The boxes of every ball side by side, two at a time (a 128-bit register's worth): which come
// near one box is a few vector compares rather than a loop over balls. A lane's compare is the
// scalar compare, so the answer is the same on any target, with vector registers or without.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "reach_box.hpp"

namespace termpool::core {

/// The boxes of `balls` balls as separate coordinate arrays, padded to a multiple of eight with
/// empty boxes, and a bit per ball that moves.
class BoxLanes {
public:
    explicit BoxLanes(std::size_t balls)
        : padded_((balls + 7) / 8 * 8), moving_((balls + 63) / 64) {
        clear();
    }

    /// Every box empty, every ball at rest.
    void clear() {
        constexpr double infinity = std::numeric_limits<double>::infinity();
        min_x_.assign(padded_, infinity);
        min_y_.assign(padded_, infinity);
        max_x_.assign(padded_, -infinity);
        max_y_.assign(padded_, -infinity);
        std::fill(moving_.begin(), moving_.end(), 0);
    }
    void set_box(std::size_t i, const Box& box) {
        min_x_[i] = box.min.x;
        min_y_[i] = box.min.y;
        max_x_[i] = box.max.x;
        max_y_[i] = box.max.y;
    }
    void set_moving(std::size_t i, bool moving) {
        const std::uint64_t bit = std::uint64_t{1} << (i % 64);
        moving_[i / 64] = moving ? moving_[i / 64] | bit : moving_[i / 64] & ~bit;
    }

    /// Bit c - `first` for each ball c in [first, first + 64) (fewer at the end) whose box may
    /// overlap [lo, hi] and that moves if `needs_motion`. `first` is a multiple of 64.
    std::uint64_t overlapping(std::size_t first, Vec2 lo, Vec2 hi, bool needs_motion) const {
        const auto load = [](const double* p) {
            Lanes v;
            std::memcpy(&v, p, sizeof v);
            return v;
        };
        const Lanes lo_x = {lo.x, lo.x}, lo_y = {lo.y, lo.y};
        const Lanes hi_x = {hi.x, hi.x}, hi_y = {hi.y, hi.y};
        const std::size_t end = first + 64 < padded_ ? first + 64 : padded_;
        const auto two = [&](std::size_t c) {
            const Mask m = (lo_x <= load(&max_x_[c])) & (load(&min_x_[c]) <= hi_x) &
                           (lo_y <= load(&max_y_[c])) & (load(&min_y_[c]) <= hi_y);
            return two_bits(m);
        };
        // Eight balls a step: four independent pairs, then one shift into the word.
        std::uint64_t bits = 0;
        for (std::size_t c = first; c < end; c += 8) {
            const std::uint64_t eight =
                two(c) | two(c + 2) << 2 | two(c + 4) << 4 | two(c + 6) << 6;
            bits |= eight << (c - first);
        }
        return needs_motion ? bits & moving_[first / 64] : bits;
    }

private:
    using Lanes = double __attribute__((vector_size(16)));
    using Mask = std::int64_t __attribute__((vector_size(16)));

    // The two lanes of a mask (each all ones or zero) as bits 0 and 1: one instruction where
    // there is one for it.
    static std::uint64_t two_bits(Mask m) {
#if defined(__SSE2__)
        return static_cast<std::uint64_t>(__builtin_ia32_movmskpd(reinterpret_cast<Lanes>(m)));
#else
        return static_cast<std::uint64_t>((m[0] & 1) | (m[1] & 2));
#endif
    }

    std::size_t padded_;
    std::vector<double> min_x_, min_y_, max_x_, max_y_;
    std::vector<std::uint64_t> moving_;
};

} // namespace termpool::core
