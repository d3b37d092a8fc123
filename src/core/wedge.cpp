#include "wedge.hpp"

#include <algorithm>

#include "collision.hpp"

namespace termpool::core {
namespace {

bool presses_into(const Ball& ball, Vec2 towards, Vec2 other_velocity = {}) {
    return dot(ball.velocity - other_velocity, towards) > 0;
}

bool is_held(const Ball& b) {
    return b.state == MotionState::stationary;
}

void note(std::vector<Event>& events, const Event& e) {
    if (std::find(events.begin(), events.end(), e) == events.end())
        events.push_back(e);
}

} // namespace

std::vector<CushionTouch> touching_cushions(const Table& table, Vec2 p, double radius) {
    std::vector<CushionTouch> out;
    const double reach = radius + wedge_touch_gap;
    for (std::size_t i = 0; i < table.cushions.size(); ++i) {
        const CushionSegment& seg = table.cushions[i];
        const Vec2 along = seg.end - seg.start;
        const double u = dot(p - seg.start, along) / length_squared(along);
        const double across = dot(p - seg.start, seg.normal);
        // Strictly between the ends: an end is a jaw point, below.
        if (u > 0 && u < 1 && across > 0 && across <= reach) {
            const Event e = seg.pocket == 0 ? Event{0, EventKind::cushion, 0, static_cast<int>(i)}
                                            : Event{0, EventKind::jaw, 0, seg.pocket};
            out.push_back({seg.normal * -1.0, e});
        }
    }
    for (std::size_t i = 0; i < table.jaw_points.size(); ++i) {
        const Vec2 d = table.jaw_points[i] - p;
        const double distance = length(d);
        if (distance > 0 && distance <= reach)
            out.push_back({d / distance, {0, EventKind::jaw, 0, table.jaw_point_pocket[i]}});
    }
    return out;
}

WedgeContacts escape_wedge(Ball& mover, const std::vector<CushionTouch>& cushions,
                           std::vector<Ball>& held, const PhysicsParams& params,
                           const ClothModel& cloth) {
    WedgeContacts touched;
    const double apart = 2 * params.ball_radius + wedge_touch_gap;
    for (int turn = 0; turn < max_wedge_turns; ++turn) {
        bool pressed = false;
        for (const CushionTouch& c : cushions) {
            if (presses_into(mover, c.towards)) {
                resolve_cushion(mover, c.towards, params, cloth);
                note(touched.cushions, c.event);
                pressed = true;
            }
        }
        for (std::size_t k = 0; k < held.size(); ++k) {
            Ball& wall = held[k];
            const Vec2 d = wall.position - mover.position;
            if (!is_held(wall) || length(d) > apart || !presses_into(mover, normalized(d)))
                continue;
            resolve_ball_ball(mover, wall, params, cloth);
            if (std::find(touched.balls.begin(), touched.balls.end(), k) == touched.balls.end())
                touched.balls.push_back(k);
            pressed = true;
        }
        if (!pressed || mover.state == MotionState::stationary)
            return touched;
    }
    // Still pressed into its wedge: it is jammed there. Stopping only takes energy.
    mover.velocity = {};
    mover.angular_velocity = {};
    cloth.settle_motion_state(mover, params);
    return touched;
}

} // namespace termpool::core
