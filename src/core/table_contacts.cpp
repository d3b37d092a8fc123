#include "table_contacts.hpp"

#include <algorithm>
#include <utility>

#include "contact_time.hpp"

namespace termpool::core {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

bool near_pocket(const Table& table, const Box& box, int p, double radius) {
    const Pocket& pocket = table.pockets[p];
    return boxes_within(box, {pocket.region_min, pocket.region_max}, radius);
}

// Whether any point of the box is within `offset` of the line (rails are axis-aligned, but this
// works for any line).
bool box_reaches_line(const Box& box, Vec2 point, Vec2 normal, double offset) {
    const Vec2 corner{normal.x > 0 ? box.min.x : box.max.x, normal.y > 0 ? box.min.y : box.max.y};
    return dot(corner - point, normal) <= offset;
}

// Whether the contact with the segment's line `dt` from now falls on the segment itself.
bool hits_segment(const Path& path, double dt, const CushionSegment& seg) {
    if (!(dt < infinity))
        return false;
    const Vec2 at = path.position + path.velocity * dt + path.acceleration * (0.5 * dt * dt);
    const Vec2 along = seg.end - seg.start;
    const double u = dot(at - seg.start, along);
    return u >= 0 && u <= length_squared(along);
}

Vec2 closest_on_segment(const CushionSegment& seg, Vec2 p) {
    const Vec2 along = seg.end - seg.start;
    const double u = std::clamp(dot(p - seg.start, along) / length_squared(along), 0.0, 1.0);
    return seg.start + along * u;
}

double classic_segment_contact(const Ball& b, const CushionSegment& seg, double horizon,
                               const PhysicsParams& params, AdvanceFn advance) {
    const double R = params.ball_radius;
    auto gap = [&](double t) {
        const Ball moved = advance(b, t, params);
        const Vec2 d = moved.position - closest_on_segment(seg, moved.position);
        const double dist = length(d);
        return std::pair{dist - R, dot(d, moved.velocity) / dist};
    };
    auto bound = [&](double t) { return length(advance(b, t, params).velocity); };
    return advance_until_contact(gap, bound, horizon);
}

double classic_line_contact(const Ball& b, Vec2 point, Vec2 normal, double horizon,
                            const PhysicsParams& params, AdvanceFn advance) {
    auto gap = [&](double t) {
        const Ball moved = advance(b, t, params);
        return std::pair{dot(moved.position - point, normal), dot(moved.velocity, normal)};
    };
    auto bound = [&](double t) { return length(advance(b, t, params).velocity); };
    return advance_until_contact(gap, bound, horizon);
}

// The earliest table event a search has found in a piece, from `now` on; the piece's own end
// (its next transition) until something comes sooner.
struct EarliestEvent {
    EarliestEvent(const MotionPiece& piece, double now)
        : now(now), best{piece.end, TableEventKind::transition, 0} {}
    // An event `dt` seconds after `now`, kept when it is the soonest yet.
    void consider(double dt, TableEventKind kind, int feature) {
        if (now + dt < best.time)
            best = {now + dt, kind, feature};
    }
    double now;
    TableEvent best;
};

} // namespace

TableEvent physical_table_event(const MotionPiece& piece, const Box& reach, double now,
                                const Table& table, const PhysicsParams& params) {
    EarliestEvent found(piece, now);
    const double R = params.ball_radius;
    const double horizon = piece.end - now;
    const Path path = path_from(piece, now);
    for (int c = 0; c < 6; ++c) {
        const CushionSegment& seg = table.cushions[c];
        if (!box_reaches_line(reach, seg.start, seg.normal, R))
            continue;
        const double dt = path_line_contact_time(path, seg.start, seg.normal, R, horizon);
        if (now + dt < found.best.time && hits_segment(path, dt, seg))
            found.consider(dt, TableEventKind::rail, c);
    }
    // Nothing of the table is met after the first rail hit, so the pockets are searched only up
    // to it: for a fast ball that path's box is far smaller than the whole slide's.
    const double until_rail = std::min(horizon, found.best.time - now);
    const Box to_rail = path_box(path, until_rail);
    for (int p = 0; p < 6; ++p) {
        if (!near_pocket(table, to_rail, p, R))
            continue;
        // A pocket's region is wide; each jaw face and point is solved for only when the path's
        // box comes within R of it (the point is a quartic, the dearest solve here).
        for (int side = 0; side < 2; ++side) {
            const int c = 6 + 2 * p + side;
            const CushionSegment& seg = table.cushions[c];
            if (boxes_within(to_rail, box_of(seg.start, seg.end), R)) {
                const double dt =
                    path_line_contact_time(path, seg.start, seg.normal, R, until_rail);
                if (now + dt < found.best.time && hits_segment(path, dt, seg))
                    found.consider(dt, TableEventKind::jaw_line, c);
            }
            const int point = 2 * p + side;
            const Vec2 jaw = table.jaw_points[point];
            if (boxes_within(to_rail, {jaw, jaw}, R))
                found.consider(path_point_contact_time(path, jaw, R, until_rail),
                               TableEventKind::jaw_point, point);
        }
        const Pocket& pocket = table.pockets[p];
        if (box_reaches_line(to_rail, pocket.capture_point, pocket.capture_normal, 0))
            found.consider(path_line_contact_time(path, pocket.capture_point, pocket.capture_normal,
                                                  0, until_rail),
                           TableEventKind::capture, p);
    }
    return found.best;
}

TableEvent classic_table_event(const MotionPiece& piece, const Box& reach, double now,
                               const Table& table, const PhysicsParams& params, AdvanceFn advance) {
    EarliestEvent found(piece, now);
    const double R = params.ball_radius;
    const double horizon = piece.end - now;
    const Ball b = state_at(piece, now, advance, params);
    for (int c = 0; c < 18; ++c) {
        const CushionSegment& seg = table.cushions[c];
        if (seg.pocket != 0 && !near_pocket(table, reach, seg.pocket - 1, R))
            continue;
        found.consider(classic_segment_contact(b, seg, horizon, params, advance),
                       c < 6 ? TableEventKind::rail : TableEventKind::jaw_line, c);
    }
    for (int p = 0; p < 6; ++p) {
        if (!near_pocket(table, reach, p, R))
            continue;
        const Pocket& pocket = table.pockets[p];
        found.consider(classic_line_contact(b, pocket.capture_point, pocket.capture_normal, horizon,
                                            params, advance),
                       TableEventKind::capture, p);
    }
    return found.best;
}

Vec2 physical_towards_cushion(const Ball&, const CushionSegment& seg) {
    return -seg.normal;
}

Vec2 classic_towards_cushion(const Ball& ball, const CushionSegment& seg) {
    return normalized(closest_on_segment(seg, ball.position) - ball.position);
}

} // namespace termpool::core
