/* Entry points of primary-sample-space MLT (Kelemen et al. 2002) with the
 * chain storage of Frolov and Galaktionov: one chain per K work-items,
 * states packed (pss.cl), proposals lazy (sample_chain.cl), the step's parts
 * in mlt_step.cl, the film in film.cl. Every kernel runs in work-groups of
 * MLT_GROUP and counts into its group's row of stats. */

/* The target I of burn-in sample i of round `round`: the path of the Sobol
 * numbers burnin_sample gives it. The normalization b = E[I] is their mean.
 * With MLT_BURN_IN_SAMPLES (a split, or the two-stage target) the path's
 * parts go to omc[2 i] (xyz: the OMC part, RGB; w: the pixel's bits) and
 * omc[2 i + 1] (xyz: the MLT part; w: its light behind smooth transmitters,
 * cl/path/path.cl), so that the burn-in's paths also render the OMC part,
 * and the host can tell how well path tracing renders the MLT part
 * (src/render/split.hpp) and weigh the two-stage target's cells
 * (src/render/target.hpp). The host adds them in sample order: no atomics,
 * and the same sums every time. With `splat` (a restart's rounds under
 * Kelemen's weights) each sample is also one of the large steps' uniform
 * samples in the film (mlt_splat_restart_sample). */
__kernel void mlt_luminance(SCENE_ARGS, __global const float* weight, const TargetCells cells,
                            const BurnInFilm film, __global uint* state, const uint round,
                            const uint count, __global float* lum, __global float4* omc,
                            __global ulong* stats, STRATA_ARGS, FILM_ARGS, const ulong seed,
                            const uint splat) {
    __local uint l_count[MLT_COUNTS];
    uint i = get_global_id(0), nonfinite = 0u;
    mlt_zero_counts(l_count);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (i < count) {
        SceneView sc = SCENE_VIEW();
        MltTarget target = mlt_target(weight, cells, &frame, 0.0f);
        BurnInSample b = burnin_sample(&film, &frame, (ulong)round * film.per_round + i);
        SampleSource src = smp_chain_start(state, 0u, 1u, b, b.film, strata_whole(&frame));
        EvalResult s =
            mlt_cell_parts(&target, mlt_checked(eval_state(&sc, &frame, &src), &nonfinite));
        lum[i] = path_luminance(s.f) * mlt_weight(&target, s.pixel);
#ifdef MLT_BURN_IN_SAMPLES
        omc[2u * i] = (float4)(s.omc, as_float(s.pixel));
        omc[2u * i + 1u] = (float4)(s.f, s.behind_specular);
#endif
        if (splat) {
            Film image = FILM_VIEW();
            mlt_splat_restart_sample(&image, weight, cells, &frame, strata_tiles, strata_weights, s,
                                     rng_key(seed, i, round));
        }
    }
    mlt_publish_nonfinite(stats, l_count, nonfinite);
}

/* The emission the camera sees directly, sample i of stream `seed`
 * (cl/path/emission_seen.cl), into out[i]. */
__kernel void mlt_emission_seen(SCENE_ARGS, const ulong seed, const uint pick_bits,
                                const uint count, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= count) return;
    SceneView sc = SCENE_VIEW();
    out[i] = emission_seen_sample(&sc, &frame, rng_key(seed, i, 0u), pick_bits);
}

/* Starts chain c at burn-in sample picks[c] = (round r, index i), the path
 * mlt_luminance drew, its film position read as numbers of the chain's tile
 * (a fresh start outside the tile is moved to its edge). */
__kernel void mlt_init(SCENE_ARGS, __global const float* weight, const TargetCells cells,
                       const BurnInFilm film, STRATA_ARGS, __global uint* state,
                       __global ChainValue* values, const uint num_chains,
                       __global const uint2* picks, __global ulong* stats) {
    __local uint l_count[MLT_COUNTS];
    uint c = get_global_id(0), nonfinite = 0u;
    mlt_zero_counts(l_count);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (c < num_chains) {
        SceneView sc = SCENE_VIEW();
        MltTarget target = mlt_target(weight, cells, &frame, 0.0f);
        MltStratum stratum = MLT_STRATUM(c);
        uint2 pick = picks[c];
        BurnInSample b = burnin_sample(&film, &frame, (ulong)pick.x * film.per_round + pick.y);
        SampleSource src = smp_chain_start(
            state, c, num_chains, b, strata_local(&stratum.tile, &frame, b.film), stratum.tile);
        float w;
        EvalResult s = mlt_evaluate(&sc, &frame, &src, &target, &nonfinite, &w);
        smp_commit(&src, s.bounces);
        values[c] = chain_started(s.f, s.bounces);
    }
    mlt_publish_nonfinite(stats, l_count, nonfinite);
}

/* One Metropolis step of every chain with K proposals each (split-transition
 * MLT; K = 1 is plain PSSMLT). Work-item t is proposal t % K of chain t / K;
 * a chain's K work-items sit in one work-group (K divides MLT_GROUP):
 * 1. each evaluates its proposal y_i (a large one with its film numbers
 *    where the target is above 0, mlt_large_film) and splats a_i F(y_i)/I(y_i) (with
 *    Kelemen's weights, mlt_step.cl, a_i F(y_i)/(I(y_i) + p b0), and a large
 *    proposal's own F(y_i)/(I(y_i) + p b0) in the film's large-steps layer);
 * 2. they meet in local memory; the first picks the next state among
 *    (x, y_1..y_K) in proportion to (K - sum a_i, a_1, .., a_K), adds the
 *    stay weight K - sum a_i to x's gathered weight, splats that at x's
 *    pixel if the chain moves away, and counts a run of rejections
 *    (doc/stability.md);
 * 3. the group's counters, with its large steps' samples of b (I over
 *    their density), go to its row of stats; the picked
 *    work-item commits its proposal. */
__kernel void mlt_step(SCENE_ARGS, __global const float* weight, const TargetCells cells,
                       STRATA_ARGS, __global uint* state, __global ChainValue* values,
                       const uint num_threads, const uint proposals, const ulong seed,
                       const uint iteration, const uint large_threshold, FILM_ARGS,
                       __global ulong* stats, const uint stuck_run) {
    __local float l_a[MLT_GROUP];
    __local uint l_next[MLT_GROUP];
    __local uint l_count[MLT_COUNTS];
    __local ulong l_large_lum[MLT_GROUP];
    MltThread th = mlt_thread(num_threads, proposals);
    uint c = th.active ? th.chain : 0u;
    SceneView sc = SCENE_VIEW();
    MltStratum stratum = MLT_STRATUM(c);
    MltTarget target = mlt_target(weight, cells, &frame, stratum.weights.kelemen_pb);
    Film film = FILM_VIEW();
    ChainValue x = values[c];
    ulong key = rng_key(seed, th.t, iteration);
    bool large = mlt_is_large(key, large_threshold);
    SampleSource src = smp_chain(state, c, th.chains, key, large ? SMP_LARGE : SMP_SMALL,
                                 chain_bounces(x), stratum.tile);
    if (large) src.film = mlt_large_film(&target, &stratum.tile, &frame, key);
    EvalResult y = eval_nothing();
    float a = 0.0f;
    uint atomics = 0u, nonfinite = 0u;
    if (th.active)
        a = mlt_try_proposal(&sc, &frame, &src, &target, chain_g(x), large, &film, key, &y,
                             &nonfinite, &atomics);

    l_a[th.lid] = a;
    mlt_zero_counts(l_count);
    barrier(CLK_LOCAL_MEM_FENCE);
    if (th.active && th.i == 0u) {
        float stay = mlt_stay_weight(&l_a[th.first], proposals);
        uint next = mlt_select(&l_a[th.first], proposals, stay, mlt_select_number(key, proposals));
        l_next[th.lid] = next;
        uint pending = mlt_settle_stay(&frame, &target, &stratum.tile, state, c, th.chains, x, stay,
                                       next != 0u, &film, key, &atomics);
        if (next == 0u)
            mlt_stay(&values[c], x, pending, stuck_run, l_count);
        else
            atomic_inc(&l_count[MLT_STAT_ACCEPTED]);
    }
    mlt_count(l_count, l_large_lum, th.active && large, y, stratum.weights.large_density, nonfinite,
              atomics);
    barrier(CLK_LOCAL_MEM_FENCE);
    mlt_publish(stats, l_count, get_local_id(0) == 0u ? mlt_large_lum(l_large_lum) : 0ul);

    if (!th.active) return;
    if (l_next[th.first] == th.i + 1u) mlt_move(&src, &values[c], x, y);
}

/* What each chain owes the film: its gathered stay weight at its state's
 * pixel, rounded with the numbers of (seed, chain, iteration), added,
 * subtracted or flushed by `mode` (MLT_OWED_*, cl/core/shared_types.h;
 * src/render/mlt_film.hpp). */
__kernel void mlt_owed(const Frame frame, __global const float* weight, const TargetCells cells,
                       STRATA_ARGS, __global const uint* state, __global ChainValue* values,
                       const uint num_chains, const ulong seed, const uint iteration, FILM_ARGS,
                       const uint mode) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    Film film = FILM_VIEW();
    MltStratum stratum = MLT_STRATUM(c);
    MltTarget target = mlt_target(weight, cells, &frame, stratum.weights.kelemen_pb);
    ChainValue x = values[c];
    if (!x.stay) return;
    mlt_splat_state(&frame, &target, &stratum.tile, state, c, num_chains, x,
                    chain_stay_weight(x.stay), &film, rng_key(seed, c, iteration),
                    MLT_DIM_ROUND_OWED, mode == MLT_OWED_UNDO);
    if (mode == MLT_OWED_FLUSH) values[c].stay = 0u;
}
