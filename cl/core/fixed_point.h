/* b's fixed point, one definition for the host (C++17) and the kernels
 * (OpenCL C 1.2): a luminance sample of b (a burn-in sample's or a large
 * step's I) in MLT_B_FRAC_BITS fixed point, so that sums of them are exact
 * in any order. It is computed in float on both sides (a product by a
 * power of two, then one rounded addition), so the host's sum of the
 * burn-in and the device's of the large steps round alike. */
#ifndef SMALLMLT_FIXED_POINT_H
#define SMALLMLT_FIXED_POINT_H

#ifndef __OPENCL_VERSION__
#include "shared_types.h"
#endif

/* 0 unless lum > 0; at most MLT_B_MAX_SAMPLE. */
inline u64 fixed_b_sample(f32 lum) {
    if (!(lum > 0.0f)) return 0;
    f32 clamped = lum < MLT_B_MAX_SAMPLE ? lum : MLT_B_MAX_SAMPLE;
    f32 scaled = clamped * (f32)(1u << MLT_B_FRAC_BITS) + 0.5f;
    return (u64)scaled;
}

#endif
