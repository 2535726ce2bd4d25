/* Entry points of primary-sample-space MLT (Kelemen et al. 2002) with the
 * chain storage of Frolov and Galaktionov: one chain per work-item, states
 * packed (pss.cl), proposals lazy (sample_mlt.cl). Splats use expected
 * values: each step adds a * F(y)/I(y) at y's pixel and (1 - a) * F(x)/I(x)
 * at x's, with a = min(1, I(y)/I(x)) and I the luminance. */

#pragma OPENCL EXTENSION cl_khr_int64_base_atomics : enable

/* A non-finite F is dropped and counted: it contributes nothing and a chain
 * never moves to it. */
inline MltSample mlt_checked(MltSample s, __global ulong* stats) {
    if (!path_finite(s.f)) {
        atom_inc(&stats[MLT_STAT_NONFINITE]);
        s.f = (float3)(0.0f);
    }
    return s;
}

inline uint chain_bounces(ChainValue v) {
    return v.meta & CHAIN_BOUNCES_MASK;
}

inline uint chain_run(ChainValue v) {
    return v.meta >> CHAIN_RUN_SHIFT;
}

/* The value of a chain that moved to a path with F = f and `bounces` live
 * bounces: its run of rejections starts again, its stuck mark stays. */
inline ChainValue chain_moved(ChainValue x, float3 f, uint bounces) {
    ChainValue v = {{f.x, f.y, f.z}, bounces | (x.meta & CHAIN_STUCK_BIT)};
    return v;
}

/* Chain x stays where it is: its run of rejections grows by one; reaching
 * stuck_run marks and counts it, once. */
inline void mlt_rejected(__global ChainValue* value, ChainValue x, uint stuck_run,
                         __global ulong* stats, __local uint* longest) {
    uint run = min(chain_run(x) + 1u, CHAIN_RUN_MAX);
    uint meta = (x.meta & (CHAIN_BOUNCES_MASK | CHAIN_STUCK_BIT)) | (run << CHAIN_RUN_SHIFT);
    if (run >= stuck_run && !(x.meta & CHAIN_STUCK_BIT)) {
        meta |= CHAIN_STUCK_BIT;
        atom_inc(&stats[MLT_STAT_STUCK]);
    }
    value->meta = meta;
    atomic_max(longest, run);
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

/* Luminance of the OMC path of each key rng_key(seed, first + i, 0): the
 * normalization b = E[I] is their mean. */
__kernel void mlt_luminance(__global const Triangle* tris, __global const BvhNode* nodes,
                            __global const Material* mats, __global const LightEntry* lights,
                            const Frame frame, __global uint* state, const ulong seed,
                            const uint first, const uint count, __global float* lum,
                            __global ulong* stats) {
    uint i = get_global_id(0);
    if (i >= count) return;
    SceneView sc = path_scene(tris, nodes, mats, lights, &frame);
    SampleSource src = smp_chain(state, 0u, 1u, rng_key(seed, first + i, 0u), SMP_LARGE, 0u);
    MltSample s = mlt_checked(mlt_evaluate(&sc, &frame, &src), stats);
    lum[i] = path_luminance(s.f);
}

/* Starts chain c at the OMC path of sample picks[c]: the path of key
 * rng_key(seed, picks[c], 0), as mlt_luminance drew it. */
__kernel void mlt_init(__global const Triangle* tris, __global const BvhNode* nodes,
                       __global const Material* mats, __global const LightEntry* lights,
                       const Frame frame, __global uint* state, __global ChainValue* values,
                       const uint num_chains, const ulong seed, __global const uint* picks,
                       __global ulong* stats) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    SceneView sc = path_scene(tris, nodes, mats, lights, &frame);
    SampleSource src = smp_chain(state, c, num_chains, rng_key(seed, picks[c], 0u), SMP_LARGE, 0u);
    MltSample s = mlt_checked(mlt_evaluate(&sc, &frame, &src), stats);
    mlt_commit(&src, s.bounces);
    ChainValue v = {{s.f.x, s.f.y, s.f.z}, s.bounces};
    values[c] = v;
}

/* One Metropolis step of every chain with K proposals each: split-transition
 * MLT (Frolov and Galaktionov, section 3.3, Algorithm 1). Work-item t is
 * proposal t % K of chain t / K; a chain's K work-items sit in one
 * work-group (K divides MLT_GROUP) and meet in local memory. Each evaluates
 * its proposal y_i lazily and splats a_i F(y_i)/I(y_i), a_i = min(1,
 * I(y_i)/I(x)); the chain's first work-item splats (K - sum a_i) F(x)/I(x)
 * and picks the next state among (x, y_1..y_K) in proportion to (K - sum a_i,
 * a_1, .., a_K); the picked work-item commits its proposal. K = 1 is plain
 * PSSMLT with expected-value splats. A proposal is large when its stream's
 * number MLT_DIM_LARGE is below large_threshold (= P * 2^32).
 *
 * Stuck chains: the first work-item keeps the chain's run of consecutive
 * rejections in its ChainValue; a chain whose run reaches stuck_run is marked
 * and counted once (MLT_STAT_STUCK), and longest_run[0] is the longest run
 * any chain has reached (one atomic per work-group and step). */
__kernel void mlt_step(__global const Triangle* tris, __global const BvhNode* nodes,
                       __global const Material* mats, __global const LightEntry* lights,
                       const Frame frame, __global uint* state, __global ChainValue* values,
                       const uint num_threads, const uint proposals, const ulong seed,
                       const uint iteration, const uint large_threshold, __global ulong* splat,
                       __global ulong* stats, const uint stuck_run, __global uint* longest_run) {
    __local float l_a[MLT_GROUP];
    __local uint l_next[MLT_GROUP];
    __local uint l_longest;
    uint t = get_global_id(0), lid = get_local_id(0);
    uint chains = num_threads / proposals, c = t / proposals, i = t % proposals;
    uint first = lid - i; /* the chain's first work-item in this group */
    bool active = t < num_threads;
    SceneView sc = path_scene(tris, nodes, mats, lights, &frame);
    ChainValue x = values[active ? c : 0u];
    float3 fx = (float3)(x.rgb[0], x.rgb[1], x.rgb[2]);
    float ix = path_luminance(fx);
    ulong key = rng_key(seed, t, iteration);
    bool large = rng_u32(key, MLT_DIM_LARGE) < large_threshold;
    SampleSource src = smp_chain(state, active ? c : 0u, chains, key, large ? SMP_LARGE : SMP_SMALL,
                                 chain_bounces(x));
    MltSample y;
    y.rays = 0u;
    float a = 0.0f;
    if (active) {
        y = mlt_checked(mlt_evaluate(&sc, &frame, &src), stats);
        float iy = path_luminance(y.f);
        a = ix > 0.0f ? fmin(1.0f, iy / ix) : 1.0f;
        mlt_splat(splat, y.pixel, y.f, a);
    }
    l_a[lid] = a;
    if (lid == 0u) l_longest = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    if (active && i == 0u) {
        float stay = (float)proposals;
        for (uint j = 0; j < proposals; ++j)
            stay -= l_a[first + j];
        stay = fmax(stay, 0.0f);
        uint x_pixel = mlt_pixel(&frame, pss_load(state, c, chains, layout_film(0u)),
                                 pss_load(state, c, chains, layout_film(1u)));
        mlt_splat(splat, x_pixel, fx, stay);
        float u =
            (float)(rng_u32(key, MLT_DIM_ACCEPT) >> 8) * (1.0f / 16777216.0f) * (float)proposals;
        uint next = 0u; /* 0: stay at x; j: move to y_j */
        float acc = stay;
        for (uint j = 0; j < proposals && u >= acc; ++j) {
            if (l_a[first + j] > 0.0f) next = j + 1u; /* float rounding: keep the last one */
            acc += l_a[first + j];
        }
        l_next[lid] = next;
        if (next == 0u) mlt_rejected(&values[c], x, stuck_run, stats, &l_longest);
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    if (lid == 0u && l_longest > 0u) atomic_max(longest_run, l_longest);
    if (!active) return;
    if (l_next[first] == i + 1u) {
        mlt_commit(&src, y.bounces);
        values[c] = chain_moved(x, y.f, y.bounces);
        atom_inc(&stats[MLT_STAT_ACCEPTED]);
    }
    if (large) atom_inc(&stats[MLT_STAT_LARGE]);
    atom_add(&stats[MLT_STAT_RAYS], (ulong)y.rays);
}
