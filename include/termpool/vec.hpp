#pragma once
/// \file
/// Small value types for 2D and 3D vectors. All quantities are SI unless a name says otherwise.

#include <cmath>

namespace termpool {

/// A vector in the table plane (x along the long side, y across).
struct Vec2 {
    double x = 0; ///< x component
    double y = 0; ///< y component

    /// Component-wise sum.
    constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    /// Component-wise difference.
    constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    /// Negation.
    constexpr Vec2 operator-() const { return {-x, -y}; }
    /// Scaling by a scalar.
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    /// Division by a scalar.
    constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
    /// In-place sum.
    constexpr Vec2& operator+=(Vec2 o) { return *this = *this + o; }
    /// In-place difference.
    constexpr Vec2& operator-=(Vec2 o) { return *this = *this - o; }
    /// Exact equality (used by determinism checks, not by physics).
    constexpr bool operator==(const Vec2&) const = default;
};

/// Scalar times vector.
constexpr Vec2 operator*(double s, Vec2 v) {
    return v * s;
}
/// Dot product.
constexpr double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
/// z component of the 3D cross product of two plane vectors.
constexpr double cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
/// Squared length.
constexpr double length_squared(Vec2 v) {
    return dot(v, v);
}
/// Length.
inline double length(Vec2 v) {
    return std::sqrt(dot(v, v));
}
/// The vector turned 90 degrees counter-clockwise.
constexpr Vec2 perpendicular(Vec2 v) {
    return {-v.y, v.x};
}
/// Unit vector in direction v, or zero for the zero vector.
inline Vec2 normalized(Vec2 v) {
    const double len = length(v);
    return len > 0 ? v / len : Vec2{};
}
/// Unit vector at angle `radians` counter-clockwise from +x (the same bits on every machine).
Vec2 unit_from_angle(double radians);
/// Unit vector at angle `degrees` counter-clockwise from +x; exact along the axes. Any finite
/// angle points where its exact remainder modulo 360 does (1e20 degrees is 280 degrees); a
/// non-finite one gives NaN components.
Vec2 unit_from_degrees(double degrees);

/// A vector in space: x and y in the table plane, z up. Used for angular velocity.
struct Vec3 {
    double x = 0; ///< x component
    double y = 0; ///< y component
    double z = 0; ///< z component (up)

    /// Component-wise sum.
    constexpr Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
    /// Component-wise difference.
    constexpr Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
    /// Scaling by a scalar.
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    /// In-place sum.
    constexpr Vec3& operator+=(Vec3 o) { return *this = *this + o; }
    /// Exact equality.
    constexpr bool operator==(const Vec3&) const = default;
};

/// Dot product.
constexpr double dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
/// Cross product.
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// A plane vector lifted into space at height z.
constexpr Vec3 lift(Vec2 v, double z = 0) {
    return {v.x, v.y, z};
}
/// The plane part of a space vector.
constexpr Vec2 planar(Vec3 v) {
    return {v.x, v.y};
}

} // namespace termpool
