#include "table_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "classic_contacts.hpp"
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

// The physical model's centre: a parabola, its contacts polynomial roots in t.
struct ParabolaMotion {
    Path path;
    Vec2 position_at(double dt) const {
        return path.position + path.velocity * dt + path.acceleration * (0.5 * dt * dt);
    }
    Box box(double duration) const { return path_box(path, duration); }
    Capsule capsule(double duration) const { return capsule_of(path, duration); }
    double line(Vec2 point, Vec2 normal, double offset, double horizon) const {
        return path_line_contact_time(path, point, normal, offset, horizon);
    }
    double point(Vec2 point, double radius, double horizon) const {
        return path_point_contact_time(path, point, radius, horizon);
    }
};

// A classic model's centre: a straight line, its contacts solved exactly in each phase of the law.
struct StraightMotion {
    Ball ball; // now
    const ClassicMotion& motion;
    Vec2 position_at(double dt) const { return motion.advance(ball, dt, *motion.params).position; }
    // The centre moves along its line and never back, so its ends bound it.
    Box box(double duration) const { return box_of(ball.position, position_at(duration)); }
    Capsule capsule(double duration) const { return {ball.position, position_at(duration), 0}; }
    double line(Vec2 point, Vec2 normal, double offset, double horizon) const {
        return classic_line_contact_time(ball, point, normal, offset, horizon, motion);
    }
    double point(Vec2 point, double radius, double horizon) const {
        return classic_point_contact_time(ball, point, radius, horizon, motion);
    }
};

// Whether a point further than `radius` from the capsule could still be within `radius` of the
// path it holds: no. A micrometre of slack covers the rounding of the capsule's own arithmetic,
// so that a point the contact search would find is never left out.
bool capsule_misses(const Capsule& capsule, Vec2 point, double radius) {
    const Vec2 d = capsule.to - capsule.from;
    const double len2 = length_squared(d);
    const double s = len2 > 0 ? std::clamp(dot(point - capsule.from, d) / len2, 0.0, 1.0) : 0.0;
    const double reach = radius + capsule.bulge + 1e-6;
    return length_squared(point - (capsule.from + d * s)) > reach * reach;
}

// Whether the contact with the segment's line `dt` from now falls on the segment itself.
template <class Motion>
bool hits_segment(const Motion& motion, double dt, const CushionSegment& seg) {
    if (!(dt < infinity))
        return false;
    const Vec2 at = motion.position_at(dt);
    const Vec2 along = seg.end - seg.start;
    const double u = dot(at - seg.start, along);
    return u >= 0 && u <= length_squared(along);
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

// The search every model shares, with the model's own line and point solvers (`motion`): rails
// and jaw lines as lines whose contact must fall on the segment, jaw points, capture lines.
template <class Motion>
TableSearch table_event_search(const MotionPiece& piece, const Motion& motion, const Box& reach,
                               double now, const Table& table, const PhysicsParams& params) {
    EarliestEvent found(piece, now);
    const double R = params.ball_radius;
    const double horizon = piece.end - now;
    for (int c = 0; c < 6; ++c) {
        const CushionSegment& seg = table.cushions[c];
        if (!box_reaches_line(reach, seg.start, seg.normal, R))
            continue;
        const double dt = motion.line(seg.start, seg.normal, R, horizon);
        if (now + dt < found.best.time && hits_segment(motion, dt, seg))
            found.consider(dt, TableEventKind::rail, c);
    }
    // Nothing of the table is met after the first rail hit, so the pockets are searched only up
    // to it: for a fast ball that path's box is far smaller than the whole slide's.
    const double until_rail = std::min(horizon, found.best.time - now);
    const Box to_rail = motion.box(until_rail);
    // The capsule of that path, worked out at the first jaw point in its box (most searches
    // have none).
    std::optional<Capsule> to_rail_path;
    auto misses = [&](Vec2 point) {
        if (!to_rail_path)
            to_rail_path = motion.capsule(until_rail);
        return capsule_misses(*to_rail_path, point, R);
    };
    for (int p = 0; p < 6; ++p) {
        if (!near_pocket(table, to_rail, p, R))
            continue;
        // A pocket's region is wide; each jaw face and point is solved for only when the path's
        // box comes within R of it (the point is a quartic, the dearest solve here).
        for (int side = 0; side < 2; ++side) {
            const int c = 6 + 2 * p + side;
            const CushionSegment& seg = table.cushions[c];
            if (boxes_within(to_rail, box_of(seg.start, seg.end), R)) {
                const double dt = motion.line(seg.start, seg.normal, R, until_rail);
                if (now + dt < found.best.time && hits_segment(motion, dt, seg))
                    found.consider(dt, TableEventKind::jaw_line, c);
            }
            const int point = 2 * p + side;
            const Vec2 jaw = table.jaw_points[point];
            // The box of a long diagonal path holds points far from it: the capsule culls
            // those before the quartic.
            if (boxes_within(to_rail, {jaw, jaw}, R) && !misses(jaw))
                found.consider(motion.point(jaw, R, until_rail), TableEventKind::jaw_point, point);
        }
        const Pocket& pocket = table.pockets[p];
        if (box_reaches_line(to_rail, pocket.capture_point, pocket.capture_normal, 0))
            found.consider(motion.line(pocket.capture_point, pocket.capture_normal, 0, until_rail),
                           TableEventKind::capture, p);
    }
    const TableEvent& best = found.best;
    // The first rail hit came first (found.best's time less now is until_rail then): its box
    // is to_rail. A pocket's contact came sooner: the box up to it.
    if (best.kind == TableEventKind::transition)
        return {best, reach};
    if (best.kind == TableEventKind::rail)
        return {best, to_rail};
    return {best, motion.box(best.time - now)};
}

// Whether the search would cull every rail and pocket for a ball whose box is `box`: the culls
// are monotone in the box (a box inside it is culled too, to the bit).
bool culls_everything(const Table& table, const Box& box, double radius) {
    for (int c = 0; c < 6; ++c)
        if (box_reaches_line(box, table.cushions[c].start, table.cushions[c].normal, radius))
            return false;
    for (int p = 0; p < 6; ++p)
        if (near_pocket(table, box, p, radius))
            return false;
    return true;
}

// `box` made smaller along `axis` (0: x, 1: y) until it is clear of every pocket's region
// widened by `radius`, from the side each region lies on.
Box clear_of_pockets(const Table& table, Box box, int axis, double radius) {
    auto coord = [axis](Vec2& v) -> double& { return axis == 0 ? v.x : v.y; };
    for (const Pocket& pocket : table.pockets) {
        Box region{pocket.region_min, pocket.region_max};
        if (!boxes_within(box, region, radius))
            continue;
        const double middle = 0.5 * (coord(box.min) + coord(box.max));
        if (0.5 * (coord(region.min) + coord(region.max)) < middle)
            coord(box.min) = std::max(coord(box.min), coord(region.max) + radius);
        else
            coord(box.max) = std::min(coord(box.max), coord(region.min) - radius);
    }
    return box;
}

} // namespace

OpenField open_field(const Table& table, double radius) {
    // Inside every rail's line by more than a radius.
    Box inner{{-infinity, -infinity}, {infinity, infinity}};
    for (int c = 0; c < 6; ++c) {
        const CushionSegment& rail = table.cushions[c];
        const Vec2 n = rail.normal;
        if (n.x == 1 && n.y == 0)
            inner.min.x = std::max(inner.min.x, rail.start.x + radius);
        else if (n.x == -1 && n.y == 0)
            inner.max.x = std::min(inner.max.x, rail.start.x - radius);
        else if (n.x == 0 && n.y == 1)
            inner.min.y = std::max(inner.min.y, rail.start.y + radius);
        else if (n.x == 0 && n.y == -1)
            inner.max.y = std::min(inner.max.y, rail.start.y - radius);
        else
            return {};
    }
    const double middle_x = 0.5 * (inner.min.x + inner.max.x);
    Box left = inner, right = inner;
    left.max.x = middle_x;
    right.min.x = middle_x;
    const Box candidates[] = {clear_of_pockets(table, inner, 1, radius),
                              clear_of_pockets(table, left, 0, radius),
                              clear_of_pockets(table, right, 0, radius)};
    // Kept a micrometre inside what is checked: a reach in a box then has the search's own box
    // of its path within the checked one.
    constexpr double spare = 1e-6;
    OpenField field;
    for (const Box& candidate : candidates) {
        const Box kept{candidate.min + Vec2{2 * spare, 2 * spare},
                       candidate.max - Vec2{2 * spare, 2 * spare}};
        const Box checked{kept.min - Vec2{spare, spare}, kept.max + Vec2{spare, spare}};
        if (kept.min.x < kept.max.x && kept.min.y < kept.max.y && std::isfinite(kept.min.x) &&
            std::isfinite(kept.max.x) && std::isfinite(kept.min.y) && std::isfinite(kept.max.y) &&
            culls_everything(table, checked, radius))
            field.boxes[field.count++] = kept;
    }
    return field;
}

TableSearch physical_table_event(const MotionPiece& piece, const Box& reach, double now,
                                 const Table& table, const PhysicsParams& params) {
    return table_event_search(piece, ParabolaMotion{path_from(piece, now)}, reach, now, table,
                              params);
}

TableSearch classic_table_event(const MotionPiece& piece, const Box& reach, double now,
                                const Table& table, const ClassicMotion& motion) {
    const StraightMotion straight{state_at(piece, now, motion.advance, *motion.params), motion};
    return table_event_search(piece, straight, reach, now, table, *motion.params);
}

Vec2 physical_towards_cushion(const Ball&, const CushionSegment& seg) {
    return -seg.normal;
}

} // namespace termpool::core
