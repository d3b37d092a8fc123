#include "../support/portable_math.hpp"
#include <termpool/vec.hpp>

// Out of line: the library's interface does not show the project's own sine and cosine.
namespace termpool {

Vec2 unit_from_angle(double radians) {
    const portable::SinCos sc{portable::sin(radians), portable::cos(radians)};
    return {sc.cos, sc.sin};
}

Vec2 unit_from_degrees(double degrees) {
    const portable::SinCos sc = portable::sin_cos_degrees(degrees);
    return {sc.cos, sc.sin};
}

} // namespace termpool
