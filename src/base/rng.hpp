// Host-side seed derivation: the kernels' generator (cl/core/rng.h, one
// definition for both), so each purpose of a render gets its own streams.
#pragma once
#include "rng.h"

#include <cstdint>

namespace smallmlt {

// Seed of the streams of one purpose (a small constant) under a user seed.
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t purpose) {
    return rng_derive(seed, purpose);
}

} // namespace smallmlt
