#include "event_schedule.hpp"

#include <cmath>
#include <stdexcept>
#include <termpool/simulator.hpp>

namespace termpool::core {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Up to this many balls a search goes through the box lanes (box_lanes.hpp: every box, or,
// without four lanes, the strips above 32 balls); above, through the grid. On the bench's ball rows
// the lanes were the cheaper up to about 150 balls, and with the strips the grid was as fast or
// faster at 256 and 512.
constexpr std::size_t most_without_grid = 128;
// The width of the strips that pick the boxes to test (box_strips.hpp), in ball diameters: a
// ball at rest is in one strip or two on each axis. Measured with the bench's 128-ball row,
// one diameter to six, two ran the fewest instructions with the fewest mispredicted branches.
constexpr double strip_diameters = 2;

static_assert(ScheduledEvent::max_balls == max_world_balls, "the limit World's callers are told");

// Whether strips or grid cells can be sized from `diameter`: a diameter that is zero, negative,
// subnormal or not finite (a caller's nonsense; World does not refuse it) would make their
// indices NaN or run backwards, so every box is tested instead, which is right for any boxes.
bool cells_from(double diameter) {
    const double inverse = 1 / (4 * diameter);
    return diameter > 0 && std::isfinite(diameter) && std::isfinite(inverse) && inverse > 0;
}

// The width of the lanes' strips, or 0 for none (every box tested). Where the processor tests
// four boxes at a time, testing every one of up to 128 was the cheaper: on the bench's 64- and
// 128-ball rows 10% and 3% fewer instructions than picking them by strips, and fewer mispredicted
// branches. Two at a time, the strips were the cheaper (5% and 22% fewer).
double strip_width(double diameter) {
    return cells_from(diameter) && !BoxColumns::four_lanes_available() ? strip_diameters * diameter
                                                                       : 0;
}

// `balls`, refused before anything is allocated for them when their indices do not fit.
std::size_t checked(std::size_t balls) {
    if (balls > ScheduledEvent::max_balls)
        throw std::length_error("termpool: a world holds at most 32768 balls");
    return balls;
}

} // namespace

EventSchedule::EventSchedule(std::size_t balls, double diameter)
    : diameter_(diameter), many_(balls > most_without_grid && cells_from(diameter)),
      reach_(checked(balls), empty_box()), paths_(many_ ? balls : 0), moving_(balls),
      lanes_(many_ ? 0 : balls, strip_width(diameter)), pairs_(balls), searched_(balls, 0),
      table_time_(balls, infinity), row_min_time_(balls, infinity), row_min_partner_(balls, balls),
      leaves_(std::bit_ceil(std::max<std::size_t>(balls, 1))), key_dirty_(balls, 0) {
    dirty_keys_.reserve(balls);
    // Boxes grown by a little more than a radius each overlap whenever they come within a
    // diameter, whatever the rounding. Cells of four diameters: a ball at rest covers one to
    // four, a rolling ball a handful.
    if (many_)
        grid_.emplace(balls, 4 * diameter, 0.5 * diameter * (1 + 1e-6) + 1e-9);
    tree_.assign(2 * leaves_, no_event());
}

void EventSchedule::clear() {
    if (!touched_)
        return; // as new
    touched_ = false;
    const std::size_t n = size();
    pairs_.clear();
    std::fill(reach_.begin(), reach_.end(), empty_box());
    std::fill(moving_.begin(), moving_.end(), 0);
    lanes_.clear();
    if (many_)
        grid_->clear();
    std::fill(table_time_.begin(), table_time_.end(), infinity);
    std::fill(row_min_time_.begin(), row_min_time_.end(), infinity);
    std::fill(row_min_partner_.begin(), row_min_partner_.end(), n);
    std::fill(tree_.begin(), tree_.end(), no_event());
    dirty_keys_.clear();
    std::fill(key_dirty_.begin(), key_dirty_.end(), 0);
}

void EventSchedule::set_exact(std::size_t i, std::size_t j, double time) {
    pairs_.set_bound(i, j, false);
    set_time(i, j, time);
}

void EventSchedule::rescan_row(std::size_t r) {
    const double* row = pairs_.row(r);
    double min_time = infinity;
    std::size_t min_partner = size();
    // In ascending order, and only a strictly earlier time replaces: the lowest partner on ties.
    pairs_.visit_finite(r, [&](std::size_t k) {
        if (row[k] < min_time) {
            min_time = row[k];
            min_partner = k;
        }
    });
    row_min_time_[r] = min_time;
    row_min_partner_[r] = min_partner;
}

} // namespace termpool::core
