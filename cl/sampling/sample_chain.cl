/* Sample source of a Markov chain in primary sample space (Kelemen et al.
 * 2002): the path reads the numbers of a proposal y made from the chain's
 * stored state x. Proposals are lazy (Frolov and Galaktionov, section 3.2):
 * number `dim` of y is computed when the path asks for it, from x's stored
 * number and the counter-based stream `key`, and cut to the slot's precision,
 * so the path evaluated is exactly the path stored if y is accepted
 * (smp_commit regenerates y from the same key; nothing else is stored).
 *
 * Only the numbers of x's first `alive` bounces are live state; a proposal
 * draws later numbers afresh, as a large step would. This keeps the proposal
 * symmetric when paths change length: the numbers a shorter path leaves
 * behind are never mutated from, so they need not be stored or cleared. */

#define SMP_REPLAY 0u /* y = x: evaluate the stored state */
#define SMP_SMALL 1u  /* perturb every live number */
#define SMP_LARGE 2u  /* draw every number afresh: the film numbers `film`, the rest of `key` */
#define SMP_START 3u  /* a burn-in sample: Sobol numbers, the film position `film` */

typedef struct {
    __global uint* state;
    uint chain;
    uint stride; /* number of chains */
    ulong key;   /* SMP_START: the pixel's Sobol scrambling key */
    uint index;  /* SMP_START: the sample's index in the pixel's sequence */
    uint mode;
    uint alive;    /* live bounces of x */
    uint2 film;    /* SMP_START, SMP_LARGE: the film numbers (LAYOUT_CAMERA_BITS wide) */
    FilmTile tile; /* the chain's stratum (strata.cl): its film numbers are the tile's */
} SampleSource;

inline SampleSource smp_chain(__global uint* state, uint chain, uint stride, ulong key, uint mode,
                              uint alive, FilmTile tile) {
    SampleSource s;
    s.state = state;
    s.chain = chain;
    s.stride = stride;
    s.key = key;
    s.index = 0u;
    s.mode = mode;
    s.alive = alive;
    s.film = (uint2)(0u);
    s.tile = tile;
    return s;
}

/* Burn-in sample b (burnin_film.cl) at the film numbers `film` of tile
 * `tile` (b.film, or strata_local of it for a chain's own tile): every other
 * number is Sobol sample b.index of its pixel's sequence, as the OMC part's
 * path tracer reads it (sample_sobol.cl). */
inline SampleSource smp_chain_start(__global uint* state, uint chain, uint stride, BurnInSample b,
                                    uint2 film, FilmTile tile) {
    SampleSource s = smp_chain(state, chain, stride, b.key, SMP_START, 0u, tile);
    s.index = b.index;
    s.film = film;
    return s;
}

/* Number `at` of a burn-in sample, as a 32-bit fraction: its pair's Sobol
 * number. */
inline uint smp_start_u32(const SampleSource* s, uint bounce, LayoutSlot at) {
    uint component;
    uint pair = layout_pair(bounce, at, &component);
    return sobol_value(s->key, pair, s->index, component);
}

/* Small step of a `bits`-wide number, in grid steps (Kelemen et al. 2002):
 * 2^(bits - scale) * 2^(-4u), u = (r & 0x7FFFFFFF) / 2^31, rounded to nearest
 * and at least 1: exponentially distributed in [2^-(scale + 4), 2^-scale] of
 * the unit interval (Kelemen's scale is 6). r's top bit gives the sign,
 * independent of the size, so the step is symmetric. Integer only, so a lazy
 * evaluation and the commit that regenerates the number get the same step
 * whatever a compiler does with float expressions (contraction, reordering).
 * 4u = whole + f with f in Q29; 2^-f in Q31 is a degree-5 polynomial
 * (Chebyshev interpolant, relative error below 2^-23, so within 0.53 steps of
 * the exact exponential for bits - scale <= 18), in Horner form with every
 * partial result positive. For scale + 4 <= bits <= scale + 30. */
inline uint smp_small_delta(uint r, uint bits, uint scale) {
    uint t = r & 0x7FFFFFFFu;
    uint whole = t >> 29;
    ulong f = (ulong)(t & 0x1FFFFFFFu);
    ulong p = 19776564ul - ((2033403ul * f) >> 29);
    p = 118751808ul - ((p * f) >> 29);
    p = 515780381ul - ((p * f) >> 29);
    p = 1488513547ul - ((p * f) >> 29);
    p = 2147483527ul - ((p * f) >> 29);
    uint shift = 31u + scale + whole - bits; /* p * 2^(bits - scale - whole) / 2^31 */
    return max((uint)((p + (1ul << (shift - 1u))) >> shift), 1u);
}

/* How many times longer a film number's small step is than another
 * number's (cl/core/film_step.h), in the chain's tile: MLT_FILM_STEP pixels
 * asked for, or MLT_FILM_STEP_SHARE times the film over the tile with a
 * floor of MLT_FILM_STEP_FLOOR pixels (0: none). */
inline uint smp_film_stretch(const SampleSource* s, uint dim) {
    uint n = dim ? s->tile.h : s->tile.w;
    uint film_over_tile = (uint)(1.0f / (dim ? s->tile.sy : s->tile.sx) + 0.5f);
    return film_step_stretch(n, film_over_tile, MLT_FILM_STEP, MLT_FILM_STEP_SHARE,
                             MLT_FILM_STEP_FLOOR);
}

/* The small step of the number in slot `at` for stream number r, in grid
 * steps of a `bits`-wide slot: a film number's is Kelemen's (scale 6) times
 * its stretch, a path number's has the largest step 2^-MLT_PATH_STEP_LOG2
 * (--path-step). */
inline uint smp_step_of(const SampleSource* s, LayoutSlot at, uint r, uint bits) {
    if (at.dim < LAYOUT_CAMERA_DIMS)
        return smp_small_delta(r, bits, 6u) * smp_film_stretch(s, at.dim);
    return smp_small_delta(r, bits, MLT_PATH_STEP_LOG2);
}

#ifndef PSS_FLOAT32

/* Integer value v of a `bits`-wide number moved by `delta` grid steps, up
 * where stream number r's top bit is set, wrapping around the slot's grid. */
inline uint smp_perturb_bits(uint v, uint r, uint bits, uint delta) {
    return ((r >> 31) ? v + delta : v - delta) & ((1u << bits) - 1u);
}

/* The proposal's number in slot `at`, owned by bounce `bounce`, as an
 * integer below 2^bits: the path reads it (smp_propose) and a commit stores
 * it, one value computed the same way both times. */
inline uint smp_propose_bits(const SampleSource* s, uint bounce, LayoutSlot at) {
    if (s->mode >= SMP_LARGE && at.dim < LAYOUT_CAMERA_DIMS) return at.dim ? s->film.y : s->film.x;
    if (s->mode == SMP_START) return smp_start_u32(s, bounce, at) >> (32u - at.bits);
    uint r = rng_u32(s->key, at.dim);
    bool live = at.dim < LAYOUT_CAMERA_DIMS || bounce < s->alive;
    if (s->mode >= SMP_LARGE || !live) return r >> (32u - at.bits);
    uint v = pss_read_bits(s->state, s->chain, s->stride, at.bit_offset, at.bits);
    return s->mode == SMP_REPLAY ? v
                                 : smp_perturb_bits(v, r, at.bits, smp_step_of(s, at, r, at.bits));
}

inline float smp_propose(const SampleSource* s, uint bounce, LayoutSlot at) {
    return layout_unit(smp_propose_bits(s, bounce, at), at.bits);
}

/* Puts the proposal's number in slot `at` to the chain's writer. */
inline void smp_commit_slot(const SampleSource* s, PssWriter* w, uint bounce, LayoutSlot at) {
    pss_put(w, s->state, s->chain, s->stride, at.bits, smp_propose_bits(s, bounce, at));
}

#else

/* The float32 reference: 24-bit numbers moved in float arithmetic by
 * `delta` grid steps of a 24-bit slot, wrapping around [0, 1). */
inline float smp_perturb(float x, uint r, uint delta) {
    float d = layout_unit(delta, 24u);
    float y = (r >> 31) ? x + d : x - d;
    y -= floor(y);
    return y < 1.0f ? y : 0.0f;
}

inline float smp_propose(const SampleSource* s, uint bounce, LayoutSlot at) {
    if (s->mode >= SMP_LARGE && at.dim < LAYOUT_CAMERA_DIMS)
        return layout_unit(at.dim ? s->film.y : s->film.x, LAYOUT_CAMERA_BITS);
    if (s->mode == SMP_START)
        return (float)(smp_start_u32(s, bounce, at) >> 8) * (1.0f / 16777216.0f);
    uint r = rng_u32(s->key, at.dim);
    bool live = at.dim < LAYOUT_CAMERA_DIMS || bounce < s->alive;
    if (s->mode >= SMP_LARGE || !live) return (float)(r >> 8) * (1.0f / 16777216.0f);
    float x = pss_load(s->state, s->chain, s->stride, at);
    return s->mode == SMP_REPLAY ? x : smp_perturb(x, r, smp_step_of(s, at, r, 24u));
}

inline void smp_commit_slot(const SampleSource* s, PssWriter* w, uint bounce, LayoutSlot at) {
    pss_store(s->state, s->chain, s->stride, at, smp_propose(s, bounce, at));
}

#endif

inline float smp_uniform(SampleSource* s, uint bounce, LayoutSlot at) {
    return smp_propose(s, bounce, at);
}

/* Where the proposal lies on the film: its film numbers read in its tile. */
inline FilmPoint smp_film_point(SampleSource* s, const Frame* frame) {
    float u = smp_uniform(s, 0u, layout_film(0u)), v = smp_uniform(s, 0u, layout_film(1u));
    return strata_point(&s->tile, frame, u, v);
}

/* Makes the proposal the chain's state: stores its numbers for the film and
 * the first `bounces` bounces, in bit-stream order, a word at a time. */
inline void smp_commit(const SampleSource* s, uint bounces) {
    PssWriter w = pss_writer();
    for (uint i = 0; i < LAYOUT_CAMERA_DIMS; ++i)
        smp_commit_slot(s, &w, 0u, layout_film(i));
#if LAYOUT_BOUNCE_DIMS > 0
    for (uint b = 0; b < bounces; ++b)
        for (int slot = 0; slot < (int)LAYOUT_BOUNCE_DIMS; ++slot)
            smp_commit_slot(s, &w, b, layout_slot(b, slot));
#endif
    pss_finish(&w, s->state, s->chain, s->stride);
}
