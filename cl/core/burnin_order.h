/* The order in which MLT's burn-in takes the pixels' Sobol samples
 * (BurnInFilm, cl/core/shared_types.h), one definition for the host (C++17)
 * and the kernels (OpenCL C 1.2). Burn-in sample g, with h = g + offset,
 * lies in pixel ((h mod P) step) mod P of the P pixels and is number
 * floor(h / P) - [h mod P < offset] of that pixel's sequence, so that a
 * pixel's samples are numbered 0, 1, 2, ... without a gap: the first 2^m
 * stay a net (cl/sampling/sobol.cl), and the path tracer of the split's
 * OMC part goes on with each sequence where the burn-in left it
 * (LatePixels). */
#ifndef SMALLMLT_BURNIN_ORDER_H
#define SMALLMLT_BURNIN_ORDER_H

#ifndef __OPENCL_VERSION__
#include "shared_types.h"
#endif

/* The pixel of burn-in sample g. */
inline u32 burnin_order_pixel(const BurnInFilm* f, u32 pixels, u64 g) {
    return (u32)((((g + (u64)f->offset) % pixels) * (u64)f->step) % pixels);
}

/* The number of burn-in sample g in its pixel's sequence. */
inline u32 burnin_order_index(const BurnInFilm* f, u32 pixels, u64 g) {
    u64 h = g + (u64)f->offset;
    return (u32)(h / pixels) - (u32)(h % pixels < (u64)f->offset);
}

/* 1 if pixel `pixel` begins its sequence one number later (LatePixels). */
inline u32 burnin_order_late(const LatePixels* l, u32 pixels, u32 pixel) {
    u64 residue = ((u64)pixel * (u64)l->inverse) % pixels;
    return (u32)((residue + pixels - (u64)l->offset) % pixels < (u64)l->count);
}

#endif
