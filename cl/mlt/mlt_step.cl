/* The parts of one Metropolis step of primary-sample-space MLT (Kelemen et
 * al. 2002) in the split-transition form of Frolov and Galaktionov (section
 * 3.3, Algorithm 1); cl/kernels/mlt.cl composes them. The target is
 * I(x) = lum(F(x)) w(x), w the weight of x's pixel's cell (MltTarget; 1
 * everywhere but for the two-stage target, src/render/target.hpp, and 0 in
 * the cells the OMC part renders whole, src/render/omc_cells.hpp). A chain
 * keeps G(x) = F(x) w(x), so that I(x) = lum(G(x)). Splats use expected
 * values: a proposal y adds a * F(y)/I(y) at its pixel and the chain's state
 * x adds its stay weight * F(x)/I(x) at x's, with a = min(1, I(y)/I(x)), so
 * every splat has luminance equal to its weight over w <= its weight. With
 * Kelemen's weights (Kelemen et al. 2002, section 5; MltTarget.kelemen_pb =
 * p q b0 > 0, q the large steps' density, StratumWeights; p b0 below stands
 * for it), a large proposal is also an independent sample of the image,
 * and the two estimates are combined by the balance heuristic: every splat's
 * 1/I becomes 1/(I + p b0), and a large proposal also splats its own
 * estimate, weight 1, in the film's large-steps layer, which the image
 * scales by the b0 of these weights where the chains' layer takes b
 * (src/render/mlt.hpp). A splat's luminance stays at most its weight, at
 * most 1 per mutation in each layer (src/render/mlt_film.hpp). x's
 * stay weights are gathered in its ChainValue and splatted once, when the
 * chain moves away (MLT_EAGER_STAY, the reference build, splats them at
 * every step). Splats go to the film through 32-bit atomics (cl/mlt/film.cl);
 * the step's counters are summed per work-group in local memory and added
 * to the group's own row of stats, so the only global atomics are the
 * film's. */

/* The target's weights, w >= 1 per cell of TargetCells (0 in the cells
 * the OMC part renders whole, where G = 0 and film_value drops the splat),
 * and what a splat weighs. */
typedef struct {
    __global const float* weight;
    TargetCells cells;
    uint width;       /* the film's, in pixels */
    float kelemen_pb; /* p q b0 with Kelemen's weights; 0: expected values alone */
} MltTarget;

inline MltTarget mlt_target(__global const float* weight, TargetCells cells, const Frame* frame,
                            float kelemen_pb) {
    MltTarget t = {weight, cells, frame->width, kelemen_pb};
    return t;
}

/* Stratified MLT (src/render/strata.hpp): the chains of work-group g (of
 * MLT_GROUP threads, strata_group_chains chains) live in tile
 * strata_group_tile[g] of strata_tiles, whose large steps weigh
 * strata_weights[tile] (StratumWeights: Kelemen's p q b0, b0 the tile's own
 * normalization, and the large steps' density). One tile, the whole film,
 * is plain MLT. */
#define STRATA_ARGS                                                                                \
    __global const FilmTile *strata_tiles, __global const uint *strata_group_tile,                 \
        __global const StratumWeights *strata_weights, const uint strata_group_chains

typedef struct {
    FilmTile tile;
    StratumWeights weights;
} MltStratum;

inline MltStratum mlt_stratum(__global const FilmTile* tiles, __global const uint* group_tile,
                              __global const StratumWeights* weights, uint group_chains,
                              uint chain) {
    uint t = group_tile[chain / group_chains];
    MltStratum s = {tiles[t], weights[t]};
    return s;
}
#define MLT_STRATUM(chain)                                                                         \
    mlt_stratum(strata_tiles, strata_group_tile, strata_weights, strata_group_chains, (chain))

/* What a splat at target value i keeps of its expected-value weight:
 * i / (i + p b0) with Kelemen's weights, else 1. */
inline float mlt_kelemen(const MltTarget* t, float i) {
    return t->kelemen_pb > 0.0f ? i / (i + t->kelemen_pb) : 1.0f;
}

/* w at a pixel. */
inline float mlt_weight(const MltTarget* t, uint pixel) {
    return target_weight(t->weight, &t->cells, t->width, pixel);
}

/* Stream numbers of a large step's film numbers after its first try, which
 * takes the film's own (dims 0 and 1): try t takes MLT_DIM_LARGE_FILM + 2 t
 * and the next. Below MLT_DIM_LARGE, above every path number. */
#define MLT_DIM_LARGE_FILM 0xFFFFFF00u

/* A large step's film numbers (LAYOUT_CAMERA_BITS wide) in tile `tile`:
 * the first of MLT_LARGE_FILM_TRIES uniform draws that lands where w > 0,
 * else the last (StratumWeights). The chains' states never lie where
 * w = 0, so draws there are wasted steps; on the chains' part the draw is
 * uniform, with the density StratumWeights.large_density. */
inline uint2 mlt_large_film(const MltTarget* t, const FilmTile* tile, const Frame* frame,
                            ulong key) {
    const uint shift = 32u - LAYOUT_CAMERA_BITS;
    uint2 film = (uint2)(rng_u32(key, 0u), rng_u32(key, 1u)) >> shift;
    for (uint i = 1u; i < MLT_LARGE_FILM_TRIES; ++i) {
        FilmPoint p = strata_point(tile, frame, layout_unit(film.x, LAYOUT_CAMERA_BITS),
                                   layout_unit(film.y, LAYOUT_CAMERA_BITS));
        if (mlt_weight(t, p.pixel) > 0.0f) break;
        uint dim = MLT_DIM_LARGE_FILM + 2u * i;
        film = (uint2)(rng_u32(key, dim), rng_u32(key, dim + 1u)) >> shift;
    }
    return film;
}

/* A path in a cell the OMC part renders whole (w = 0): its MLT part joins
 * its OMC part (cl/core/target_cells.h), for the burn-in's parts. */
inline EvalResult mlt_cell_parts(const MltTarget* t, EvalResult s) {
    if (mlt_weight(t, s.pixel) > 0.0f) return s;
    s.omc += s.f;
    s.f = (float3)(0.0f);
    s.behind_specular = 0.0f;
    return s;
}

/* Numbers of a step's stream reserved for the step itself: the large-step
 * choice, the choice of the next state, and the rounding of the proposal's
 * splat (3), of the state's (3), of what a chain owes at a read (3) and of a
 * large proposal's own estimate (3). */
#define MLT_DIM_LARGE 0xFFFFFFF0u
#define MLT_DIM_ACCEPT 0xFFFFFFF1u
#define MLT_DIM_ROUND_Y 0xFFFFFFF2u
#define MLT_DIM_ROUND_X 0xFFFFFFF5u
#define MLT_DIM_ROUND_OWED 0xFFFFFFF8u
#define MLT_DIM_ROUND_LARGE 0xFFFFFFFBu

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

/* A sample with a non-finite part is dropped and counted in *nonfinite: it
 * contributes nothing and a chain never moves to it. */
inline EvalResult mlt_checked(EvalResult s, uint* nonfinite) {
    if (!path_finite(s.f) || !path_finite(s.omc)) {
        ++*nonfinite;
        s.f = (float3)(0.0f);
        s.omc = (float3)(0.0f);
    }
    return s;
}

/* The first work-item of a group clears the group's counters. */
inline void mlt_zero_counts(__local uint* count) {
    if (get_local_id(0) != 0u) return;
    for (uint i = 0; i < MLT_COUNTS; ++i)
        count[i] = 0u;
}

/* After a barrier, the first work-item adds the group's counters (and the
 * sum of its large steps' luminances, `large_lum`) to the group's row of
 * stats: plain arithmetic, as no other work-item writes that row. */
inline void mlt_publish(__global ulong* stats, __local const uint* count, ulong large_lum) {
    if (get_local_id(0) != 0u) return;
    __global ulong* row = stats + (size_t)get_group_id(0) * MLT_STAT_COUNT;
#define MLT_JOIN_SUM(a, b) ((a) + (b))
#define MLT_JOIN_MAX(a, b) max((a), (b))
#define MLT_PUBLISH(NAME, member, JOIN)                                                            \
    row[MLT_STAT_##NAME] = MLT_JOIN_##JOIN(row[MLT_STAT_##NAME], (ulong)count[MLT_STAT_##NAME]);
    MLT_COUNTERS(MLT_PUBLISH)
#undef MLT_PUBLISH
    row[MLT_STAT_LARGE_LUM] += large_lum;
}

/* A step's proposal is large when its stream's number MLT_DIM_LARGE is below
 * large_threshold (= P * 2^32). */
inline bool mlt_is_large(ulong key, uint large_threshold) {
    return rng_u32(key, MLT_DIM_LARGE) < large_threshold;
}

/* The proposal y that src defines, evaluated (lazily), with y.f = G(y);
 * *w = w(y). */
inline EvalResult mlt_evaluate(const SceneView* sc, const Frame* frame, SampleSource* src,
                               const MltTarget* target, uint* nonfinite, float* w) {
    EvalResult y = mlt_checked(eval_state(sc, frame, src), nonfinite);
    *w = mlt_weight(target, y.pixel);
    y.f *= *w;
    return y;
}

/* Evaluates the proposal y (y->f = G(y)), splats a * F(y)/I(y) at its pixel
 * (Kelemen's weights: a * F(y)/(I(y) + p b0), and a large proposal's own
 * estimate F(y)/(I(y) + p b0) in the large steps' layer) and returns
 * a = min(1, I(y)/I(x)) (1 where I(x) = 0), for a chain at x with
 * G(x) = gx. */
inline float mlt_try_proposal(const SceneView* sc, const Frame* frame, SampleSource* src,
                              const MltTarget* target, float3 gx, bool large, const Film* film,
                              ulong key, EvalResult* y, uint* nonfinite, uint* atomics) {
    float ix = path_luminance(gx), wy;
    *y = mlt_evaluate(sc, frame, src, target, nonfinite, &wy);
    float iy = path_luminance(y->f);
    float a = ix > 0.0f ? fmin(1.0f, iy / ix) : 1.0f;
    float w = mlt_kelemen(target, iy) / wy;
    *atomics +=
        film_splat(film, y->pixel, FILM_LAYER_CHAINS, y->f, a * w, key, MLT_DIM_ROUND_Y, false);
    if (large && target->kelemen_pb > 0.0f)
        *atomics +=
            film_splat(film, y->pixel, FILM_LAYER_LARGE, y->f, w, key, MLT_DIM_ROUND_LARGE, false);
    return a;
}

/* A restart's burn-in sample s as one more uniform sample of Kelemen's
 * large steps (doc/design.md, "Restarts"): F(s)/(I(s) + c b0) in the large
 * steps' layer, where c b0, its tile's kelemen_pb, counts the restarts'
 * samples per mutation in c. Nothing where the target is 0 (the OMC part's
 * cells). Returns the global atomics it made. */
inline uint mlt_splat_restart_sample(const Film* film, __global const float* weight,
                                     const TargetCells cells, const Frame* frame,
                                     __global const FilmTile* tiles,
                                     __global const StratumWeights* weights, EvalResult s,
                                     ulong key) {
    StratumWeights sw = weights[strata_pixel_tile(tiles, frame, s.pixel)];
    MltTarget target = mlt_target(weight, cells, frame, sw.kelemen_pb);
    float w = mlt_weight(&target, s.pixel);
    if (w <= 0.0f) return 0u;
    float3 f = s.f * w;
    return film_splat(film, s.pixel, FILM_LAYER_LARGE, f,
                      mlt_kelemen(&target, path_luminance(f)) / w, key, MLT_DIM_ROUND_LARGE, false);
}

/* The weight of staying at x after the chain's K proposals with
 * acceptances a[0..K-1]: K - sum a_j (never below 0 after rounding). */
inline float mlt_stay_weight(__local const float* a, uint proposals) {
    float stay = (float)proposals;
    for (uint j = 0; j < proposals; ++j)
        stay -= a[j];
    return fmax(stay, 0.0f);
}

/* The pixel the chain's current state x splats to, in its tile. */
inline uint mlt_state_pixel(const Frame* frame, const FilmTile* tile, __global const uint* state,
                            uint chain, uint chains) {
    return strata_point(tile, frame, pss_load(state, chain, chains, layout_film(0u)),
                        pss_load(state, chain, chains, layout_film(1u)))
        .pixel;
}

/* Splats w * F(x)/I(x) (Kelemen's weights: w * F(x)/(I(x) + p b0)) at the
 * pixel of chain's state x in tile `tile` (subtracts it with `undo`);
 * returns the global atomics it made. */
inline uint mlt_splat_state(const Frame* frame, const MltTarget* target, const FilmTile* tile,
                            __global const uint* state, uint chain, uint chains, ChainValue x,
                            float w, const Film* film, ulong key, uint dim, bool undo) {
    uint pixel = mlt_state_pixel(frame, tile, state, chain, chains);
    float3 g = chain_g(x);
    w *= mlt_kelemen(target, path_luminance(g)) / mlt_weight(target, pixel);
    return film_splat(film, pixel, FILM_LAYER_CHAINS, g, w, key, dim, undo);
}

/* The step's number for choosing the next state: uniform in [0, K). */
inline float mlt_select_number(ulong key, uint proposals) {
    return rng_unit(key, MLT_DIM_ACCEPT) * (float)proposals;
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
inline uint mlt_settle_stay(const Frame* frame, const MltTarget* target, const FilmTile* tile,
                            __global const uint* state, uint chain, uint chains, ChainValue x,
                            float stay, bool moves, const Film* film, ulong key, uint* atomics) {
    uint pending = x.stay + chain_stay_fixed(stay);
#ifndef MLT_EAGER_STAY
    if (!moves && pending < MLT_STAY_FLUSH) return pending;
#endif
    *atomics += mlt_splat_state(frame, target, tile, state, chain, chains, x,
                                chain_stay_weight(pending), film, key, MLT_DIM_ROUND_X, false);
    return 0u;
}

/* The chain stays at x with `pending` weight gathered: its run of
 * rejections grows; a chain that becomes stuck is counted once
 * (MLT_STAT_STUCK), and the group keeps its longest run. */
inline void mlt_stay(__global ChainValue* value, ChainValue x, uint pending, uint stuck_run,
                     __local uint* count) {
    ChainValue v = chain_stayed(x, stuck_run);
    if (chain_stuck(v) && !chain_stuck(x)) atomic_inc(&count[MLT_STAT_STUCK]);
    value->meta = v.meta;
    value->stay = pending;
    atomic_max(&count[MLT_STAT_LONGEST], chain_run(v));
}

/* The chain moves to the proposal y of this work-item: its numbers are
 * stored (regenerated from src) and its value replaced. */
inline void mlt_move(SampleSource* src, __global ChainValue* value, ChainValue x, EvalResult y) {
    smp_commit(src, y.bounces);
    *value = chain_moved(x, y.f, y.bounces);
}

/* For kernels that count only dropped samples: the work-item's `nonfinite`
 * joins the group's count, which goes to the group's row of stats. */
inline void mlt_publish_nonfinite(__global ulong* stats, __local uint* count, uint nonfinite) {
    if (nonfinite) atomic_add(&count[MLT_STAT_NONFINITE], nonfinite);
    barrier(CLK_LOCAL_MEM_FENCE);
    mlt_publish(stats, count, 0ul);
}

/* A work-item's share of the group's counters: rays, large steps,
 * non-finite results, global atomics; and in large_lum[lid] its large
 * step's estimate of b, I(y) over the large steps' density (0 if small),
 * which the group sums in a fixed order. */
inline void mlt_count(__local uint* count, __local ulong* large_lum, bool large, EvalResult y,
                      float large_density, uint nonfinite, uint atomics) {
    atomic_add(&count[MLT_STAT_RAYS], y.rays);
    if (large) atomic_inc(&count[MLT_STAT_LARGE]);
    large_lum[get_local_id(0)] = large ? fixed_b_sample(path_luminance(y.f) / large_density) : 0ul;
    if (nonfinite) atomic_add(&count[MLT_STAT_NONFINITE], nonfinite);
    if (atomics) atomic_add(&count[MLT_STAT_ATOMICS], atomics);
}

/* After a barrier: the group's large-step luminances, summed in local order
 * (integers, so the sum is exact and repeatable). */
inline ulong mlt_large_lum(__local const ulong* large_lum) {
    ulong sum = 0ul;
    for (uint i = 0; i < get_local_size(0); ++i)
        sum += large_lum[i];
    return sum;
}
