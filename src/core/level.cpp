// The computer's levels by name.
#include <termpool/level.hpp>

namespace termpool {

const char* level_name(Level level) {
    return name_of(level_names, level);
}

std::optional<Level> parse_level(const std::string& name) {
    return parse_name(level_names, name);
}

} // namespace termpool
