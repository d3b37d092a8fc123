#pragma once
// Which balls' boxes come near a ball's box, without looking at every ball: a uniform grid
// hashed into buckets, so that the pair search does not test every box when there are many balls.
//
// A ball is entered in every cell its box (grown by a margin) covers; each bucket keeps a copy of
// its balls' boxes side by side, so that a search tests a cell's boxes two at a time
// (box_lanes.hpp). A box that covers more cells than a search should walk (a fast ball's long
// path) is on a short wide list instead, which every search looks at; its own search walks only
// the cells along its path.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "box_lanes.hpp"
#include "reach_box.hpp"

namespace termpool::core {

/// Boxes of `balls` balls, each grown by `margin` and entered in the grid cells it covers.
class BallGrid {
public:
    /// `balls` balls, none entered; `cell` is the side of a grid cell, m (a few ball diameters:
    /// a ball at rest then covers one to four cells, a rolling ball a handful).
    BallGrid(std::size_t balls, double cell, double margin);

    /// Forgets every ball's box.
    void clear();
    /// Ball i's box changed: it is entered again before the next search.
    void moved(std::size_t i) {
        if (!is_dirty_[i]) {
            is_dirty_[i] = 1;
            dirty_.push_back(static_cast<std::uint16_t>(i));
        }
    }

    /// The balls k != i whose box (in `boxes`) overlaps [lo, hi], each once. [lo, hi] must lie
    /// within ball i's box grown by 2 `margin`, so that every such ball shares a cell with it.
    /// Where ball i's box covers many cells, only the cells that may come within 2 `margin` of
    /// its `path` (which must hold its centre's path) are looked at: a ball further from the
    /// path cannot touch it. `boxes` holds every ball's current box; an empty box (min > max)
    /// is in no cell. The list is the grid's own, valid until its next call.
    const std::vector<std::uint16_t>& near(std::size_t i, const std::vector<Box>& boxes,
                                           const Capsule& path, Vec2 lo, Vec2 hi);

private:
    struct Cells {
        std::int64_t x0, y0, x1, y1;
        bool wide; // more cells than a search should walk: the ball is on the wide list
        bool empty;
        bool operator==(const Cells&) const = default;
    };
    static const Cells empty_cells;
    Cells cells_of(const Box& box) const;
    std::size_t bucket(std::int64_t x, std::int64_t y) const;
    void enter(std::size_t i, const Cells& cells, const Box& box);
    void leave(std::size_t i);
    void flush(const std::vector<Box>& boxes);
    /// Narrows the rows [y0, y1] of column x to those within reach of `path`.
    void column_of(const Capsule& path, std::int64_t x, std::int64_t& y0, std::int64_t& y1) const;

    double cell_;
    double inverse_cell_;
    double margin_;
    std::size_t mask_; // buckets - 1, a power of two less one
    // The balls entered in a bucket and their boxes, at the same index.
    struct Bucket {
        std::vector<std::uint16_t> balls;
        BoxColumns boxes;
    };
    // Where a ball is entered: a bucket and its index there.
    struct Entry {
        std::uint32_t bucket;
        std::uint32_t slot;
    };
    std::vector<Bucket> buckets_;
    std::vector<std::vector<Entry>> entries_; // per ball, where it is entered
    std::vector<Cells> cells_;                // per ball, the cells it is entered in
    std::vector<std::uint16_t> wide_;         // balls on the wide list
    std::vector<std::uint8_t> is_wide_;
    std::vector<std::uint16_t> dirty_; // balls whose box changed since they were entered
    std::vector<std::uint8_t> is_dirty_;
    std::vector<std::uint32_t> seen_; // per ball, the search that last found it
    std::uint32_t search_ = 0;
    std::vector<std::uint16_t> near_; // the last search's balls
};

} // namespace termpool::core
