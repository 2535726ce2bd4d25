/* A chain's small step on the film (doc/design.md, "Small steps on the
 * film"), one definition for the host (C++17) and the kernels (OpenCL C
 * 1.2). A film number's largest small step is 2^-6 of its unit square, the
 * n pixels of its tile along the axis, times a whole stretch: n x stretch /
 * 64 pixels. */
#ifndef SMALLMLT_FILM_STEP_H
#define SMALLMLT_FILM_STEP_H

#ifndef __OPENCL_VERSION__
#include "shared_types.h"
#endif

/* The stretch that makes the largest step about `pixels` pixels on n:
 * pixels x 64 / n, rounded (0 for 0 pixels). */
inline u32 film_step_pixels_stretch(u32 pixels, u32 n) {
    return (pixels * 64u + n / 2u) / n;
}

/* The stretch in a tile of n pixels along the axis, `film_over_tile` times
 * narrower than the film (1 on the whole film). `step` pixels asked for
 * (--film-step PIXELS), at least a stretch of one; with `step` 0, `share`
 * times the film over the tile, so that a step moves as many pixels in a
 * tile as on the film, `share` 64ths of the film, and at least about
 * `floor` pixels (--film-step auto: share 2, floor 4; --film-step film:
 * share 1, floor 0). */
inline u32 film_step_stretch(u32 n, u32 film_over_tile, u32 step, u32 share, u32 floor) {
    if (step) {
        u32 asked = film_step_pixels_stretch(step, n);
        return asked > 1u ? asked : 1u;
    }
    u32 floored = film_step_pixels_stretch(floor, n);
    u32 shared = share * film_over_tile;
    return floored > shared ? floored : shared;
}

/* The largest step in pixels of `stretch` on n pixels: n x stretch / 64,
 * rounded, at least 1. */
inline u32 film_step_pixels_of(u32 n, u32 stretch) {
    u32 pixels = (n * stretch + 32u) / 64u;
    return pixels > 1u ? pixels : 1u;
}

#endif
