#include "contact_time.hpp"

#include "polynomial.hpp"

namespace termpool::core {

namespace {

// |dr + dv t + da t^2/2|^2 - distance^2 for the relative motion of two centres.
Polynomial4 pair_gap(const Path& a, const Path& b, double distance) {
    const Vec2 dr = a.position - b.position;
    const Vec2 dv = a.velocity - b.velocity;
    const Vec2 da = a.acceleration - b.acceleration;
    Polynomial4 f;
    f.c = {length_squared(dr) - distance * distance, 2 * dot(dr, dv),
           length_squared(dv) + dot(dr, da), dot(dv, da), 0.25 * length_squared(da)};
    return f;
}

} // namespace

double path_path_contact_time(const Path& a, const Path& b, double distance, double horizon) {
    return first_contact_time(pair_gap(a, b, distance), horizon);
}

ContactEstimate path_path_contact_estimate(const Path& a, const Path& b, double distance,
                                           double horizon) {
    return first_contact_estimate(pair_gap(a, b, distance), horizon);
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
    return path_path_contact_time(a, fixed, radius, horizon);
}

} // namespace termpool::core
