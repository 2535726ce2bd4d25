/* Sample source for path tracing with low-discrepancy numbers (sobol.cl).
 * A path's numbers are grouped in pairs: the film position, and within each
 * bounce its slots (0,1), (2,3), ... of layout.cl (the BSDF pair, the
 * light-sample pair, ...; layout_pair); each pair is one Sobol pair of the
 * pixel's sequence, cut to its slot's grid, so the estimator stays unbiased
 * and a seed fixes the image. MLT's burn-in samples read the same numbers
 * (sample_chain.cl, SMP_START); its large steps cannot, as they must
 * regenerate the path of their key, which only the random stream
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

inline float smp_uniform(SampleSource* s, uint bounce, LayoutSlot at) {
    uint component;
    uint pair = layout_pair(bounce, at, &component);
    uint v = sobol_value(s->key, pair, s->index, component);
    return layout_unit(v >> (32u - at.bits), at.bits);
}
