/* The per-scene layout of primary-sample numbers (src/scene/sample_layout.cpp
 * derives it and defines LAYOUT_*, SLOT_* and the layout_slot_* tables).
 * Numbers 0 and 1 place the sample on the film (LAYOUT_CAMERA_BITS each);
 * each bounce then owns LAYOUT_BOUNCE_DIMS numbers, high-precision slots
 * first. Slots a scene does not need have the index -1. Bit offsets are those
 * of the packed chain state (cl/sampling/pss.cl): a contiguous bit stream. */

/* Where one number lives: its index in the vector (the random stream's
 * dimension), its offset in the packed bit stream and its stored bits. */
typedef struct {
    uint dim;
    uint bit_offset;
    uint bits;
} LayoutSlot;

/* Number i (0 or 1) of the film position. */
inline LayoutSlot layout_film(uint i) {
    LayoutSlot s;
    s.dim = i;
    s.bit_offset = i * LAYOUT_CAMERA_BITS;
    s.bits = LAYOUT_CAMERA_BITS;
    return s;
}

#if LAYOUT_BOUNCE_DIMS > 0
/* Slot `slot` (>= 0) of bounce `bounce`. */
inline LayoutSlot layout_slot(uint bounce, int slot) {
    LayoutSlot s;
    s.dim = LAYOUT_CAMERA_DIMS + bounce * LAYOUT_BOUNCE_DIMS + (uint)slot;
    s.bit_offset = LAYOUT_CAMERA_DIMS * LAYOUT_CAMERA_BITS + bounce * LAYOUT_BOUNCE_BITS +
                   layout_slot_offset[slot];
    s.bits = layout_slot_bits[slot];
    return s;
}
#endif

/* The low-discrepancy pair number `at` of bounce `bounce` belongs to, and
 * its component in it: pair 0 is the film position, and each bounce's slots
 * (0,1), (2,3), ... (the BSDF pair, the light-sample pair, ...) are pairs
 * 1 + bounce * ceil(LAYOUT_BOUNCE_DIMS / 2) onwards (sobol.cl). */
inline uint layout_pair(uint bounce, LayoutSlot at, uint* component) {
    if (at.dim < LAYOUT_CAMERA_DIMS) {
        *component = at.dim;
        return 0u;
    }
    uint slot = at.dim - LAYOUT_CAMERA_DIMS - bounce * LAYOUT_BOUNCE_DIMS;
    *component = slot & 1u;
    return 1u + bounce * ((LAYOUT_BOUNCE_DIMS + 1u) / 2u) + (slot >> 1);
}

/* v / 2^bits, exact in float for bits <= 24; 2^-bits is built from its
 * exponent bits, as bits is often not a compile-time constant. */
inline float layout_unit(uint v, uint bits) {
    return (float)v * as_float((127u - bits) << 23);
}

/* Probability p rounded up to the grid of a `bits`-wide number, so that the
 * event v < p_q * 2^bits has probability exactly p_q for uniform v. */
inline float layout_quantize_prob(float p, uint bits) {
    float scale = (float)(1u << bits);
    return fmin(1.0f, ceil(p * scale) / scale);
}
