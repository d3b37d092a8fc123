#include <termpool/ball.hpp>
#include <termpool/event.hpp>
#include <termpool/table.hpp>

namespace termpool {

const char* motion_state_name(MotionState state) {
    switch (state) {
    case MotionState::stationary:
        return "stationary";
    case MotionState::spinning:
        return "spinning";
    case MotionState::sliding:
        return "sliding";
    case MotionState::rolling:
        return "rolling";
    case MotionState::pocketed:
        return "pocketed";
    }
    return "?";
}

const char* event_kind_name(EventKind kind) {
    switch (kind) {
    case EventKind::ball_ball:
        return "ball-ball";
    case EventKind::cushion:
        return "cushion";
    case EventKind::jaw:
        return "jaw";
    case EventKind::pocket:
        return "pocket";
    case EventKind::sliding:
        return "sliding";
    case EventKind::rolling:
        return "rolling";
    case EventKind::spinning:
        return "spinning";
    case EventKind::stopped:
        return "stopped";
    case EventKind::off_table:
        return "off-table";
    }
    return "?";
}

std::optional<TableSize> parse_table_size(std::string_view name) {
    for (const TableSize t : all_table_sizes)
        if (name == table_size_name(t))
            return t;
    return std::nullopt;
}

const char* table_size_name(TableSize size) {
    switch (size) {
    case TableSize::seven_foot:
        return "7ft";
    case TableSize::eight_foot:
        return "8ft";
    case TableSize::nine_foot:
        return "9ft";
    case TableSize::snooker:
        return "snooker";
    }
    return "?";
}

} // namespace termpool
