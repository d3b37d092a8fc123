#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>

namespace termpool {
namespace {

// Marks are measured on the 12 ft table; a shorter table keeps their proportions.
double scale(const Table& table) {
    return table.length / snooker_table_length;
}

} // namespace

double snooker_baulk_x(const Table& table) {
    return snooker_baulk_distance * scale(table);
}

double snooker_d_radius_on(const Table& table) {
    return snooker_d_radius * scale(table);
}

Vec2 snooker_d_centre(const Table& table) {
    return {snooker_baulk_x(table), 0.5 * table.width};
}

bool in_snooker_d(const Table& table, Vec2 p) {
    const Vec2 c = snooker_d_centre(table);
    // A nanometre of slack: the yellow and green spots lie on the D's arc, and their round-off
    // must not put them out of it.
    const double slack = 1e-9;
    const double r = snooker_d_radius_on(table) + slack;
    return p.x <= c.x + slack && length_squared(p - c) <= r * r;
}

Vec2 snooker_spot(const Table& table, int colour) {
    const double mid = 0.5 * table.width;
    const double r = snooker_d_radius_on(table);
    const double baulk = snooker_baulk_x(table);
    switch (colour) {
    case snooker_yellow:
        return {baulk, mid - r};
    case snooker_green:
        return {baulk, mid + r};
    case snooker_brown:
        return {baulk, mid};
    case snooker_blue:
        return {0.5 * table.length, mid};
    case snooker_pink:
        return {0.75 * table.length, mid};
    case snooker_black:
        return {table.length - snooker_black_distance * scale(table), mid};
    default:
        return {0.5 * table.length, mid};
    }
}

Vec2 snooker_respot(const Table& table, const std::vector<Ball>& balls, int colour, double R) {
    const Vec2 own = snooker_spot(table, colour);
    if (ball_touching(balls, own, R, colour) < 0)
        return own;
    for (int id = snooker_black; id >= snooker_yellow; --id)
        if (ball_touching(balls, snooker_spot(table, id), R, colour) < 0)
            return snooker_spot(table, id);
    // Every spot is taken: up the table from its own spot (the long string through the
    // spots is the middle of the table), else down it.
    return free_spot_on_string(table, balls, own, R, colour).value_or(own);
}

} // namespace termpool
