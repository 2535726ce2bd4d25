/* The parts of one Metropolis step of primary-sample-space MLT (Kelemen et
 * al. 2002) in the split-transition form of Frolov and Galaktionov (section
 * 3.3, Algorithm 1); cl/kernels_mlt.cl composes them. Splats use expected
 * values: a proposal y adds a * F(y)/I(y) at its pixel and the chain's state
 * x adds its stay weight * F(x)/I(x) at x's, with a = min(1, I(y)/I(x)) and I
 * the luminance, so every splat has luminance equal to its weight. x's stay
 * weights are gathered in its ChainValue and splatted once, when the chain
 * moves away (MLT_EAGER_STAY, the reference build, splats them at every
 * step), and the step's counters are summed per work-group in local memory:
 * global atomics are the film's and one set of counters per group. */

#pragma OPENCL EXTENSION cl_khr_int64_base_atomics : enable

/* A work-group's counters in local memory, added to stats once per step. */
#define MLT_COUNT_RAYS 0
#define MLT_COUNT_LARGE 1
#define MLT_COUNT_ACCEPTED 2
#define MLT_COUNT_ATOMICS 3
#define MLT_COUNTS 4

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

/* w * f / lum(f) in the film's fixed point (SPLAT_FRAC_BITS), per channel;
 * false if it adds nothing. */
inline bool mlt_splat_value(float3 f, float w, ulong* c) {
    float lum = path_luminance(f);
    if (!(w > 0.0f) || !(lum > 0.0f)) return false;
    float3 v = f * (w / lum) * (float)(1u << SPLAT_FRAC_BITS);
    c[0] = (ulong)(v.x + 0.5f);
    c[1] = (ulong)(v.y + 0.5f);
    c[2] = (ulong)(v.z + 0.5f);
    return true;
}

/* Adds w * f / lum(f) to a pixel; returns the global atomics it made. */
inline uint mlt_splat(__global ulong* splat, uint pixel, float3 f, float w) {
    ulong c[3];
    if (!mlt_splat_value(f, w, c)) return 0u;
    atom_add(&splat[3u * pixel + 0u], c[0]);
    atom_add(&splat[3u * pixel + 1u], c[1]);
    atom_add(&splat[3u * pixel + 2u], c[2]);
    return 3u;
}

/* A step's proposal is large when its stream's number MLT_DIM_LARGE is below
 * large_threshold (= P * 2^32). */
inline bool mlt_is_large(ulong key, uint large_threshold) {
    return rng_u32(key, MLT_DIM_LARGE) < large_threshold;
}

/* Evaluates the proposal y that src defines (lazily), splats a * F(y)/I(y)
 * at its pixel and returns a = min(1, I(y)/I(x)) (1 where I(x) = 0). */
inline float mlt_try_proposal(const SceneView* sc, const Frame* frame, SampleSource* src, float3 fx,
                              __global ulong* splat, __global ulong* stats, EvalResult* y,
                              uint* atomics) {
    float ix = path_luminance(fx);
    EvalResult r = eval_state(sc, frame, src);
    if (!path_finite(r.f)) ++*atomics;
    *y = mlt_checked(r, stats);
    float iy = path_luminance(y->f);
    float a = ix > 0.0f ? fmin(1.0f, iy / ix) : 1.0f;
    *atomics += mlt_splat(splat, y->pixel, y->f, a);
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

/* x's stay weight of this step joins the weight it has gathered, which is
 * splatted at x's pixel when the chain moves away or the weight reaches
 * MLT_STAY_FLUSH (with MLT_EAGER_STAY: at once). Returns the weight still
 * pending, in the fixed point of ChainValue.stay. */
inline uint mlt_settle_stay(const Frame* frame, __global const uint* state, uint chain, uint chains,
                            ChainValue x, float stay, bool moves, __global ulong* splat,
                            uint* atomics) {
    uint pending = x.stay + chain_stay_fixed(stay);
#ifndef MLT_EAGER_STAY
    if (!moves && pending < MLT_STAY_FLUSH) return pending;
#endif
    *atomics += mlt_splat(splat, mlt_state_pixel(frame, state, chain, chains), chain_f(x),
                          chain_stay_weight(pending));
    return 0u;
}

/* The chain stays at x with `pending` weight gathered: its run of
 * rejections grows; a chain that becomes stuck is counted once
 * (MLT_STAT_STUCK); *longest keeps the longest run of the work-group. */
inline void mlt_stay(__global ChainValue* value, ChainValue x, uint pending, uint stuck_run,
                     __global ulong* stats, __local uint* longest, uint* atomics) {
    ChainValue v = chain_stayed(x, stuck_run);
    if (chain_stuck(v) && !chain_stuck(x)) {
        atom_inc(&stats[MLT_STAT_STUCK]);
        ++*atomics;
    }
    value->meta = v.meta;
    value->stay = pending;
    atomic_max(longest, chain_run(v));
}

/* The chain moves to the proposal y of this work-item: its numbers are
 * stored (regenerated from src) and its value replaced. */
inline void mlt_move(SampleSource* src, __global ChainValue* value, ChainValue x, EvalResult y) {
    smp_commit(src, y.bounces);
    *value = chain_moved(x, y.f, y.bounces);
}

inline void mlt_zero_counts(__local uint* count) {
    for (uint i = 0; i < MLT_COUNTS; ++i)
        count[i] = 0u;
}

/* A large step's luminance in the fixed point of MLT_STAT_LARGE_LUM. */
inline ulong mlt_b_sample(float lum) {
    return (ulong)(fmin(lum, MLT_B_MAX_SAMPLE) * (float)(1u << MLT_B_FRAC_BITS) + 0.5f);
}

/* A work-item's share of the group's counters: rays, large steps and their
 * luminance, global atomics. */
inline void mlt_count(__local uint* count, __local ulong* large_lum, bool large, EvalResult y,
                      uint atomics) {
    atomic_add(&count[MLT_COUNT_RAYS], y.rays);
    if (large) {
        atomic_inc(&count[MLT_COUNT_LARGE]);
        ulong v = mlt_b_sample(path_luminance(y.f));
        if (v) atom_add(large_lum, v);
    }
    if (atomics) atomic_add(&count[MLT_COUNT_ATOMICS], atomics);
}

/* Adds the group's counters and longest run to the global ones, counting
 * the atomics this takes as well. */
inline void mlt_publish(__global ulong* stats, __global uint* longest_run,
                        __local const uint* count, ulong large_lum, uint longest) {
    uint n = 1u; /* the last add below */
    if (large_lum) {
        atom_add(&stats[MLT_STAT_LARGE_LUM], large_lum);
        ++n;
    }
    if (longest > 0u) {
        atomic_max(longest_run, longest);
        ++n;
    }
    const uint stat[3] = {MLT_STAT_RAYS, MLT_STAT_LARGE, MLT_STAT_ACCEPTED};
    for (uint i = 0; i < 3u; ++i)
        if (count[i]) {
            atom_add(&stats[stat[i]], (ulong)count[i]);
            ++n;
        }
    atom_add(&stats[MLT_STAT_ATOMICS], (ulong)(count[MLT_COUNT_ATOMICS] + n));
}
