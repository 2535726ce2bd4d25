/* Film positions of the burn-in's OMC samples (Frolov and Galaktionov,
 * section 3.1): not uniform random, as a large step's, but the first Sobol
 * samples of each pixel's sequence in the OMC part's path tracer (sobol.cl),
 * spread over the pixels by BurnInFilm (cl/core/shared_types.h). The pixels get
 * equal numbers of samples, give or take one, and the OMC part goes on with
 * each pixel's sequence after them, so the burn-in's paths add to the split's
 * OMC part as path-traced samples do (src/render/burn_in.hpp). The random
 * offset makes every pixel equally likely to get the extra samples, so b,
 * their mean, stays unbiased. Every other number of the path comes from the
 * sample's key, as a large step's. */

/* The `bits`-wide film number in column (or row) x of n at fraction s / 2^32
 * of it: the grid values v with x <= v n / 2^bits < x + 1 are
 * ceil(x 2^bits / n) .. ceil((x + 1) 2^bits / n) - 1. */
inline uint burnin_film_number(uint x, uint n, uint s) {
    ulong lo = (((ulong)x << LAYOUT_CAMERA_BITS) + n - 1u) / n;
    ulong hi = (((ulong)(x + 1u) << LAYOUT_CAMERA_BITS) + n - 1u) / n;
    return (uint)(lo + (((hi - lo) * (ulong)s) >> 32));
}

/* The film numbers of burn-in sample g. */
inline uint2 burnin_film(const BurnInFilm* f, const Frame* frame, ulong g) {
    uint pixels = frame->width * frame->height;
    ulong h = g + (ulong)f->offset;
    uint pixel = (uint)(((h % pixels) * (ulong)f->step) % pixels);
    uint index = (uint)(h / pixels);
    ulong key = sobol_pixel_key(((ulong)f->seed_hi << 32) | (ulong)f->seed_lo, pixel);
    return (uint2)(burnin_film_number(pixel % frame->width, frame->width,
                                      sobol_value(key, 0u, index, 0u)),
                   burnin_film_number(pixel / frame->width, frame->height,
                                      sobol_value(key, 0u, index, 1u)));
}
