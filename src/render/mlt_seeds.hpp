// The streams of an MLT render, each a seed derived from the render's:
// the OMC samples of burn-in and of fresh starts, the burn-in's picks, the
// steps, the split's per-pixel samples and the burn-in's film offset.
#pragma once
#include "base/rng.hpp"

#include <cstdint>

namespace smallmlt {

enum class MltStream : std::uint64_t { Omc = 1, Pick = 2, Step = 3, Pixel = 4, FilmOffset = 5 };

inline std::uint64_t mlt_seed(std::uint64_t seed, MltStream s) {
    return derive_seed(seed, std::uint64_t(s));
}

} // namespace smallmlt
