#pragma once
// Which balls' boxes reach into each strip of the plane, across x and across y: two boxes
// overlap only where they share an x strip and a y strip, so that a search with many balls
// tests only the few whose boxes share both with its own, rather than every box.
//
// A strip is `width` wide; strip s holds x in [s w, (s + 1) w), and strip indices are taken
// modulo 64, so that a table of any size needs no bounds: strips 64 apart share a mask, which
// only adds balls for the exact test to drop. Entering a box costs a bit per strip it covers,
// on each axis, not per cell.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "reach_box.hpp"

namespace termpool::core {

/// Balls by the strips their boxes cover.
class BoxStrips {
public:
    /// Strips per axis (a power of two: indices wrap by a mask).
    static constexpr std::int64_t strips = 64;

    /// The strips a box covers, [x0, x1] by [y0, y1], wrapped: fewer than 64 on each axis, or
    /// [0, 63]; x0 > x1 for none.
    struct Spans {
        std::int64_t x0, x1, y0, y1;
        bool operator==(const Spans&) const = default;
    };

    /// `balls` balls, none entered; `width` is a strip's width, m (positive, and its inverse
    /// finite).
    BoxStrips(std::size_t balls, double width)
        : words_((balls + 63) / 64), inverse_width_(1 / width), spans_(balls, nowhere()),
          x_(strips * words_, 0), y_(strips * words_, 0) {}

    /// Every ball in no strip.
    void clear() {
        std::fill(spans_.begin(), spans_.end(), nowhere());
        std::fill(x_.begin(), x_.end(), 0);
        std::fill(y_.begin(), y_.end(), 0);
    }

    /// Ball i's box is now `box`.
    void set_box(std::size_t i, const Box& box) {
        const Spans now = spans_of(box);
        Spans& was = spans_[i];
        if (now == was)
            return; // most changes keep the strips (a ball at rest, a slow ball's next piece)
        const std::uint64_t bit = std::uint64_t{1} << (i % 64);
        const std::size_t word = i / 64;
        mark(x_, was.x0, was.x1, word, bit, false);
        mark(y_, was.y0, was.y1, word, bit, false);
        mark(x_, now.x0, now.x1, word, bit, true);
        mark(y_, now.y0, now.y1, word, bit, true);
        was = now;
    }

    /// The strips of the finite search box [lo, hi], found once for every word of candidates;
    /// out of order, every strip between its corners (a box that overlaps it holds that
    /// stretch).
    Spans query(Vec2 lo, Vec2 hi) const {
        return wrapped({strip_of(std::min(lo.x, hi.x)), strip_of(std::max(lo.x, hi.x)),
                        strip_of(std::min(lo.y, hi.y)), strip_of(std::max(lo.y, hi.y))});
    }
    /// Bits of the balls in [first, first + 64) whose boxes share an x strip and a y strip with
    /// the query's box: every ball whose box overlaps it (shares a point with it), and a few
    /// more. `first` is a multiple of 64.
    std::uint64_t candidates(std::size_t first, const Spans& query) const {
        const std::size_t word = first / 64;
        return gather(x_, query.x0, query.x1, word) & gather(y_, query.y0, query.y1, word);
    }

private:
    static Spans nowhere() { return {1, 0, 1, 0}; }
    static Spans everywhere() { return {0, strips - 1, 0, strips - 1}; }
    // Every strip once where a span covers 64 or more.
    static Spans wrapped(Spans s) {
        if (s.x1 - s.x0 >= strips)
            s.x0 = 0, s.x1 = strips - 1;
        if (s.y1 - s.y0 >= strips)
            s.y0 = 0, s.y1 = strips - 1;
        return s;
    }

    // A coordinate's strip before wrapping (clamped a billion strips out, which keeps every
    // overlap: the clamp is monotonic as the floor is). `x` is not NaN.
    std::int64_t strip_of(double x) const { return floor_clamped(x * inverse_width_); }

    // The strips of an entered box. A box no finite search box reaches (a pocketed ball's empty
    // box, +infinity to -infinity) is in none; one whose corners are out of order or NaN in
    // every one, for the exact test to decide.
    Spans spans_of(const Box& box) const {
        constexpr double infinity = std::numeric_limits<double>::infinity();
        if (box.min.x == infinity || box.min.y == infinity || box.max.x == -infinity ||
            box.max.y == -infinity)
            return nowhere();
        if (!(box.min.x <= box.max.x && box.min.y <= box.max.y))
            return everywhere();
        return wrapped(
            {strip_of(box.min.x), strip_of(box.max.x), strip_of(box.min.y), strip_of(box.max.y)});
    }

    // Sets or clears `bit` of `word` in the wrapped strips [s0, s1].
    void mark(std::vector<std::uint64_t>& masks, std::int64_t s0, std::int64_t s1, std::size_t word,
              std::uint64_t bit, bool on) const {
        for (std::int64_t s = s0; s <= s1; ++s) {
            std::uint64_t& m = masks[static_cast<std::size_t>(s & (strips - 1)) * words_ + word];
            m = on ? m | bit : m & ~bit;
        }
    }
    // The union of `word` over the wrapped strips [s0, s1].
    std::uint64_t gather(const std::vector<std::uint64_t>& masks, std::int64_t s0, std::int64_t s1,
                         std::size_t word) const {
        std::uint64_t any = 0;
        for (std::int64_t s = s0; s <= s1; ++s)
            any |= masks[static_cast<std::size_t>(s & (strips - 1)) * words_ + word];
        return any;
    }

    std::size_t words_;
    double inverse_width_;
    std::vector<Spans> spans_; // per ball, the strips it is entered in
    // Per strip, a bit per ball: [s * words_ + w] holds balls 64 w .. 64 w + 63.
    std::vector<std::uint64_t> x_, y_;
};

} // namespace termpool::core
