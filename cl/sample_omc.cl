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

/* Number `dim` of the path: a multiple of 2^-bits in [0, 1) for the slot's
 * stored bits. */
inline float smp_uniform(SampleSource* s, uint dim) {
    uint bits = layout_bits(dim);
    return layout_unit(rng_u32(s->key, dim) >> (32u - bits), bits);
}
