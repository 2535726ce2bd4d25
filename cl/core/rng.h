/* Counter-based random numbers, one definition for the host (C++17) and the
 * kernels (OpenCL C 1.2): every number is a pure function of a 64-bit
 * stream key and a dimension index, so any number of any stream can be
 * regenerated at any time without storing it. The mixer is SplitMix64's
 * finalizer; a stream's numbers are SplitMix64's sequence started at its key. */
#ifndef SMALLMLT_RNG_H
#define SMALLMLT_RNG_H

#ifndef __OPENCL_VERSION__
#include "shared_types.h"
#endif

inline u64 rng_mix64(u64 z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
    return z ^ (z >> 31);
}

/* Seed of the streams of one purpose (a small constant, or a round's index)
 * under a seed, so each purpose of a render gets its own streams. */
inline u64 rng_derive(u64 seed, u64 purpose) {
    return rng_mix64(seed * 0x9E3779B97F4A7C15UL + purpose);
}

/* Key of the stream (a, b) under a seed. mix64 is a bijection, so distinct
 * (a, b) give distinct keys for one seed. */
inline u64 rng_key(u64 seed, u32 a, u32 b) {
    return rng_mix64(seed + rng_mix64(((u64)a << 32) | (u64)b));
}

/* Number `dim` of stream `key`, as 32 uniformly distributed bits. */
inline u32 rng_u32(u64 key, u32 dim) {
    return (u32)(rng_mix64(key + (u64)(dim + 1u) * 0x9E3779B97F4A7C15UL) >> 32);
}

/* Number `dim` of stream `key`, as a float in [0, 1) (24 bits). */
inline float rng_unit(u64 key, u32 dim) {
    return (float)(rng_u32(key, dim) >> 8) * (1.0f / 16777216.0f);
}

#endif
