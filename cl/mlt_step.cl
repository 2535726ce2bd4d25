/* The parts of one Metropolis step of primary-sample-space MLT (Kelemen et
 * al. 2002) in the split-transition form of Frolov and Galaktionov (section
 * 3.3, Algorithm 1); cl/kernels_mlt.cl composes them. Splats use expected
 * values: a proposal y adds a * F(y)/I(y) at its pixel and the chain's state
 * x adds its stay weight * F(x)/I(x) at x's, with a = min(1, I(y)/I(x)) and I
 * the luminance, so every splat has luminance equal to its weight. */

#pragma OPENCL EXTENSION cl_khr_int64_base_atomics : enable

/* Dimensions of a step's stream reserved for the step itself. */
#define MLT_DIM_LARGE 0xFFFFFFF0u
#define MLT_DIM_ACCEPT 0xFFFFFFF1u

/* Where a work-item sits: proposal i of chain `chain` (of `chains`), whose
 * K work-items start at local index `first` of one work-group. */
typedef struct {
    uint t, lid, chain, chains, i, first;
    bool active; /* t < number of threads */
} MltThread;

inline MltThread mlt_thread(uint num_threads, uint proposals) {
    MltThread th;
    th.t = get_global_id(0);
    th.lid = get_local_id(0);
    th.chains = num_threads / proposals;
    th.chain = th.t / proposals;
    th.i = th.t % proposals;
    th.first = th.lid - th.i;
    th.active = th.t < num_threads;
    return th;
}

/* A non-finite F is dropped and counted: it contributes nothing and a chain
 * never moves to it. */
inline EvalResult mlt_checked(EvalResult s, __global ulong* stats) {
    if (!path_finite(s.f)) {
        atom_inc(&stats[MLT_STAT_NONFINITE]);
        s.f = (float3)(0.0f);
    }
    return s;
}

/* Adds w * f / lum(f) to a pixel in fixed point (SPLAT_FRAC_BITS). */
inline void mlt_splat(__global ulong* splat, uint pixel, float3 f, float w) {
    float lum = path_luminance(f);
    if (!(w > 0.0f) || !(lum > 0.0f)) return;
    float3 c = f * (w / lum) * (float)(1u << SPLAT_FRAC_BITS);
    atom_add(&splat[3u * pixel + 0u], (ulong)(c.x + 0.5f));
    atom_add(&splat[3u * pixel + 1u], (ulong)(c.y + 0.5f));
    atom_add(&splat[3u * pixel + 2u], (ulong)(c.z + 0.5f));
}

/* A step's proposal is large when its stream's number MLT_DIM_LARGE is below
 * large_threshold (= P * 2^32). */
inline bool mlt_is_large(ulong key, uint large_threshold) {
    return rng_u32(key, MLT_DIM_LARGE) < large_threshold;
}

/* Evaluates the proposal y that src defines (lazily), splats a * F(y)/I(y)
 * at its pixel and returns a = min(1, I(y)/I(x)) (1 where I(x) = 0). */
inline float mlt_try_proposal(const SceneView* sc, const Frame* frame, SampleSource* src, float3 fx,
                              __global ulong* splat, __global ulong* stats, EvalResult* y) {
    float ix = path_luminance(fx);
    *y = mlt_checked(eval_state(sc, frame, src), stats);
    float iy = path_luminance(y->f);
    float a = ix > 0.0f ? fmin(1.0f, iy / ix) : 1.0f;
    mlt_splat(splat, y->pixel, y->f, a);
    return a;
}

/* The weight of staying at x after the chain's K proposals with
 * acceptances a[0..K-1]: K - sum a_j (never below 0 after rounding). */
inline float mlt_stay_weight(__local const float* a, uint proposals) {
    float stay = (float)proposals;
    for (uint j = 0; j < proposals; ++j)
        stay -= a[j];
    return fmax(stay, 0.0f);
}

/* The pixel the chain's current state x splats to. */
inline uint mlt_state_pixel(const Frame* frame, __global const uint* state, uint chain,
                            uint chains) {
    return eval_pixel(frame, pss_load(state, chain, chains, layout_film(0u)),
                      pss_load(state, chain, chains, layout_film(1u)));
}

/* The step's number for choosing the next state: uniform in [0, K). */
inline float mlt_select_number(ulong key, uint proposals) {
    return (float)(rng_u32(key, MLT_DIM_ACCEPT) >> 8) * (1.0f / 16777216.0f) * (float)proposals;
}

/* The chain's next state among (x, y_1..y_K), picked by u in [0, K) in
 * proportion to (stay, a_1, .., a_K): 0 stays at x, j moves to y_j. */
inline uint mlt_select(__local const float* a, uint proposals, float stay, float u) {
    uint next = 0u;
    float acc = stay;
    for (uint j = 0; j < proposals && u >= acc; ++j) {
        if (a[j] > 0.0f) next = j + 1u; /* float rounding: keep the last one */
        acc += a[j];
    }
    return next;
}

/* The chain stays at x: its run of rejections grows; a chain that becomes
 * stuck is counted once (MLT_STAT_STUCK); *longest keeps the longest run of
 * the work-group. */
inline void mlt_stay(__global ChainValue* value, ChainValue x, uint stuck_run,
                     __global ulong* stats, __local uint* longest) {
    ChainValue v = chain_stayed(x, stuck_run);
    if (chain_stuck(v) && !chain_stuck(x)) atom_inc(&stats[MLT_STAT_STUCK]);
    value->meta = v.meta;
    atomic_max(longest, chain_run(v));
}

/* The chain moves to the proposal y of this work-item: its numbers are
 * stored (regenerated from src) and its value replaced. */
inline void mlt_move(SampleSource* src, __global ChainValue* value, ChainValue x, EvalResult y,
                     __global ulong* stats) {
    smp_commit(src, y.bounces);
    *value = chain_moved(x, y.f, y.bounces);
    atom_inc(&stats[MLT_STAT_ACCEPTED]);
}

/* Per-step counters: large steps and rays traced. */
inline void mlt_count(__global ulong* stats, bool large, uint rays) {
    if (large) atom_inc(&stats[MLT_STAT_LARGE]);
    atom_add(&stats[MLT_STAT_RAYS], (ulong)rays);
}
