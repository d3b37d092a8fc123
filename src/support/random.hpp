#pragma once
/// \file
/// A small deterministic random number generator (SplitMix64). It is a value: copy it to fork a
/// stream, and the same seed gives the same numbers on every platform.

#include <cstdint>

namespace termpool {

/// SplitMix64 generator.
class Random {
public:
    /// A generator seeded with `seed`.
    explicit Random(std::uint64_t seed) : state_(seed) {}
    /// Next 64 random bits.
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1), with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform integer in [0, n), n > 0.
    std::uint64_t below(std::uint64_t n) { return next() % n; }

    /// The state: `Random(state())` continues this stream.
    std::uint64_t state() const { return state_; }

private:
    std::uint64_t state_;
};

/// For a stream kept as its bare state (the players keep it so: their public headers do not
/// show this class): a copy of the stream as it stands, and `state` moved on by one number.
inline Random fork_stream(std::uint64_t& state) {
    const Random fork(state);
    Random moved(state);
    moved.next();
    state = moved.state();
    return fork;
}

/// Calls `use` with the stream kept in `state` and keeps where it got to.
template <class Use> auto with_stream(std::uint64_t& state, Use&& use) {
    Random stream(state);
    auto result = use(stream);
    state = stream.state();
    return result;
}

} // namespace termpool
