#pragma once
// The contact time of every pair of balls, kept current as balls change, and what the search over
// all pairs culls with: the box each ball stays in and whether it moves.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "polynomial.hpp"
#include "reach_box.hpp"

namespace termpool::core {

/// Pair contact times of `size()` balls, absolute, +infinity for a pair that does not touch
/// before one of its balls changes.
class PairCache {
public:
    /// A pair and when it touches.
    struct Pair {
        double time;
        std::size_t i, j; ///< i < j
    };

    /// `balls` balls, no pair touching, every box at the origin and every ball at rest.
    explicit PairCache(std::size_t balls);

    /// Sets the box ball i's centre stays in until its pairs are next searched.
    void set_reach(std::size_t i, const Box& reach) { reach_[i] = reach; }
    /// The box set last for ball i.
    const Box& reach(std::size_t i) const { return reach_[i]; }
    /// Sets whether ball i moves.
    void set_moving(std::size_t i, bool moving) { moving_[i] = moving; }

    /// Searches ball i's pairs afresh at time `now`: `contact(k)` gives the ContactEstimate of
    /// pair (i, k) in seconds from now, and is asked only for balls whose boxes come within
    /// `diameter` of i's (and that move when i does not). `done` is a ball that changed in the
    /// same event and was refreshed just before: their pair is current.
    template <class Contact>
    void refresh(std::size_t i, std::size_t done, double now, double diameter, Contact contact);

    /// Whether pair (i, j) holds only a lower bound on its contact.
    bool is_bound(std::size_t i, std::size_t j) const { return bound_[i * size() + j] != 0; }

    /// Replaces the lower bound kept for pair (i, j) by its contact time.
    void set_exact(std::size_t i, std::size_t j, double time);

    /// The earliest pair contact before `time` (the lowest pair on ties), if any.
    std::optional<Pair> earliest_before(double time) const;

    /// How many balls.
    std::size_t size() const { return reach_.size(); }

private:
    // Short arrays of their own, so that the search over all balls culls without touching the
    // world's pieces. A pocketed ball's box is empty (min > max): every overlap test with it
    // fails.
    std::vector<Box> reach_;
    std::vector<std::uint8_t> moving_;
    // Kept in both orders ([i * n + j] == [j * n + i]) so that a ball's row holds all its pairs.
    std::vector<double> time_;
    // 1 where time_ holds only a lower bound on the contact (same layout): the search is put off
    // until the bound is the earliest of all events, and most never get that far.
    std::vector<std::uint8_t> bound_;
    // Earliest contact in each ball's row, so that finding the next event scans n values rather
    // than all n^2 / 2 pairs.
    std::vector<double> row_min_;
};

template <class Contact>
void PairCache::refresh(std::size_t i, std::size_t done, double now, double diameter,
                        Contact contact) {
    // Locals rather than members: the solver calls in the loop would otherwise make the compiler
    // reload every vector and recompute the ball count on each pass.
    const std::size_t n = size();
    const Box* boxes = reach_.data();
    const std::uint8_t* moves_now = moving_.data();
    const Vec2 lo = boxes[i].min - Vec2{diameter, diameter};
    const Vec2 hi = boxes[i].max + Vec2{diameter, diameter};
    // A ball at rest can only be hit by a moving one.
    const std::uint8_t needs_motion = moves_now[i] ? 0 : 1;
    double* times = time_.data();
    std::uint8_t* bounds = bound_.data();
    double* row = times + i * n;
    double earliest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
        if (k == i)
            continue;
        if (k != done) {
            // Bitwise & rather than &&: one branch per ball instead of five unpredictable ones.
            const Box& box = boxes[k];
            const bool candidate = (moves_now[k] >= needs_motion) & (lo.x <= box.max.x) &
                                   (box.min.x <= hi.x) & (lo.y <= box.max.y) & (box.min.y <= hi.y);
            double time = std::numeric_limits<double>::infinity();
            if (candidate) {
                const ContactEstimate estimate = contact(k);
                time = now + estimate.time;
                // (The flag of a pair out of reach does not matter: it is never chosen.)
                bounds[i * n + k] = bounds[k * n + i] = estimate.exact ? 0 : 1;
            }
            if (time != row[k]) { // most pairs stay out of reach: infinity before and after
                // Row k gets the same time; its minimum is kept up to date.
                double* row_k = times + k * n;
                const double old = row[k];
                row[k] = row_k[i] = time;
                if (time <= row_min_[k]) {
                    row_min_[k] = time;
                } else if (old == row_min_[k]) {
                    row_min_[k] = *std::min_element(row_k, row_k + n);
                }
            }
        }
        earliest = std::min(earliest, row[k]);
    }
    row_min_[i] = earliest;
}

// Inline, as it was in the stepping before the pair cache had a file of its own: it runs at every
// event, and as a call the 4000 breaks of `termpool bench --breaks 4000` took 5% longer.
inline std::optional<PairCache::Pair> PairCache::earliest_before(double time) const {
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
