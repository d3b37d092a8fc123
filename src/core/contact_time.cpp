#include "contact_time.hpp"

#include <cmath>
#include <limits>

#include "polynomial.hpp"

namespace termpool::core {

double path_path_contact_time(const Path& a, const Path& b, double distance, double horizon) {
    return first_contact_time(pair_gap(a, b, distance), horizon);
}

double path_line_contact_time(const Path& a, Vec2 point, Vec2 normal, double offset,
                              double horizon) {
    Polynomial4 f;
    f.c = {dot(a.position - point, normal) - offset, dot(a.velocity, normal),
           0.5 * dot(a.acceleration, normal), 0, 0};
    return first_contact_time(f, horizon);
}

double path_point_contact_time(const Path& a, Vec2 point, double radius, double horizon) {
    const Path fixed{point, {}, {}, horizon};
    // The quartic's search would find nothing: most jaw points left by the capsule's cull are
    // this far from the path.
    if (clearly_apart(a, fixed, radius, horizon, std::abs(a.position.x) + std::abs(a.position.y)))
        return std::numeric_limits<double>::infinity();
    return path_path_contact_time(a, fixed, radius, horizon);
}

} // namespace termpool::core
