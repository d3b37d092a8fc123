#include <charconv>
#include <cmath>
#include <numbers>
#include <termpool/simulator.hpp>

#include "cue_impact.hpp"

namespace termpool {
namespace {

// How much of its downward speed a ball driven into the slate through the cloth gets back
// (about half, as balls dropped on a pool table bounce).
constexpr double slate_restitution = 0.5;
// The highest the rebound may lift the centre, in ball radii, for the ball still to count as
// staying on the cloth; above it the shot is a jump shot, which the simulator does not model.
constexpr double max_rebound_lift_radii = 1.0;

// Locale-free, for messages only: the shortest text that reads back as `v`.
std::string decimal(double v) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return ec == std::errc{} ? std::string(buffer, end) : std::string("?");
}

// The same with `digits` decimals.
std::string decimal(double v, int digits) {
    char buffer[32];
    const auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, digits);
    return ec == std::errc{} ? std::string(buffer, end) : std::string("?");
}

std::string outside(std::string_view what, double value, double low, double high,
                    std::string_view unit) {
    return std::string(what) + " " + decimal(value) + " is outside " + decimal(low) + ".." +
           decimal(high) + std::string(unit);
}

} // namespace

std::optional<std::string> strike_problem(const Strike& s, const PhysicsParams& params) {
    if (!std::isfinite(s.speed) || !std::isfinite(s.angle_deg) || !std::isfinite(s.side) ||
        !std::isfinite(s.follow) || !std::isfinite(s.elevation_deg))
        return "a strike's speed, angle, offsets and elevation must be finite numbers";
    if (s.speed < 0 || s.speed > max_strike_speed)
        return outside("speed", s.speed, 0, max_strike_speed, " m/s");
    if (std::abs(s.side) > 0.5)
        return outside("side offset", s.side, -0.5, 0.5, " (fraction of R)");
    if (std::abs(s.follow) > 0.5)
        return outside("follow offset", s.follow, -0.5, 0.5, " (fraction of R)");
    if (s.elevation_deg < 0 || s.elevation_deg > max_cue_elevation_deg)
        return outside("elevation", s.elevation_deg, 0, max_cue_elevation_deg, " degrees");
    // The slate sends the ball back up at e v_down; it must not rise by more than the limit:
    // (e v_down)^2 / (2 g) <= h. v_down is proportional to the speed, so the limit is a speed.
    const double down_per_speed =
        -core::cue_impact({1.0, s.angle_deg, s.side, s.follow, s.elevation_deg}, params.cue_mass(),
                          params)
             .velocity.z;
    const double max_down =
        std::sqrt(2.0 * params.gravity * max_rebound_lift_radii * params.ball_radius) /
        slate_restitution;
    if (s.speed * down_per_speed > max_down)
        return "a cue raised " + decimal(s.elevation_deg, 1) + " degrees at " +
               decimal(s.speed, 2) + " m/s would make the ball jump: at most " +
               decimal(max_down / down_per_speed, 2) +
               " m/s at that elevation (jump shots are not modelled)";
    return std::nullopt;
}

} // namespace termpool
