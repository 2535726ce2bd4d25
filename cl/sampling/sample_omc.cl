/* Sample source for ordinary Monte Carlo: number `dim` of a path is drawn
 * from the counter-based stream of the path's key and cut to the slot's
 * stored precision, so an MLT chain regenerated from the same key sees the
 * same path. The path code reads numbers only through smp_uniform. */

typedef struct {
    ulong key;
} SampleSource;

inline SampleSource smp_omc(ulong key) {
    SampleSource s;
    s.key = key;
    return s;
}

/* The path's number in slot `at`: a multiple of 2^-bits in [0, 1) for the
 * slot's stored bits. `bounce` is the bounce that owns it (unused here). */
inline float smp_uniform(SampleSource* s, uint bounce, LayoutSlot at) {
    return layout_unit(rng_u32(s->key, at.dim) >> (32u - at.bits), at.bits);
}

/* Sample `sample` of pixel `pixel` for the path tracer: the stream of the
 * key (seed, pixel, sample). */
inline SampleSource smp_pixel(ulong seed, uint pixel, uint sample) {
    return smp_omc(rng_key(seed, pixel, sample));
}
