/* Sample source for path tracing with low-discrepancy numbers (sobol.cl).
 * A path's numbers are grouped in pairs: the film position, and within each
 * bounce its slots (0,1), (2,3), ... of layout.cl (the BSDF pair, the
 * light-sample pair, ...); each pair is one Sobol pair of the pixel's
 * sequence, cut to its slot's grid, so the estimator stays unbiased and a
 * seed fixes the image. Not used by MLT's chains: a large step must
 * regenerate the path of its key, which only the random stream
 * (sample_omc.cl) does. */

typedef struct {
    ulong key;  /* the pixel's scrambling key */
    uint index; /* sample index within the pixel */
} SampleSource;

inline SampleSource smp_pixel(ulong seed, uint pixel, uint sample) {
    SampleSource s;
    s.key = sobol_pixel_key(seed, pixel);
    s.index = sample;
    return s;
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
    uint v = sobol_value(s->key, pair, s->index, component);
    return layout_unit(v >> (32u - at.bits), at.bits);
}
