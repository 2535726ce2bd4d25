/* Burn-in samples of MLT (Frolov and Galaktionov, section 3.1): not uniform
 * random, as a large step's, but the first Sobol samples of each pixel's
 * sequence in the OMC part's path tracer (sobol.cl, sample_sobol.cl), spread
 * over the pixels in the order of cl/core/burnin_order.h. The pixels get
 * equal numbers of samples, give or take one, and the OMC part goes on with
 * each pixel's sequence after them, so the burn-in's paths add to the split's
 * OMC part as path-traced samples do (src/render/burn_in.hpp). The random
 * offset makes every pixel equally likely to get the extra samples, so b,
 * their mean, stays unbiased. All of a sample's numbers are its pixel's
 * Sobol numbers (sample_chain.cl, SMP_START), the film position cut to the
 * film numbers' grid within the pixel, the others to their slots'. */

/* Burn-in sample g: film numbers, the scrambling key of its pixel's
 * sequence and its index there. */
typedef struct {
    uint2 film;
    ulong key;
    uint index;
} BurnInSample;

/* The `bits`-wide film number in column (or row) x of n at fraction s / 2^32
 * of it: the grid values v with x <= v n / 2^bits < x + 1 are
 * ceil(x 2^bits / n) .. ceil((x + 1) 2^bits / n) - 1. */
inline uint burnin_film_number(uint x, uint n, uint s) {
    ulong lo = (((ulong)x << LAYOUT_CAMERA_BITS) + n - 1u) / n;
    ulong hi = (((ulong)(x + 1u) << LAYOUT_CAMERA_BITS) + n - 1u) / n;
    return (uint)(lo + (((hi - lo) * (ulong)s) >> 32));
}

/* Burn-in sample g. */
inline BurnInSample burnin_sample(const BurnInFilm* f, const Frame* frame, ulong g) {
    uint pixels = frame->width * frame->height;
    uint pixel = burnin_order_pixel(f, pixels, g);
    BurnInSample b;
    b.index = burnin_order_index(f, pixels, g);
    b.key = sobol_pixel_key(((ulong)f->seed_hi << 32) | (ulong)f->seed_lo, pixel);
    b.film = (uint2)(burnin_film_number(pixel % frame->width, frame->width,
                                        sobol_value(b.key, 0u, b.index, 0u)),
                     burnin_film_number(pixel / frame->width, frame->height,
                                        sobol_value(b.key, 0u, b.index, 1u)));
    return b;
}
