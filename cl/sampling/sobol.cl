/* Padded, shuffled and Owen-scrambled 2D Sobol points (Burley 2020,
 * "Practical hash-based Owen scrambling"), per pixel: pair `pair` of sample
 * `index` of a pixel takes the first two Sobol dimensions, a
 * (0,2)-sequence, at an index shuffled by its own scramble and with its
 * values scrambled, all keyed by the pixel's key. So the first 2^m samples
 * of a pixel are a (0,m,2)-net in every pair, different pairs are
 * decorrelated, and every value is uniform. Used by the path tracer's
 * sample source (sample_sobol.cl) and by the burn-in's film positions
 * (burnin_film.cl), which are the first samples of the same sequences. */

/* The scrambling key of pixel `pixel` under a seed. */
inline ulong sobol_pixel_key(ulong seed, uint pixel) {
    return rng_key(seed, pixel, 0xFFFFFFFFu);
}

inline uint sobol_reverse_bits(uint x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00FF00FFu) << 8) | ((x >> 8) & 0x00FF00FFu);
    x = ((x & 0x0F0F0F0Fu) << 4) | ((x >> 4) & 0x0F0F0F0Fu);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
}

/* Nested uniform (Owen) scramble of the binary fraction x / 2^32: bit i
 * (from the top) is flipped by a hash of the seed and the bits above it.
 * On bit-reversed x that is a hash in which each bit depends only on lower
 * bits: additions and products with even constants (Laine and Karras 2011,
 * with Burley's constants). A bijection that maps every aligned block of
 * 2^k fractions onto an aligned block. */
inline uint sobol_owen(uint x, uint seed) {
    x = sobol_reverse_bits(x);
    x += seed;
    x ^= x * 0x6C50B47Cu;
    x ^= x * 0xB82F1E52u;
    x ^= x * 0xC7AFE638u;
    x ^= x * 0x8D22F6E6u;
    return sobol_reverse_bits(x);
}

/* Sobol dimension 0 (van der Corput) and 1 of index i, as 32-bit fractions.
 * Dimension 1's direction numbers are v_1 = 2^31, v_{k+1} = v_k ^ (v_k >> 1)
 * (Pascal's triangle mod 2). */
inline uint sobol_dim0(uint i) {
    return sobol_reverse_bits(i);
}

inline uint sobol_dim1(uint i) {
    uint r = 0u;
    for (uint v = 0x80000000u; i != 0u; i >>= 1, v ^= v >> 1)
        if (i & 1u) r ^= v;
    return r;
}

/* Component `component` (0 or 1) of pair `pair` of sample `index` of the
 * pixel keyed `key`, as a 32-bit fraction. */
inline uint sobol_value(ulong key, uint pair, uint index, uint component) {
    uint i = sobol_owen(index, rng_u32(key, 3u * pair));
    uint v = component ? sobol_dim1(i) : sobol_dim0(i);
    return sobol_owen(v, rng_u32(key, 3u * pair + 1u + component));
}
