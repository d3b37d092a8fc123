// The assist levels by name.
#include <termpool/assist.hpp>

namespace termpool {

const char* assist_name(Assist assist) {
    return name_of(assist_names, assist);
}

std::optional<Assist> parse_assist(std::string_view name) {
    return parse_name(assist_names, name);
}

} // namespace termpool
