/* The per-scene layout of primary-sample numbers (src/sample_layout.cpp
 * derives it and defines LAYOUT_*, SLOT_* and the layout_slot_* tables).
 * Numbers 0 and 1 place the sample on the film (LAYOUT_CAMERA_BITS each);
 * each bounce then owns LAYOUT_BOUNCE_DIMS numbers, high-precision slots
 * first. Slots a scene does not need have the index -1. Bit offsets are those
 * of the packed chain state (cl/pss.cl): a contiguous bit stream. */

inline uint layout_dim(uint bounce, int slot) {
    return LAYOUT_CAMERA_DIMS + bounce * LAYOUT_BOUNCE_DIMS + (uint)slot;
}

/* Bounce that owns number `dim`; the film numbers count as bounce 0. */
inline uint layout_bounce_of(uint dim) {
#if LAYOUT_BOUNCE_DIMS > 0
    return dim < LAYOUT_CAMERA_DIMS ? 0u : (dim - LAYOUT_CAMERA_DIMS) / LAYOUT_BOUNCE_DIMS;
#else
    return 0u;
#endif
}

/* Stored bits of number `dim`. */
inline uint layout_bits(uint dim) {
#if LAYOUT_BOUNCE_DIMS > 0
    if (dim >= LAYOUT_CAMERA_DIMS)
        return layout_slot_bits[(dim - LAYOUT_CAMERA_DIMS) % LAYOUT_BOUNCE_DIMS];
#endif
    return LAYOUT_CAMERA_BITS;
}

/* Offset of number `dim` in the packed bit stream. */
inline uint layout_bit_offset(uint dim) {
#if LAYOUT_BOUNCE_DIMS > 0
    if (dim >= LAYOUT_CAMERA_DIMS) {
        uint d = dim - LAYOUT_CAMERA_DIMS;
        return LAYOUT_CAMERA_DIMS * LAYOUT_CAMERA_BITS + (d / LAYOUT_BOUNCE_DIMS) * LAYOUT_BOUNCE_BITS +
               layout_slot_offset[d % LAYOUT_BOUNCE_DIMS];
    }
#endif
    return dim * LAYOUT_CAMERA_BITS;
}

/* v / 2^bits: exact in float for bits <= 24. */
inline float layout_unit(uint v, uint bits) {
    return (float)v * (1.0f / (float)(1u << bits));
}

/* Probability p rounded up to the grid of a `bits`-wide number, so that the
 * event v < p_q * 2^bits has probability exactly p_q for uniform v. */
inline float layout_quantize_prob(float p, uint bits) {
    float scale = (float)(1u << bits);
    return fmin(1.0f, ceil(p * scale) / scale);
}
