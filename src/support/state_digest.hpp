#pragma once
/// \file
/// A 64-bit digest of simulator and referee state, to tell at a glance whether two runs agree
/// to the bit: the determinism test, `termpool bench`, a record's check and the hall use it.

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <termpool/ball.hpp>
#include <vector>

namespace termpool {

/// FNV-1a fed whole values: integers widened to 64 bits, doubles by their bits (so -0 and 0,
/// or two NaNs, differ as their bits do).
class StateDigest {
public:
    /// Adds 64 bits.
    void add(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) {
            hash_ ^= (v >> (8 * i)) & 0xFF;
            hash_ *= 0x100000001b3ULL;
        }
    }
    /// Adds an integer.
    void add(int v) { add(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))); }
    /// Adds a flag.
    void add(bool v) { add(static_cast<std::uint64_t>(v)); }
    /// Adds the bits of a double.
    void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
    /// Adds every field of a ball: id, state, pocket, mass, position, velocity and spin.
    void add(const Ball& b) {
        add(b.id);
        add(static_cast<int>(b.state));
        add(b.pocket);
        add(b.mass);
        add(b.position.x);
        add(b.position.y);
        add(b.velocity.x);
        add(b.velocity.y);
        add(b.angular_velocity.x);
        add(b.angular_velocity.y);
        add(b.angular_velocity.z);
    }
    /// Adds a text: its length, then its bytes.
    void add(std::string_view text) {
        add(static_cast<std::uint64_t>(text.size()));
        for (const char c : text) {
            hash_ ^= static_cast<unsigned char>(c);
            hash_ *= 0x100000001b3ULL;
        }
    }
    /// Adds every ball, in order.
    void add(const std::vector<Ball>& balls) {
        add(static_cast<std::uint64_t>(balls.size()));
        for (const Ball& b : balls)
            add(b);
    }
    /// The digest so far.
    constexpr std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

/// A digest as 16 lower-case hexadecimal digits.
inline std::string digest_hex(std::uint64_t digest) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i, digest >>= 4)
        out[static_cast<std::size_t>(i)] = digits[digest & 0xF];
    return out;
}

} // namespace termpool
