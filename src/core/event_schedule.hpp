#pragma once
// What the world does next: each ball's next event on its own (its table event) and the contact
// time of every pair of balls, kept current as balls change, with the earliest of them all at
// hand. A ball's row of pair times keeps its minimum, and a tournament over the balls keeps the
// earliest table event or row minimum of all, so that a change replays a few matches on its way
// to the root. The pair search culls with the box each ball's centre stays in and whether it
// moves; only the pairs holding a contact are walked, by a bit per pair. Which boxes a search
// tests: up to 128 balls every box, four at a time without a branch where the processor has AVX2;
// two at a time without it, and from 33 balls only those whose boxes share a strip of the table
// across x and one across y with its box (box_strips.hpp); above 128, a grid over the boxes, so
// that nothing in an event's work walks every ball.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "ball_grid.hpp"
#include "box_lanes.hpp"
#include "pair_times.hpp"
#include "polynomial.hpp"
#include "reach_box.hpp"

namespace termpool::core {

/// The earliest event: a ball's table event or a pair's contact.
struct ScheduledEvent {
    double time; ///< absolute, s; +infinity when nothing is scheduled
    /// `is_pair`, i and j packed so that one comparison breaks ties: at one time a table event
    /// comes before a pair, the lower ball first, and the lower pair (i, then j) first.
    std::uint32_t order;

    static constexpr std::uint32_t pair_bit = 1u << 31;
    /// Ball indices stay below this (15 bits each).
    static constexpr std::size_t max_balls = 1u << 15;

    static ScheduledEvent table(double time, std::size_t i) {
        return {time, static_cast<std::uint32_t>(i << 15)};
    }
    static ScheduledEvent pair(double time, std::size_t i, std::size_t j) {
        return {time, pair_bit | static_cast<std::uint32_t>(std::min(i, j) << 15 | std::max(i, j))};
    }
    bool is_pair() const { return (order & pair_bit) != 0; }
    std::size_t i() const { return (order >> 15) & 0x7fff; }
    std::size_t j() const { return order & 0x7fff; }

    friend bool operator<(const ScheduledEvent& a, const ScheduledEvent& b) {
        return a.time < b.time || (a.time == b.time && a.order < b.order);
    }
};

namespace schedule_detail {

#ifdef __SIZEOF_INT128__
// An event as one number: its time's bits above its order, so that the earlier of two keys is
// the smaller number, picked by a compare and two conditional moves. The time's bits are below
// 2^63 and the order below 2^32: the key fits in 95 bits.
__extension__ using EventKey = unsigned __int128;
inline EventKey event_key(std::uint64_t time_bits, std::uint32_t order) {
    return static_cast<EventKey>(time_bits) << 32 | order;
}
inline std::uint64_t time_bits_of(EventKey key) {
    return static_cast<std::uint64_t>(key >> 32);
}
inline std::uint32_t order_of(EventKey key) {
    return static_cast<std::uint32_t>(key);
}
inline EventKey earlier(EventKey a, EventKey b) {
    return b < a ? b : a;
}
#else
// Without 128-bit integers: the same order from two compares.
struct EventKey {
    std::uint64_t time_bits;
    std::uint32_t order;
};
inline EventKey event_key(std::uint64_t time_bits, std::uint32_t order) {
    return {time_bits, order};
}
inline std::uint64_t time_bits_of(EventKey key) {
    return key.time_bits;
}
inline std::uint32_t order_of(EventKey key) {
    return key.order;
}
inline EventKey earlier(EventKey a, EventKey b) {
    const bool b_first =
        (b.time_bits < a.time_bits) | ((b.time_bits == a.time_bits) & (b.order < a.order));
    return b_first ? b : a;
}
#endif

} // namespace schedule_detail

/// The table events and pair contacts of `size()` balls; times are absolute, +infinity for
/// nothing (a NaN time counts as nothing too).
class EventSchedule {
public:
    /// `balls` balls of diameter `diameter`, nothing scheduled, every box empty and every ball
    /// at rest. At most ScheduledEvent::max_balls balls (std::length_error otherwise).
    EventSchedule(std::size_t balls, double diameter);

    /// Back to the state of a new schedule, keeping the memory.
    void clear();

    /// Sets ball i's next event on its own.
    void set_table_time(std::size_t i, double time);

    /// Sets the box ball i's centre stays in until its pairs are next searched, and the capsule
    /// within it that holds the path.
    void set_reach(std::size_t i, const Box& reach, const Capsule& path);
    /// Whether set_reach's capsules are used (with many balls, where the search walks the grid
    /// along long paths); otherwise any capsule will do.
    bool searches_paths() const { return many_; }
    /// The box set last for ball i.
    const Box& reach(std::size_t i) const { return reach_[i]; }
    /// Sets whether ball i moves.
    void set_moving(std::size_t i, bool moving) {
        moving_[i] = moving;
        if (!many_)
            lanes_.set_moving(i, moving);
    }

    /// Searches ball i's pairs afresh at time `now`: `contact(k)` gives the ContactEstimate of
    /// pair (i, k) in seconds from now, and is asked only for balls whose boxes come within a
    /// diameter of i's (and that move when i does not). `done` is a ball that changed in the
    /// same event and was refreshed just before: their pair is current.
    template <class Contact>
    void refresh(std::size_t i, std::size_t done, double now, Contact contact);

    /// Whether pair (i, j) holds only a lower bound on its contact.
    bool is_bound(std::size_t i, std::size_t j) const { return pairs_.is_bound(i, j); }
    /// Replaces the lower bound kept for pair (i, j) by its contact time.
    void set_exact(std::size_t i, std::size_t j, double time);

    /// The earliest event of all (time +infinity when there is none).
    ScheduledEvent earliest();

    /// How many balls.
    std::size_t size() const { return reach_.size(); }

private:
    // Sets pair (i, k)'s time; row k's minimum follows, and row i's too unless `row_i_later`
    // (a search of row i, which finds its minimum once at the end).
    void set_time(std::size_t i, std::size_t k, double time, bool row_i_later = false);
    void row_changed(std::size_t r, std::size_t partner, double time);
    void rescan_row(std::size_t r);
    void update_key(std::size_t i);

    double diameter_;
    bool touched_ = false; // anything set since construction or clear()
    // Many balls (above 128, of a size grid cells can be sized by): their pairs are searched
    // through the grid. Fewer are faster through the lanes than through the grid's bookkeeping.
    bool many_;
    // Short arrays of their own, so that the search culls without touching the world's pieces.
    // A pocketed ball's box is empty (min > max): every overlap test with it fails.
    std::vector<Box> reach_;
    std::vector<Capsule> paths_; // with many balls only: the grid walks long paths
    std::vector<std::uint8_t> moving_;
    BoxLanes lanes_; // without many balls, the boxes and motions again, to test them at once
    std::optional<BallGrid> grid_; // only with many balls
    // A pair's time may be only a lower bound on its contact: the search is put off until the
    // bound is the earliest of all events, and most never get that far.
    PairTimes pairs_;
    // Per ball, the search that last gave its pair with the searched ball a time.
    std::vector<std::uint32_t> searched_;
    std::uint32_t search_ = 0;
    std::vector<double> table_time_;
    // Each row's earliest pair: its time and partner (the lowest partner on ties; size() when
    // the row holds no contact).
    std::vector<double> row_min_time_;
    std::vector<std::size_t> row_min_partner_;
    // Each ball's earliest event (its table event or its row's minimum) as a key, at the leaves
    // of a tournament: each node above holds the earlier of its two children, so that the root
    // is the earliest event of all, and a changed key replays only the matches on its way up
    // (four at 16 balls, seven at 128), rather than a rescan of its neighbours' keys.
    // A key's time is the bits of the double: times are never negative (nor -0), and for those
    // the bits order as the values do, so that picking the earlier of two is integer compares
    // without a branch to mispredict (schedule_detail::EventKey).
    using Key = schedule_detail::EventKey;
    static constexpr std::uint64_t infinity_bits = 0x7ff0000000000000; // +infinity's bits
    // Nothing scheduled: +infinity with order 0.
    static Key no_event() { return schedule_detail::event_key(infinity_bits, 0); }
    // Leaves: the balls, then padding with nothing up to a power of two. tree_[1] is the root,
    // node p's children are 2p and 2p + 1, and ball i's leaf is tree_[leaves_ + i].
    std::size_t leaves_;
    std::vector<Key> tree_;
    // Balls whose table event or row minimum changed since their keys were last brought up to
    // date: an event changes a row several times, and the key is made once.
    std::vector<std::size_t> dirty_keys_;
    std::vector<std::uint8_t> key_dirty_;
    void key_changed(std::size_t i) {
        if (!key_dirty_[i]) {
            key_dirty_[i] = 1;
            dirty_keys_.push_back(i);
        }
    }
};

template <class Contact>
void EventSchedule::refresh(std::size_t i, std::size_t done, double now, Contact contact) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const std::size_t n = size();
    const Vec2 lo = reach_[i].min - Vec2{diameter_, diameter_};
    const Vec2 hi = reach_[i].max + Vec2{diameter_, diameter_};
    // A ball at rest can only be hit by a moving one.
    const std::uint8_t needs_motion = moving_[i] ? 0 : 1;
    const double* row = pairs_.row(i);
    if (++search_ == 0) { // after 2^32 searches the old marks could match again
        std::fill(searched_.begin(), searched_.end(), 0);
        search_ = 1;
    }
    auto search = [&](std::size_t k) __attribute__((always_inline)) {
        searched_[k] = search_;
        const ContactEstimate estimate = contact(k);
        // (The flag of a pair out of reach does not matter: it is never chosen.)
        pairs_.set_bound(i, k, !estimate.exact);
        const double time = now + estimate.time;
        if (time != row[k])
            set_time(i, k, time, true);
    };
    // Pair (i, k) is searched where the boxes come within a diameter and one of the balls
    // moves.
    if (many_) { // the few balls the grid finds in reach
        for (const std::size_t k : grid_->near(i, reach_, paths_[i], lo, hi))
            if (k != done && moving_[k] >= needs_motion)
                search(k);
    } else {
        // The boxes in reach as masks of 64 (every box tested without a branch, or those the
        // strips pick); only the balls in reach (about one in five) are walked: a branch per
        // ball would be mispredicted at every other.
        const BoxLanes::Search box = lanes_.search(lo, hi);
        for (std::size_t base = 0; base < n; base += 64) {
            std::uint64_t reached = lanes_.overlapping(base, box, needs_motion != 0);
            if (i - base < 64)
                reached &= ~(std::uint64_t{1} << (i - base));
            if (done - base < 64)
                reached &= ~(std::uint64_t{1} << (done - base));
            for (; reached != 0; reached &= reached - 1)
                search(base + static_cast<std::size_t>(std::countr_zero(reached)));
        }
    }
    // The pairs that held a contact and are out of reach now (the pair with `done` excepted)
    // are cleared, and the row's minimum is found among the others in the same walk (as
    // rescan_row finds it: ascending, the lowest partner on ties).
    double min_time = infinity;
    std::size_t min_partner = n;
    pairs_.visit_finite(i, [&](std::size_t k) {
        if (k != done && searched_[k] != search_) {
            set_time(i, k, infinity, true);
        } else if (row[k] < min_time) {
            min_time = row[k];
            min_partner = k;
        }
    });
    row_min_time_[i] = min_time;
    row_min_partner_[i] = min_partner;
    key_changed(i);
}

inline void EventSchedule::set_reach(std::size_t i, const Box& reach, const Capsule& path) {
    touched_ = true;
    reach_[i] = reach;
    if (many_) {
        paths_[i] = path;
        grid_->moved(i);
    } else {
        lanes_.set_box(i, reach);
    }
}

inline void EventSchedule::set_table_time(std::size_t i, double time) {
    touched_ = true;
    table_time_[i] = time < std::numeric_limits<double>::infinity()
                         ? time
                         : std::numeric_limits<double>::infinity();
    key_changed(i);
}

inline void EventSchedule::set_time(std::size_t i, std::size_t k, double time, bool row_i_later) {
    time = pairs_.set(i, k, time); // NaN and beyond kept as +infinity
    if (!row_i_later)
        row_changed(i, k, time);
    row_changed(k, i, time);
}

// Row r's pair with `partner` now has `time`: its minimum moves only when that pair comes
// earlier than it, or was it.
inline void EventSchedule::row_changed(std::size_t r, std::size_t partner, double time) {
    double& min_time = row_min_time_[r];
    std::size_t& min_partner = row_min_partner_[r];
    if (time < min_time || (time == min_time && time < std::numeric_limits<double>::infinity() &&
                            partner < min_partner)) {
        min_time = time;
        min_partner = partner;
    } else if (partner == min_partner) {
        rescan_row(r);
    } else {
        return;
    }
    key_changed(r);
}

inline ScheduledEvent EventSchedule::earliest() {
    for (const std::size_t i : dirty_keys_)
        update_key(i);
    dirty_keys_.clear();
    const Key first = tree_[1];
    return {std::bit_cast<double>(schedule_detail::time_bits_of(first)),
            schedule_detail::order_of(first)};
}

inline void EventSchedule::update_key(std::size_t i) {
    key_dirty_[i] = 0;
    ScheduledEvent leaf = ScheduledEvent::table(table_time_[i], i);
    const double pair_time = row_min_time_[i];
    if (pair_time < std::numeric_limits<double>::infinity()) {
        const ScheduledEvent pair = ScheduledEvent::pair(pair_time, i, row_min_partner_[i]);
        if (pair < leaf)
            leaf = pair;
    }
    // + 0.0 turns a -0 into +0; nothing scheduled is +infinity with order 0.
    Key key =
        leaf.time < std::numeric_limits<double>::infinity()
            ? schedule_detail::event_key(std::bit_cast<std::uint64_t>(leaf.time + 0.0), leaf.order)
            : no_event();
    // Up to the root, each match replayed with the winner so far kept in registers: reading it
    // back from the node just written would wait on that store at every level.
    std::size_t node = leaves_ + i;
    tree_[node] = key;
    for (; node > 1; node /= 2) {
        key = schedule_detail::earlier(key, tree_[node ^ 1]);
        tree_[node / 2] = key;
    }
}

} // namespace termpool::core
