/* Sample source for path tracing with low-discrepancy numbers: padded,
 * shuffled and Owen-scrambled 2D Sobol points (Burley 2020, "Practical
 * hash-based Owen scrambling"). A path's numbers are grouped in pairs: the
 * film position, and within each bounce its slots (0,1), (2,3), ... of
 * layout.cl (the BSDF pair, the light-sample pair, ...). Each pair of each
 * pixel takes the first two Sobol dimensions, a (0,2)-sequence, at a
 * shuffled index and with scrambled values, so:
 *  - the first 2^m samples of a pixel are a (0,m,2)-net in every pair: each
 *    elementary interval of area 2^-m holds one point;
 *  - different pairs are decorrelated by their own index shuffle (padding);
 *  - every number is uniform on its slot's grid, so the estimator stays
 *    unbiased, and a seed fixes the image.
 * Not used by MLT or burn-in: a large step must regenerate the path of its
 * key, which only the random stream (sample_omc.cl) does. */

typedef struct {
    ulong key;  /* the pixel's scrambling key */
    uint index; /* sample index within the pixel */
} SampleSource;

inline SampleSource smp_pixel(ulong seed, uint pixel, uint sample) {
    SampleSource s;
    s.key = rng_key(seed, pixel, 0xFFFFFFFFu);
    s.index = sample;
    return s;
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

/* The pair a number belongs to (0: the film) and its place in it. */
inline uint smp_pair(uint bounce, LayoutSlot at, uint* component) {
    if (at.dim < LAYOUT_CAMERA_DIMS) {
        *component = at.dim;
        return 0u;
    }
    uint slot = at.dim - LAYOUT_CAMERA_DIMS - bounce * LAYOUT_BOUNCE_DIMS;
    *component = slot & 1u;
    return 1u + bounce * ((LAYOUT_BOUNCE_DIMS + 1u) / 2u) + (slot >> 1);
}

inline float smp_uniform(SampleSource* s, uint bounce, LayoutSlot at) {
    uint component;
    uint pair = smp_pair(bounce, at, &component);
    uint i = sobol_owen(s->index, rng_u32(s->key, 3u * pair));
    uint v = component ? sobol_dim1(i) : sobol_dim0(i);
    v = sobol_owen(v, rng_u32(s->key, 3u * pair + 1u + component));
    return layout_unit(v >> (32u - at.bits), at.bits);
}
