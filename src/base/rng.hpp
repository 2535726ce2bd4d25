// Host-side seed derivation, with the mixer of cl/core/rng.cl (SplitMix64's
// finalizer), so each purpose of a render gets its own independent streams.
#pragma once
#include <cstdint>

namespace smallmlt {

inline std::uint64_t rng_mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Seed of the streams of one purpose (a small constant) under a user seed.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t purpose) {
    return rng_mix64(seed * 0x9E3779B97F4A7C15ull + purpose);
}

} // namespace smallmlt
