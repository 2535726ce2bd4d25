/* The per-scene layout of primary-sample numbers (src/sample_layout.cpp
 * derives it and defines LAYOUT_*, SLOT_*). Numbers 0 and 1 place the sample
 * on the film; each bounce then owns LAYOUT_BOUNCE_DIMS numbers, high-precision
 * slots first. Slots a scene does not need have the index -1. */

inline uint layout_dim(uint bounce, int slot) {
    return LAYOUT_CAMERA_DIMS + bounce * LAYOUT_BOUNCE_DIMS + (uint)slot;
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
