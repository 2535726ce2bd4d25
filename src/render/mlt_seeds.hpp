// The streams of an MLT render, each a seed derived from the render's: the
// burn-in's picks, the steps, the pixels' Sobol sequences (the burn-in's
// samples and the split's OMC part), the burn-in's film offset, the
// rounding of the restarts' samples on the film and the emitters' points
// sampled from the eye.
#pragma once
#include "base/rng.hpp"

#include <cstdint>

namespace smallmlt {

enum class MltStream : std::uint64_t {
    Pick = 2,
    Step = 3,
    Pixel = 4,
    FilmOffset = 5,
    RestartSplat = 6, // the film's rounding of the restarts' samples
    EmissionSeen = 7  // the emitters' points of mlt_emission_seen
};

inline std::uint64_t mlt_seed(std::uint64_t seed, MltStream s) {
    return derive_seed(seed, std::uint64_t(s));
}

} // namespace smallmlt
