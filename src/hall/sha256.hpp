#pragma once
/// \file
/// SHA-256 as FIPS 180-4 defines it, written out here so that the hall needs no crypto
/// library: the state files keep the SHA-256 of each seat token, which nobody who reads them
/// can turn back into a token. Plus the comparison of two digests that takes as long whatever
/// bytes differ.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace termpool::hall {

/// A SHA-256 digest: 32 bytes.
using Sha256Digest = std::array<std::uint8_t, 32>;

/// SHA-256 fed piece by piece: `update` as often as needed, then `finish` once.
class Sha256 {
public:
    Sha256();
    /// Appends `data` to the message.
    void update(std::string_view data);
    /// The digest of everything appended; the value is spent afterwards (reset it to reuse).
    Sha256Digest finish();
    /// Starts a new, empty message.
    void reset();

private:
    void compress(const std::uint8_t* block);

    std::array<std::uint32_t, 8> state_;
    std::array<std::uint8_t, 64> block_{};
    std::size_t used_ = 0;     // bytes waiting in block_
    std::uint64_t length_ = 0; // bytes of the message so far
};

/// The SHA-256 digest of `data`.
Sha256Digest sha256(std::string_view data);

/// The SHA-256 digest of `data` as 64 lowercase hex digits.
std::string sha256_hex(std::string_view data);

/// True when `a` and `b` are the same text. The time it takes depends on their lengths only,
/// not on where they differ, so that comparing a guess with a secret's digest tells nothing
/// about how much of it was right.
bool same_digest(std::string_view a, std::string_view b);

} // namespace termpool::hall
