// The assist levels by name.
#include <termpool/assist.hpp>

namespace termpool {

const char* assist_name(Assist assist) {
    switch (assist) {
    case Assist::guided:
        return "guided";
    case Assist::standard:
        return "standard";
    case Assist::pro:
        return "pro";
    }
    return "?";
}

std::optional<Assist> parse_assist(std::string_view name) {
    for (const Assist a : {Assist::guided, Assist::standard, Assist::pro})
        if (name == assist_name(a))
            return a;
    return std::nullopt;
}

} // namespace termpool
