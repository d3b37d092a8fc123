#pragma once
/// \file
/// Standard racks.

#include <cstdint>
#include <optional>
#include <termpool/ball.hpp>
#include <termpool/enum_names.hpp>
#include <termpool/params.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// Which game's rack.
enum class RackType {
    eight_ball, ///< triangle of 15, the 8 in the centre, a solid and a stripe in the back corners
    nine_ball,  ///< diamond of 9, the 1 at the apex, the 9 in the centre
    /// triangle of 10 (rows of 1 to 4), the 1 at the apex, the 10 in the middle of the third
    /// row, the 2 and the 3 on the back corners
    ten_ball,
    /// snooker: 15 reds in a triangle just above the pink, apex nearest it, the six colours on
    /// their spots, the cue ball in the D (between the brown and the yellow, on the baulk line)
    snooker,
};

/// The racks' names, as a scenario's `rack` line gives them.
inline constexpr NameRow<RackType> rack_type_names[] = {
    {RackType::eight_ball, "8ball"},
    {RackType::nine_ball, "9ball"},
    {RackType::ten_ball, "10ball"},
    {RackType::snooker, "snooker"},
};
static_assert(names_in_order(rack_type_names));

/// The highest ball id a rack of `type` holds: 15 (8-ball), 9, 10, or 21 (snooker's black).
int rack_last_ball(RackType type);

/// Gap between neighbouring balls in a rack (m): a tight rack, nearly frozen. (A looser rack
/// spreads far less on the break: with 0.2 mm gaps half as many balls reach a cushion.)
inline constexpr double rack_gap = 0.00001;
/// Largest displacement of a ball from its rack spot when a seed jitters the rack (m); balls
/// that the jitter made overlap are then pushed apart.
inline constexpr double rack_jitter = 0.0001;

/// The rack seed a game seeded with `game_seed` uses for its rack number `rerack` (0 for the
/// first, then one more for each re-rack), so that re-racks differ but replay the same.
inline std::uint64_t game_rack_seed(std::uint64_t game_seed, int rerack) {
    return game_seed * 1000003ULL + static_cast<std::uint64_t>(rerack);
}

/// The object balls racked with the apex on the foot spot and the cue ball on the head spot
/// (snooker: as RackType::snooker says, with ids as snooker_layout.hpp gives them). Without a
/// seed the order is fixed; with one, the free positions are shuffled and every racked ball
/// (every red in snooker; the colours stay on their spots) is moved by up to `rack_jitter`.
std::vector<Ball> make_rack(const Table& table, const PhysicsParams& params, RackType type,
                            std::optional<std::uint64_t> seed = std::nullopt);

} // namespace termpool
