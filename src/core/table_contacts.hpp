#pragma once
// What a ball does next on its own: its next transition on the cloth, or its first contact with
// the table (a rail, a pocket's jaw line or jaw point, a pocket's capture line), under each cloth
// model. Contacts between balls are kept apart (pair_contacts.hpp).

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

/// The unit vector from the centre of a ball touching the rail or jaw line `seg` to the contact,
/// as the search finds it (every model's): across the line.
Vec2 physical_towards_cushion(const Ball& ball, const CushionSegment& seg);

} // namespace termpool::core
