/* Counter-based random numbers: every number is a pure function of a 64-bit
 * stream key and a dimension index, so any number of any stream can be
 * regenerated at any time without storing it. The mixer is SplitMix64's
 * finalizer; a stream's numbers are SplitMix64's sequence started at its key. */

inline ulong rng_mix64(ulong z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
    return z ^ (z >> 31);
}

/* Key of the stream (a, b) under a seed. mix64 is a bijection, so distinct
 * (a, b) give distinct keys for one seed. */
inline ulong rng_key(ulong seed, uint a, uint b) {
    return rng_mix64(seed + rng_mix64(((ulong)a << 32) | (ulong)b));
}

/* Number `dim` of stream `key`, as 32 uniformly distributed bits. */
inline uint rng_u32(ulong key, uint dim) {
    return (uint)(rng_mix64(key + (ulong)(dim + 1u) * 0x9E3779B97F4A7C15UL) >> 32);
}
