#pragma once
// What a ball does next on its own: its next transition on the cloth, or its first contact with
// the table (a rail, a pocket's jaw line or jaw point, a pocket's capture line), under each cloth
// model. Contacts between balls are kept apart (pair_contacts.hpp).

#include <array>
#include <limits>
#include <termpool/params.hpp>
#include <termpool/table.hpp>

#include "classic_contacts.hpp"
#include "motion_piece.hpp"
#include "reach_box.hpp"

namespace termpool::core {

/// What a ball's next event on its own is.
enum class TableEventKind { none, transition, rail, jaw_line, jaw_point, capture };

/// A ball's next event on its own.
struct TableEvent {
    double time = std::numeric_limits<double>::infinity(); ///< absolute, s
    TableEventKind kind = TableEventKind::none;            ///< what happens then
    /// Rail or jaw segment index into Table::cushions, jaw point index, or pocket index.
    int feature = 0;
};

/// A moving ball's next event on its own, and the box its centre stays in up to it.
struct TableSearch {
    TableEvent event;
    /// From `now` to the event: the search's `reach` for the transition at the piece's end,
    /// otherwise the box of the path up to the contact, as the model's reach from the piece's
    /// start gives it (the search is made at the start of a piece, and it has the box of the path
    /// up to the first rail at hand; the world would otherwise work it out again).
    Box to_event;
};

/// The physical model's next event of a moving ball: its transition at the piece's end, or an
/// earlier table contact (polynomial roots along the parabola, searched only where `reach`, the
/// box of the piece up to then, comes near). `now` is the piece's start.
TableSearch physical_table_event(const MotionPiece& piece, const Box& reach, double now,
                                 const Table& table, const PhysicsParams& params);

/// A classic model's next event of a moving ball: the same search along its straight line, the
/// contacts solved exactly in each phase of its law (classic_contacts.hpp).
TableSearch classic_table_event(const MotionPiece& piece, const Box& reach, double now,
                                const Table& table, const ClassicMotion& motion);

/// Boxes of the table where a ball's centre meets nothing of it: no rail line within a radius,
/// no pocket's region either. A moving ball whose reach lies in one of them has its transition
/// for its next event on its own, as the search would find after culling every rail and pocket
/// (most searches of a break: balls crossing the bed). Worked out once per table and ball size.
struct OpenField {
    std::array<Box, 3> boxes{}; ///< the long band between the pockets, and the two halves
    int count = 0;              ///< how many of `boxes` hold
    /// Whether `reach` lies in one of the boxes.
    bool holds(const Box& reach) const {
        for (int k = 0; k < count; ++k) {
            const Box& o = boxes[k];
            if (reach.min.x >= o.min.x && reach.max.x <= o.max.x && reach.min.y >= o.min.y &&
                reach.max.y <= o.max.y)
                return true;
        }
        return false;
    }
};

/// The open field of a table for balls of `radius`: only boxes that the search's own culls
/// reject, with a micrometre to spare (the search culls the pockets with the box of the path it
/// works out again, which may differ from the world's reach in the last bits). Without
/// axis-aligned rails, none.
OpenField open_field(const Table& table, double radius);

/// The unit vector from the centre of a ball touching the rail or jaw line `seg` to the contact,
/// as the search finds it (every model's): across the line.
Vec2 physical_towards_cushion(const Ball& ball, const CushionSegment& seg);

} // namespace termpool::core
