/* A known target in place of the path, for the sampler tests
 * (test/test_mlt.cpp, test/test_chain_target.cpp). F is grey.
 *
 * Film: numbers 0 and 1 are the film position (x, y), with
 *   g(x, y) = (1 + 3x) (1 + sin^2(2 pi y)), and 0 where x < 1/4 and y < 1/4;
 * the film's pixels are the bins of a histogram. Without bounce slots (or at
 * depth 0) F = g and the state has no live bounce: the 2D target.
 *
 * With bounces, F = g(x, y) s(x, 64) [x < 15/16] prod_{k < L} e_k, a "path"
 * of L live bounces, 1 <= L <= frame->depth, where s(v, n) is 5/4 on the odd
 * stripes of n (floor(n v) odd) and 3/4 on the even ones. Bounce k reads every
 * number of its slots; e_k is the product of one factor per slot:
 * - SLOT_BSDF_U (24 bits), value a: h(a) = 0 for a < 1/8, above it
 *   (1/2 + a) times 3/2 on the odd stripes of 64 and 1/2 on the even ones;
 * - the continuation slot (SLOT_BSDF_CHOICE, else SLOT_RR; 16 bits), value c:
 *   p(c) = (3/4 + c/2) s(c, 128) [c < 15/16]; the path goes on to bounce
 *   k + 1 iff the phase of c in 32 stripes, frac(32 c), is below q(x) (q = 1/2
 *   on the left half of the film, x < 1/2, and 3/4 on the right) and
 *   k + 1 < depth;
 * - every other slot, value v: 3/4 + v/2.
 * `bounces` = L: exactly the bounces whose numbers were read, which
 * smp_commit then stores. Numbers of bounces >= L do not change F: under the
 * target they are uniform on their slot's grid, and a proposal must draw them
 * afresh. The stripes are about as wide as a small step is long (1/1024 to
 * 1/64), so small steps cross them all the time: paths end and revive, and a
 * small step's asymmetry or a wrong acceptance moves mass between stripes;
 * the zero bands are walls that a drifting chain piles up against.
 * Each function is linear (or sin^2) in a number between breakpoints on the
 * 2^-16 grid, and every constant is dyadic, so its sums over a slot's grid
 * have closed forms (test/test_chain_target.cpp). */

#define TARGET_ZERO_BELOW 0.125f  /* h(a) = 0 below it */
#define TARGET_ZERO_ABOVE 0.9375f /* x and p(c): 0 from it on */
#define TARGET_Q_LEFT 0.5f
#define TARGET_Q_RIGHT 0.75f

#if SLOT_BSDF_CHOICE >= 0
#define TARGET_SLOT_GO_ON SLOT_BSDF_CHOICE
#else
#define TARGET_SLOT_GO_ON SLOT_RR
#endif

inline float target_value(float x, float y) {
    if (x < 0.25f && y < 0.25f) return 0.0f;
    float s = sin(2.0f * M_PI_F * y);
    return (1.0f + 3.0f * x) * (1.0f + s * s);
}

/* `odd` on the odd stripes of n (a power of two), `even` on the others. */
inline float target_stripes(float v, float n, float odd, float even) {
    return ((uint)(v * n) & 1u) ? odd : even;
}

#if LAYOUT_BOUNCE_DIMS > 0
/* Reads every number of bounce k; returns e_k and sets *go_on when the
 * continuation number's phase is below q. */
inline float target_bounce(SampleSource* src, uint k, float q, bool* go_on) {
    float e = 1.0f;
    *go_on = false;
    for (int slot = 0; slot < (int)LAYOUT_BOUNCE_DIMS; ++slot) {
        float v = smp_uniform(src, k, layout_slot(k, slot));
        if (slot == SLOT_BSDF_U) {
            e *= v < TARGET_ZERO_BELOW ? 0.0f : (0.5f + v) * target_stripes(v, 64.0f, 1.5f, 0.5f);
        } else if (slot == TARGET_SLOT_GO_ON) {
            e *= v < TARGET_ZERO_ABOVE
                     ? (0.75f + 0.5f * v) * target_stripes(v, 128.0f, 1.25f, 0.75f)
                     : 0.0f;
            *go_on = v * 32.0f - floor(v * 32.0f) < q; /* exact */
        } else {
            e *= 0.75f + 0.5f * v;
        }
    }
    return e;
}
#endif

inline EvalResult eval_state(const SceneView* sc, const Frame* frame, SampleSource* src) {
    FilmPoint at = smp_film_point(src, frame);
    float x = at.x, y = at.y;
    float f = target_value(x, y);
    uint bounces = 0u;
#if LAYOUT_BOUNCE_DIMS > 0
    if (frame->depth > 0u)
        f *= x < TARGET_ZERO_ABOVE ? target_stripes(x, 64.0f, 1.25f, 0.75f) : 0.0f;
    float q = x < 0.5f ? TARGET_Q_LEFT : TARGET_Q_RIGHT;
    bool go_on = frame->depth > 0u;
    while (go_on) {
        f *= target_bounce(src, bounces, q, &go_on);
        ++bounces;
        go_on = go_on && bounces < frame->depth;
    }
#endif
    EvalResult s;
    s.f = (float3)(f);
    s.omc = (float3)(0.0f);
    s.pixel = at.pixel;
    s.bounces = bounces;
    s.behind_specular = 0.0f;
    s.rays = 0u;
    return s;
}
