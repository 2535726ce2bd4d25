/* Sample source for ordinary Monte Carlo: number `dim` of a path is drawn
 * from the counter-based stream of the path's key and cut to the slot's
 * stored precision, so an MLT chain regenerated from the same key sees the
 * same path. The path code reads numbers only through smp_draw. */

typedef struct {
    ulong key;
} SampleSource;

inline SampleSource smp_omc(ulong key) {
    SampleSource s;
    s.key = key;
    return s;
}

/* Integer in [0, 2^bits), bits <= 24. */
inline uint smp_draw(SampleSource* s, uint dim, uint bits) {
    return rng_u32(s->key, dim) >> (32u - bits);
}
