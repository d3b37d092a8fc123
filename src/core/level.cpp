// The computer's levels by name.
#include <termpool/level.hpp>

namespace termpool {

const char* level_name(Level level) {
    switch (level) {
    case Level::easy:
        return "easy";
    case Level::medium:
        return "medium";
    case Level::hard:
        return "hard";
    case Level::pro:
        return "pro";
    }
    return "?";
}

std::optional<Level> parse_level(const std::string& name) {
    for (const Level l : {Level::easy, Level::medium, Level::hard, Level::pro})
        if (name == level_name(l))
            return l;
    return std::nullopt;
}

} // namespace termpool
