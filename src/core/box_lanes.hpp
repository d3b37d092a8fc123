#pragma once
// Boxes kept as separate coordinate arrays and tested against one box two at a time (a 128-bit
// register's worth), or four where the processor has AVX2: which come near a ball's box is a few
// vector compares rather than a loop over balls. With many balls, given a strip width, the strips
// their boxes cover (box_strips.hpp) pick the few to test (the schedule gives one only where
// boxes are tested two at a time). A lane's compare is the scalar compare, so the answer is
// the same on any target, with vector registers or without.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "box_strips.hpp"
#include "reach_box.hpp"

namespace termpool::core {

/// Boxes by coordinate: box c is [min_x[c], max_x[c]] x [min_y[c], max_y[c]].
struct BoxColumns {
    std::vector<double> min_x, min_y, max_x, max_y;

    std::size_t size() const { return min_x.size(); }
    void assign(std::size_t count, const Box& box) {
        min_x.assign(count, box.min.x);
        min_y.assign(count, box.min.y);
        max_x.assign(count, box.max.x);
        max_y.assign(count, box.max.y);
    }
    void set(std::size_t c, const Box& box) {
        min_x[c] = box.min.x;
        min_y[c] = box.min.y;
        max_x[c] = box.max.x;
        max_y[c] = box.max.y;
    }
    void push_back(const Box& box) {
        min_x.push_back(box.min.x);
        min_y.push_back(box.min.y);
        max_x.push_back(box.max.x);
        max_y.push_back(box.max.y);
    }
    /// The last box moved to index `to`, its old place dropped (to == size() - 1 drops it).
    void move_last_to(std::size_t to) {
        const std::size_t last = size() - 1;
        min_x[to] = min_x[last];
        min_y[to] = min_y[last];
        max_x[to] = max_x[last];
        max_y[to] = max_y[last];
        min_x.pop_back();
        min_y.pop_back();
        max_x.pop_back();
        max_y.pop_back();
    }
    void clear() {
        min_x.clear();
        min_y.clear();
        max_x.clear();
        max_y.clear();
    }

    /// Whether box c overlaps [lo, hi] (shares a point with it): the test every lane makes,
    /// here without a branch.
    bool overlaps(std::size_t c, Vec2 lo, Vec2 hi) const {
        return (lo.x <= max_x[c]) & (min_x[c] <= hi.x) & (lo.y <= max_y[c]) & (min_y[c] <= hi.y);
    }

    /// Bit c - `first` for each box c in [first, first + 64) and below size() that overlaps
    /// [lo, hi].
    std::uint64_t overlapping(std::size_t first, Vec2 lo, Vec2 hi) const {
#if defined(__x86_64__) && defined(__GNUC__)
        if (four_lanes_)
            return overlapping_four_lanes(first, lo, hi);
#endif
        return overlapping_two_lanes(first, lo, hi);
    }

    /// Whether overlapping() tests four boxes at a time (the processor has AVX2).
    bool has_four_lanes() const {
#if defined(__x86_64__) && defined(__GNUC__)
        return four_lanes_;
#else
        return false;
#endif
    }
    /// Whether columns made on this processor test four boxes at a time (asked of the CPU).
    static bool four_lanes_available() {
#if defined(__x86_64__) && defined(__GNUC__)
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
#else
        return false;
#endif
    }

    /// overlapping() two boxes at a time, whatever the processor.
    std::uint64_t overlapping_two_lanes(std::size_t first, Vec2 lo, Vec2 hi) const {
        using Lanes = double __attribute__((vector_size(16)));
        using Mask = std::int64_t __attribute__((vector_size(16)));
        const auto load = [](const double* p) {
            Lanes v;
            std::memcpy(&v, p, sizeof v);
            return v;
        };
        // The two lanes of a mask (each all ones or zero) as bits 0 and 1: one instruction
        // where there is one for it.
        const auto two_bits = [](Mask m) {
#if defined(__SSE2__)
            return static_cast<std::uint64_t>(__builtin_ia32_movmskpd(reinterpret_cast<Lanes>(m)));
#else
            return static_cast<std::uint64_t>((m[0] & 1) | (m[1] & 2));
#endif
        };
        const Lanes lo_x = {lo.x, lo.x}, lo_y = {lo.y, lo.y};
        const Lanes hi_x = {hi.x, hi.x}, hi_y = {hi.y, hi.y};
        const auto two = [&](std::size_t c) {
            const Mask m = (lo_x <= load(&max_x[c])) & (load(&min_x[c]) <= hi_x) &
                           (lo_y <= load(&max_y[c])) & (load(&min_y[c]) <= hi_y);
            return two_bits(m);
        };
        const std::size_t end = std::min(size(), first + 64);
        std::uint64_t bits = 0;
        std::size_t c = first;
        // Eight boxes a step: four independent pairs, then one shift into the word.
        for (; c + 8 <= end; c += 8)
            bits |= (two(c) | two(c + 2) << 2 | two(c + 4) << 4 | two(c + 6) << 6) << (c - first);
        for (; c + 2 <= end; c += 2)
            bits |= two(c) << (c - first);
        if (c < end)
            bits |= static_cast<std::uint64_t>(overlaps(c, lo, hi)) << (c - first);
        return bits;
    }

#if defined(__x86_64__) && defined(__GNUC__)
    /// overlapping() four boxes at a time; only where has_four_lanes().
    __attribute__((target("avx2"))) std::uint64_t overlapping_four_lanes(std::size_t first, Vec2 lo,
                                                                         Vec2 hi) const;
#endif

private:
#if defined(__x86_64__) && defined(__GNUC__)
    // Where the processor has AVX2 (asked once per set of columns, not per search), four boxes
    // at a time in a 256-bit register: the same compares, half the instructions. The build
    // targets x86-64's baseline, so this one function is compiled for AVX2 on its own.
    bool four_lanes_ = four_lanes_available();
#endif
};

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) inline std::uint64_t
BoxColumns::overlapping_four_lanes(std::size_t first, Vec2 lo, Vec2 hi) const {
    using Lanes = double __attribute__((vector_size(32)));
    using Mask = std::int64_t __attribute__((vector_size(32)));
    const Lanes lo_x = {lo.x, lo.x, lo.x, lo.x}, lo_y = {lo.y, lo.y, lo.y, lo.y};
    const Lanes hi_x = {hi.x, hi.x, hi.x, hi.x}, hi_y = {hi.y, hi.y, hi.y, hi.y};
    // (No helper returns a vector: outside this function that would be another ABI.)
    const auto four = [&](std::size_t c) __attribute__((target("avx2"))) {
        Lanes min_xs, min_ys, max_xs, max_ys;
        std::memcpy(&min_xs, &min_x[c], sizeof min_xs);
        std::memcpy(&min_ys, &min_y[c], sizeof min_ys);
        std::memcpy(&max_xs, &max_x[c], sizeof max_xs);
        std::memcpy(&max_ys, &max_y[c], sizeof max_ys);
        const Mask m = (lo_x <= max_xs) & (min_xs <= hi_x) & (lo_y <= max_ys) & (min_ys <= hi_y);
        return static_cast<std::uint64_t>(__builtin_ia32_movmskpd256(reinterpret_cast<Lanes>(m)));
    };
    const std::size_t end = std::min(size(), first + 64);
    std::uint64_t bits = 0;
    std::size_t c = first;
    for (; c + 8 <= end; c += 8)
        bits |= (four(c) | four(c + 4) << 4) << (c - first);
    for (; c + 4 <= end; c += 4)
        bits |= four(c) << (c - first);
    for (; c < end; ++c)
        bits |= static_cast<std::uint64_t>(overlaps(c, lo, hi)) << (c - first);
    return bits;
}
#endif

/// The boxes of `balls` balls, padded to a multiple of eight with empty boxes, and a bit per
/// ball that moves: every ball tested at once. With more than `strips_above` balls, the strips
/// their boxes cover (box_strips.hpp) pick the few to test.
class BoxLanes {
public:
    /// `strip_width`, m: a strip's width, with many balls (0: no strips, every box tested).
    BoxLanes(std::size_t balls, double strip_width)
        : balls_(balls), padded_((balls + 7) / 8 * 8), moving_((balls + 63) / 64),
          by_strips_(balls > strips_above && strip_width > 0),
          strips_(by_strips_ ? balls : 0, by_strips_ ? strip_width : 1) {
        clear();
    }

    /// Up to this many balls, testing every box (two at a time) is cheaper than picking them by
    /// strips.
    static constexpr std::size_t strips_above = 32;

    /// Every box empty, every ball at rest.
    void clear() {
        boxes_.assign(padded_, empty_box());
        std::fill(moving_.begin(), moving_.end(), 0);
        strips_.clear();
    }
    void set_box(std::size_t i, const Box& box) {
        boxes_.set(i, box);
        if (by_strips_)
            strips_.set_box(i, box);
    }
    void set_moving(std::size_t i, bool moving) {
        const std::uint64_t bit = std::uint64_t{1} << (i % 64);
        moving_[i / 64] = moving ? moving_[i / 64] | bit : moving_[i / 64] & ~bit;
    }

    /// A search box [lo, hi], prepared once for every word of overlapping().
    struct Search {
        Vec2 lo, hi;
        bool by_strips; // finite, with many balls: the strips pick the boxes to test
        BoxStrips::Spans strips;
    };
    Search search(Vec2 lo, Vec2 hi) const {
        const bool by_strips = by_strips_ && std::isfinite(lo.x) && std::isfinite(lo.y) &&
                               std::isfinite(hi.x) && std::isfinite(hi.y);
        return {lo, hi, by_strips, by_strips ? strips_.query(lo, hi) : BoxStrips::Spans{}};
    }

    /// Bit c - `first` for each ball c in [first, first + 64) (fewer at the end) whose box
    /// overlaps the search box and that moves if `needs_motion`. `first` is a multiple of 64.
    std::uint64_t overlapping(std::size_t first, const Search& s, bool needs_motion) const {
        const std::uint64_t in_word =
            balls_ - first < 64 ? (std::uint64_t{1} << (balls_ - first)) - 1 : ~std::uint64_t{0};
        const std::uint64_t allowed = needs_motion ? in_word & moving_[first / 64] : in_word;
        if (s.by_strips)
            return exactly(strips_.candidates(first, s.strips) & allowed, first, s.lo, s.hi);
        // The padding's empty boxes are (+inf, -inf): a search box infinite on every side would
        // take them in.
        return boxes_.overlapping(first, s.lo, s.hi) & allowed;
    }

private:
    // Those of `candidates` (bits from `first`) whose boxes overlap [lo, hi]: the lanes' test,
    // one box at a time.
    std::uint64_t exactly(std::uint64_t candidates, std::size_t first, Vec2 lo, Vec2 hi) const {
        std::uint64_t bits = 0;
        for (; candidates != 0; candidates &= candidates - 1) {
            const int b = std::countr_zero(candidates);
            const std::size_t c = first + static_cast<std::size_t>(b);
            bits |= static_cast<std::uint64_t>(boxes_.overlaps(c, lo, hi)) << b;
        }
        return bits;
    }

    std::size_t balls_;
    std::size_t padded_;
    BoxColumns boxes_;
    std::vector<std::uint64_t> moving_;
    bool by_strips_;   // more than strips_above balls, and strips to pick them by
    BoxStrips strips_; // only then
};

} // namespace termpool::core
