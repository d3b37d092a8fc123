#include "ball_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace termpool::core {
namespace {

// A box that covers more cells than this is on the wide list: walking its cells would cost more
// than every search looking at it.
constexpr std::int64_t max_cells = 24;

} // namespace

const BallGrid::Cells BallGrid::empty_cells{0, 0, 0, 0, false, true};

BallGrid::BallGrid(std::size_t balls, double cell, double margin)
    : cell_(cell), inverse_cell_(1 / cell), margin_(margin), entries_(balls),
      cells_(balls, empty_cells), is_wide_(balls), is_dirty_(balls), seen_(balls) {
    std::size_t buckets = 64;
    while (buckets < 4 * balls)
        buckets *= 2;
    mask_ = buckets - 1;
    buckets_.resize(buckets);
    dirty_.reserve(balls);
    near_.reserve(balls);
}

void BallGrid::clear() {
    for (Bucket& b : buckets_) {
        b.balls.clear();
        b.boxes.clear();
    }
    for (auto& e : entries_)
        e.clear();
    wide_.clear();
    dirty_.clear();
    std::fill(cells_.begin(), cells_.end(), empty_cells);
    std::fill(is_wide_.begin(), is_wide_.end(), 0);
    std::fill(is_dirty_.begin(), is_dirty_.end(), 0);
}

BallGrid::Cells BallGrid::cells_of(const Box& box) const {
    // NaN or an empty box: in no cell.
    if (!(box.min.x <= box.max.x && box.min.y <= box.max.y))
        return empty_cells;
    Cells c{};
    c.x0 = floor_clamped((box.min.x - margin_) * inverse_cell_);
    c.y0 = floor_clamped((box.min.y - margin_) * inverse_cell_);
    c.x1 = floor_clamped((box.max.x + margin_) * inverse_cell_);
    c.y1 = floor_clamped((box.max.y + margin_) * inverse_cell_);
    c.wide = (c.x1 - c.x0 + 1) * (c.y1 - c.y0 + 1) > max_cells;
    return c;
}

std::size_t BallGrid::bucket(std::int64_t x, std::int64_t y) const {
    const auto ux = static_cast<std::uint64_t>(x);
    const auto uy = static_cast<std::uint64_t>(y);
    return static_cast<std::size_t>(((ux * 0x9E3779B97F4A7C15ull) ^ (uy * 0xC2B2AE3D27D4EB4Full)) >>
                                    40) &
           mask_;
}

void BallGrid::leave(std::size_t i) {
    const auto k = static_cast<std::uint16_t>(i);
    if (is_wide_[i]) {
        wide_.erase(std::find(wide_.begin(), wide_.end(), k));
        is_wide_[i] = 0;
    }
    for (const Entry& e : entries_[i]) {
        // The bucket's last ball takes this one's place; its entry follows it there.
        Bucket& bucket = buckets_[e.bucket];
        const std::uint16_t last = bucket.balls.back();
        if (last != k) {
            bucket.balls[e.slot] = last;
            for (Entry& moved : entries_[last])
                if (moved.bucket == e.bucket)
                    moved.slot = e.slot;
        }
        bucket.balls.pop_back();
        bucket.boxes.move_last_to(e.slot);
    }
    entries_[i].clear();
    cells_[i] = empty_cells;
}

void BallGrid::enter(std::size_t i, const Cells& c, const Box& box) {
    cells_[i] = c;
    if (c.empty)
        return;
    const auto k = static_cast<std::uint16_t>(i);
    if (c.wide) {
        wide_.push_back(k);
        is_wide_[i] = 1;
        return;
    }
    std::vector<Entry>& mine = entries_[i];
    for (std::int64_t y = c.y0; y <= c.y1; ++y) {
        for (std::int64_t x = c.x0; x <= c.x1; ++x) {
            const auto b = static_cast<std::uint32_t>(bucket(x, y));
            // Two cells may share a bucket: a ball is entered in each bucket once.
            if (std::none_of(mine.begin(), mine.end(),
                             [b](const Entry& e) { return e.bucket == b; })) {
                Bucket& in = buckets_[b];
                mine.push_back({b, static_cast<std::uint32_t>(in.balls.size())});
                in.balls.push_back(k);
                in.boxes.push_back(box);
            }
        }
    }
}

void BallGrid::flush(const std::vector<Box>& boxes) {
    for (const std::uint16_t i : dirty_) {
        is_dirty_[i] = 0;
        const Cells c = cells_of(boxes[i]);
        // Most changes (a ball stopping, a slow ball's next piece) keep the cells: only the
        // copies of the box change.
        if (c == cells_[i]) {
            for (const Entry& e : entries_[i])
                buckets_[e.bucket].boxes.set(e.slot, boxes[i]);
            continue;
        }
        leave(i);
        enter(i, c, boxes[i]);
    }
    dirty_.clear();
}

const std::vector<std::uint16_t>& BallGrid::near(std::size_t i, const std::vector<Box>& boxes,
                                                 const Capsule& path, Vec2 lo, Vec2 hi) {
    flush(boxes);
    near_.clear();
    const Cells c = cells_[i];
    if (c.empty)
        return near_;
    if (++search_ == 0) { // after 2^32 searches the old marks could match again
        std::fill(seen_.begin(), seen_.end(), 0);
        search_ = 1;
    }
    seen_[i] = search_;
    auto found = [&](std::uint16_t k) {
        if (seen_[k] != search_) {
            seen_[k] = search_;
            near_.push_back(k);
        }
    };
    for (const std::uint16_t k : wide_)
        if (boxes_within(boxes[k], {lo, hi}, 0))
            found(k);
    for (std::int64_t x = c.x0; x <= c.x1; ++x) {
        std::int64_t y0 = c.y0, y1 = c.y1;
        // A long path: only the cells along it, not the whole of its box.
        if (c.wide)
            column_of(path, x, y0, y1);
        for (std::int64_t y = y0; y <= y1; ++y) {
            const Bucket& bucket = buckets_[this->bucket(x, y)];
            for (std::size_t base = 0; base < bucket.balls.size(); base += 64)
                for (std::uint64_t hits = bucket.boxes.overlapping(base, lo, hi); hits != 0;
                     hits &= hits - 1)
                    found(bucket.balls[base + static_cast<std::size_t>(std::countr_zero(hits))]);
        }
    }
    return near_;
}

void BallGrid::column_of(const Capsule& path, std::int64_t x, std::int64_t& y0,
                         std::int64_t& y1) const {
    // A path that is not finite narrows nothing: every cell of the box.
    if (!std::isfinite(path.from.x) || !std::isfinite(path.from.y) || !std::isfinite(path.to.x) ||
        !std::isfinite(path.to.y) || !std::isfinite(path.bulge))
        return;
    // Grown by the margins of both balls and the bulge, and a little more for the rounding of
    // what follows (micrometres against cells of centimetres).
    const double w = 2 * margin_ + path.bulge + 1e-6;
    const double x_lo = static_cast<double>(x) * cell_ - w;
    const double x_hi = static_cast<double>(x + 1) * cell_ + w;
    const Vec2 d = path.to - path.from;
    // The part s in [s0, s1] of the segment from + s d whose x lies in [x_lo, x_hi].
    double s0 = 0, s1 = 1;
    if (d.x != 0) {
        const double a = (x_lo - path.from.x) / d.x, b = (x_hi - path.from.x) / d.x;
        s0 = std::max(0.0, std::min(a, b));
        s1 = std::min(1.0, std::max(a, b));
    } else if (path.from.x < x_lo || path.from.x > x_hi) {
        s0 = 1;
        s1 = 0;
    }
    if (s0 > s1) { // the path does not come near this column
        y0 = 1;
        y1 = 0;
        return;
    }
    const double ya = path.from.y + s0 * d.y, yb = path.from.y + s1 * d.y;
    y0 = std::max(y0, floor_clamped((std::min(ya, yb) - w) * inverse_cell_));
    y1 = std::min(y1, floor_clamped((std::max(ya, yb) + w) * inverse_cell_));
}

} // namespace termpool::core
