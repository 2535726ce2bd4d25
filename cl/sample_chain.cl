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
#define SMP_LARGE 2u  /* draw every number afresh: the OMC path of `key` */

/* Small-step offsets are exponentially distributed in [SMP_S1, SMP_S2] =
 * [1/1024, 1/64]: SMP_S2 * (SMP_S1 / SMP_S2)^u = 2^-6 * 2^(-4u). */
#define SMP_S2 (1.0f / 64.0f)
#define SMP_LOG2_S1_OVER_S2 (-4.0f)

typedef struct {
    __global uint* state;
    uint chain;
    uint stride; /* number of chains */
    ulong key;
    uint mode;
    uint alive; /* live bounces of x */
} SampleSource;

inline SampleSource smp_chain(__global uint* state, uint chain, uint stride, ulong key, uint mode,
                              uint alive) {
    SampleSource s;
    s.state = state;
    s.chain = chain;
    s.stride = stride;
    s.key = key;
    s.mode = mode;
    s.alive = alive;
    return s;
}

/* Magnitude of a small step from a stream number whose top bit gives the
 * sign: SMP_S2 * 2^e, e = -4u. 2^e is 2^floor(e) from exponent bits times a
 * quadratic in the fraction (exact at both ends, within 0.3% between), so
 * the range [SMP_S1, SMP_S2] is kept exactly. Any fixed function of u keeps
 * the step symmetric; this one costs a few instructions on any device. */
inline float smp_small_offset(uint r) {
    float u = (float)(r & 0x7FFFFFFFu) * (1.0f / 2147483648.0f);
    float e = SMP_LOG2_S1_OVER_S2 * u;
    float whole = floor(e);
    float f = e - whole;
    float two_f = 1.0f + f * (0.6565f + 0.3435f * f);
    return SMP_S2 * two_f * as_float(((int)whole + 127) << 23);
}

#ifndef PSS_FLOAT32

inline float smp_fresh(uint r, uint bits) {
    return layout_unit(r >> (32u - bits), bits);
}

/* x moved by the small-step offset on the slot's grid, wrapping around [0,1). */
inline float smp_perturb(float x, uint r, uint bits) {
    float scale = (float)(1u << bits);
    uint delta = max(1u, (uint)(smp_small_offset(r) * scale + 0.5f));
    uint v = (uint)(x * scale);
    uint y = (r >> 31) ? v + delta : v - delta;
    return layout_unit(y & ((1u << bits) - 1u), bits);
}

#else

inline float smp_fresh(uint r, uint bits) {
    return (float)(r >> 8) * (1.0f / 16777216.0f);
}

inline float smp_perturb(float x, uint r, uint bits) {
    float d = smp_small_offset(r);
    float y = (r >> 31) ? x + d : x - d;
    if (y < 0.0f) y += 1.0f;
    if (y >= 1.0f) y -= 1.0f;
    return y < 1.0f ? y : 0.0f;
}

#endif

/* The proposal's number in slot `at`, owned by bounce `bounce`. */
inline float smp_propose(const SampleSource* s, uint bounce, LayoutSlot at) {
    uint r = rng_u32(s->key, at.dim);
    bool live = at.dim < LAYOUT_CAMERA_DIMS || bounce < s->alive;
    if (s->mode == SMP_LARGE || !live) return smp_fresh(r, at.bits);
    float x = pss_load(s->state, s->chain, s->stride, at);
    return s->mode == SMP_REPLAY ? x : smp_perturb(x, r, at.bits);
}

inline float smp_uniform(SampleSource* s, uint bounce, LayoutSlot at) {
    return smp_propose(s, bounce, at);
}

inline void smp_commit_slot(const SampleSource* s, uint bounce, LayoutSlot at) {
    pss_store(s->state, s->chain, s->stride, at, smp_propose(s, bounce, at));
}

/* Makes the proposal the chain's state: stores its numbers for the film and
 * the first `bounces` bounces. */
inline void smp_commit(const SampleSource* s, uint bounces) {
    for (uint i = 0; i < LAYOUT_CAMERA_DIMS; ++i)
        smp_commit_slot(s, 0u, layout_film(i));
#if LAYOUT_BOUNCE_DIMS > 0
    for (uint b = 0; b < bounces; ++b)
        for (int slot = 0; slot < (int)LAYOUT_BOUNCE_DIMS; ++slot)
            smp_commit_slot(s, b, layout_slot(b, slot));
#endif
}
