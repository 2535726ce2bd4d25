// The emission the camera sees directly, found by sampling the emitters from
// the eye (cl/kernels/mlt.cl, mlt_emission_seen) rather than by the burn-in's
// paths hitting it. Its second moment over the film bounds V_o of
// src/render/split.hpp from above, and equals it where the lights' images
// are far smaller than a pixel. There the burn-in's estimate of V_o rests on
// a handful of hits: water-spark's 1 cm light covers 3% of a pixel of its
// 160x90 film, and the burn-in's 2^19 paths hit it about once, or not at all.
#pragma once
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "render/burn_in.hpp"

#include <cstdint>
#include <functional>

namespace smallmlt {

struct EmissionSeen {
    double moment = 0;    // sum over pixels of E[Y^2] of one camera sample
    double luminance = 0; // Y of the brightest light seen
};

// The emission seen on the film but the OMC part's cells, and on those.
struct EmissionSeenParts {
    EmissionSeen film, cells;
};

// Samples of mlt_emission_seen in `program`, as many as `scratch` holds
// float4s, of the stream `seed`; a pixel is in a cell where `in_cell` says.
EmissionSeenParts emission_seen(const ClContext& cl, cl_program program, const SceneBuffers& scene,
                                const ClBuffer& scratch, std::uint64_t seed,
                                const std::function<bool(std::uint32_t)>& in_cell);

// V_o from the burn-in's samples `v`, but at least what one more sample of
// the brightest light seen would add to it (PixelVariance::one_sample), or
// the lights' moment where that is less: what the burn-in cannot tell from
// no hit at all.
double variance_with_emission_seen(const PixelVariance& v, const EmissionSeen& seen);

} // namespace smallmlt
