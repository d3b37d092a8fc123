#include <termpool/ball.hpp>
#include <termpool/event.hpp>
#include <termpool/table.hpp>

namespace termpool {

const char* motion_state_name(MotionState state) {
    return name_of(motion_state_names, state);
}

const char* event_kind_name(EventKind kind) {
    return name_of(event_kind_names, kind);
}

std::optional<TableSize> parse_table_size(std::string_view name) {
    return parse_name(table_size_names, name);
}

const char* table_size_name(TableSize size) {
    return name_of(table_size_names, size);
}

} // namespace termpool
