#include "../support/portable_math.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <termpool/snooker_layout.hpp>
#include <termpool/table.hpp>

namespace termpool {
namespace {

struct Dimensions {
    double length, width;
};

Dimensions dimensions(TableSize size) {
    switch (size) {
    case TableSize::seven_foot:
        return {1.98, 0.99};
    case TableSize::eight_foot:
        return {2.34, 1.17};
    case TableSize::nine_foot:
        break;
    case TableSize::snooker:
        return {snooker_table_length, snooker_table_width};
    }
    return {2.54, 1.27};
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

// One side of a pocket mouth: the point where a rail ends, and the rail's direction pointing
// away from the pocket, from which the jaw is turned through the rubber.
struct MouthSide {
    Vec2 point;
    Vec2 rail_direction;
    Vec2 rail_normal;
};

} // namespace

PocketSpec pocket_spec(TableSize size) {
    if (size != TableSize::snooker)
        return {};
    // Snooker's pockets are cut with rounded cushion ends, not pool's straight facings that
    // narrow behind the mouth. Modelled with straight jaws: in the corners they run along the
    // pocket's axis (135 degrees from the rail: the throat as wide as the mouth, 1.64 balls),
    // so that a ball is not squeezed out between converging facings but has no room to spare
    // either; in the middle they close by 5 degrees each (95), the slight taper of a middle
    // pocket's rounded ends. The fall sits further back behind the mouth than pool's (the
    // shelf of a snooker pocket), so a ball must travel deeper between the jaws before it
    // drops: 35 mm in the corners, 25 mm in the middle.
    PocketSpec spec;
    spec.corner_mouth = 0.086;
    spec.side_mouth = 0.105;
    spec.corner_jaw_angle_deg = 135;
    spec.side_jaw_angle_deg = 95;
    spec.corner_capture_depth = 0.035;
    spec.side_capture_depth = 0.025;
    return spec;
}

Table make_table(TableSize size, double ball_radius) {
    return make_table(size, ball_radius, pocket_spec(size));
}

Table make_table(TableSize size, double ball_radius, const PocketSpec& spec) {
    const auto [L, W] = dimensions(size);
    return make_table(L, W, ball_radius, spec, size);
}

Table make_table(double L, double W, double ball_radius, const PocketSpec& spec, TableSize size) {
    Table table;
    table.size = size;
    table.length = L;
    table.width = W;

    // The points of a corner pocket sit this far from the corner along each rail, so that the
    // straight line between them (the mouth) is corner_mouth wide.
    const double c = spec.corner_mouth / std::numbers::sqrt2;
    const double s = spec.side_mouth / 2;
    const Vec2 up{0, 1}, down{0, -1}, right{1, 0}, left{-1, 0};
    table.cushions[0] = {{c, 0}, {L / 2 - s, 0}, up, 0};
    table.cushions[1] = {{L / 2 + s, 0}, {L - c, 0}, up, 0};
    table.cushions[2] = {{L, c}, {L, W - c}, left, 0};
    table.cushions[3] = {{L - c, W}, {L / 2 + s, W}, down, 0};
    table.cushions[4] = {{L / 2 - s, W}, {c, W}, down, 0};
    table.cushions[5] = {{0, W - c}, {0, c}, right, 0};

    struct PocketLayout {
        Vec2 position;
        Vec2 axis_in; // unit, from the mouth into the pocket
        bool corner;
        MouthSide sides[2];
    };
    const double r2 = std::numbers::sqrt2 / 2;
    const PocketLayout layouts[6] = {
        {{0, 0}, {-r2, -r2}, true, {{{c, 0}, right, up}, {{0, c}, up, right}}},
        {{L / 2, 0}, down, false, {{{L / 2 + s, 0}, right, up}, {{L / 2 - s, 0}, left, up}}},
        {{L, 0}, {r2, -r2}, true, {{{L - c, 0}, left, up}, {{L, c}, up, left}}},
        {{L, W}, {r2, r2}, true, {{{L, W - c}, down, left}, {{L - c, W}, left, down}}},
        {{L / 2, W}, up, false, {{{L / 2 - s, W}, left, down}, {{L / 2 + s, W}, right, down}}},
        {{0, W}, {-r2, r2}, true, {{{c, W}, right, down}, {{0, W - c}, down, right}}},
    };

    for (int p = 0; p < 6; ++p) {
        const PocketLayout& layout = layouts[p];
        const double angle =
            radians(layout.corner ? spec.corner_jaw_angle_deg : spec.side_jaw_angle_deg);
        const double depth = layout.corner ? spec.corner_capture_depth : spec.side_capture_depth;
        const Vec2 mouth_centre = (layout.sides[0].point + layout.sides[1].point) * 0.5;

        Pocket& pocket = table.pockets[p];
        pocket.number = p + 1;
        pocket.position = layout.position;
        pocket.capture_point = mouth_centre + layout.axis_in * depth;
        pocket.capture_normal = -layout.axis_in;
        Vec2 lo = mouth_centre, hi = mouth_centre;

        for (int side = 0; side < 2; ++side) {
            const MouthSide& m = layout.sides[side];
            // Turn the rail direction through the rubber (away from the table) by the jaw angle.
            const Vec2 jaw =
                m.rail_direction * portable::cos(angle) - m.rail_normal * portable::sin(angle);
            // Long enough that a ball is captured before it could reach the jaw's far end.
            const double jaw_length = (depth + 2.5 * ball_radius) / dot(jaw, layout.axis_in);
            const Vec2 end = m.point + jaw * jaw_length;
            Vec2 normal = perpendicular(jaw);
            if (dot(normal, mouth_centre - m.point) < 0)
                normal = -normal;
            table.cushions[6 + 2 * p + side] = {m.point, end, normal, p + 1};
            table.jaw_points[2 * p + side] = m.point;
            table.jaw_point_pocket[2 * p + side] = p + 1;
            for (const Vec2 q : {m.point, end}) {
                lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
                hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
            }
        }
        pocket.region_min = lo;
        pocket.region_max = hi;
    }
    return table;
}

double rubber_depth(const Table& table, Vec2 p, double radius) {
    double deepest = -std::numeric_limits<double>::infinity();
    for (const CushionSegment& seg : table.cushions) {
        const Vec2 along = seg.end - seg.start;
        const double u = std::clamp(dot(p - seg.start, along) / length_squared(along), 0.0, 1.0);
        deepest = std::max(deepest, radius - length(p - (seg.start + along * u)));
    }
    return deepest;
}

namespace {

bool before_capture_line(const Pocket& pocket, Vec2 p) {
    return dot(p - pocket.capture_point, pocket.capture_normal) > 0;
}

// Between the pocket's jaws: inside its box and on the table's side of both jaw lines. The
// jaws reach past the capture line, so the box and the two lines hold the whole mouth.
bool in_mouth(const Table& table, const Pocket& pocket, Vec2 p) {
    if (p.x < pocket.region_min.x || p.x > pocket.region_max.x || p.y < pocket.region_min.y ||
        p.y > pocket.region_max.y)
        return false;
    for (const CushionSegment& jaw : table.cushions)
        if (jaw.pocket == pocket.number && dot(p - jaw.start, jaw.normal) < 0)
            return false;
    return true;
}

} // namespace

bool on_playing_surface(const Table& table, Vec2 p, double radius) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return false;
    if (!(rubber_depth(table, p, radius) <= rubber_tolerance))
        return false;
    for (const Pocket& pocket : table.pockets)
        if (!before_capture_line(pocket, p))
            return false;
    if (p.x >= 0 && p.x <= table.length && p.y >= 0 && p.y <= table.width)
        return true;
    return std::ranges::any_of(table.pockets,
                               [&](const Pocket& pocket) { return in_mouth(table, pocket, p); });
}

Vec2 step_on_table(const Table& table, Vec2 from, Vec2 step, double radius) {
    const Vec2 to = from + step;
    if (on_playing_surface(table, to, radius))
        return to;
    const Vec2 clear{std::clamp(to.x, radius, table.length - radius),
                     std::clamp(to.y, radius, table.width - radius)};
    return on_playing_surface(table, clear, radius) ? clear : from;
}

} // namespace termpool
