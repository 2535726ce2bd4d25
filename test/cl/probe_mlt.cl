/* Probe kernels for the MLT tests: packing round trips, lazy against eager
 * proposals, and where each chain is. Built after the MLT program's files. */

/* Number of numbers in a vector of `depth` bounces. */
inline uint probe_dims(uint depth) {
    return LAYOUT_CAMERA_DIMS + depth * LAYOUT_BOUNCE_DIMS;
}

/* Slot of number d (film numbers first, then bounce by bounce). */
inline LayoutSlot probe_slot(uint d) {
#if LAYOUT_BOUNCE_DIMS > 0
    if (d >= LAYOUT_CAMERA_DIMS)
        return layout_slot((d - LAYOUT_CAMERA_DIMS) / LAYOUT_BOUNCE_DIMS,
                           (int)((d - LAYOUT_CAMERA_DIMS) % LAYOUT_BOUNCE_DIMS));
#endif
    return layout_film(d);
}

/* Chain c stores values[c * dims + d] (integers below 2^bits) in every
 * number d, then reads them all back into out. */
__kernel void probe_pss_roundtrip(__global uint* state, __global const uint* values,
                                  __global uint* out, const uint num_chains, const uint depth) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    uint dims = probe_dims(depth);
    for (uint d = 0; d < dims; ++d) {
        LayoutSlot at = probe_slot(d);
        pss_store(state, c, num_chains, at, layout_unit(values[c * dims + d], at.bits));
    }
    for (uint d = 0; d < dims; ++d) {
        LayoutSlot at = probe_slot(d);
        out[c * dims + d] = (uint)(pss_load(state, c, num_chains, at) * (float)(1u << at.bits));
    }
}

/* For chain c with proposal key rng_key(seed, c, 1) (a large step for odd c):
 * out[3c] = F of the lazily evaluated proposal; out[3c + 1] = F of the same
 * proposal materialized number by number into `eager` and replayed;
 * out[3c + 2] = F of the chain's state after committing the proposal,
 * replayed. */
__kernel void probe_lazy_eager(SCENE_ARGS, __global uint* state, __global const ChainValue* values,
                               __global uint* eager, const uint num_chains, const ulong seed,
                               __global float4* out) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    SceneView sc = SCENE_VIEW();
    uint mode = (c & 1u) ? SMP_LARGE : SMP_SMALL;
    SampleSource lazy = smp_chain(state, c, num_chains, rng_key(seed, c, 1u), mode,
                                  values[c].meta & CHAIN_BOUNCES_MASK, strata_whole(&frame));
    EvalResult y = eval_state(&sc, &frame, &lazy);
    out[3u * c] = (float4)(y.f, as_float(y.bounces));

    for (uint d = 0; d < probe_dims(frame.depth); ++d) {
        LayoutSlot at = probe_slot(d);
        uint bounce =
            d < LAYOUT_CAMERA_DIMS ? 0u : (d - LAYOUT_CAMERA_DIMS) / max(LAYOUT_BOUNCE_DIMS, 1u);
        pss_store(eager, c, num_chains, at, smp_propose(&lazy, bounce, at));
    }
    SampleSource replay_eager =
        smp_chain(eager, c, num_chains, 0ul, SMP_REPLAY, frame.depth, strata_whole(&frame));
    EvalResult e = eval_state(&sc, &frame, &replay_eager);
    out[3u * c + 1u] = (float4)(e.f, as_float(e.bounces));

    smp_commit(&lazy, y.bounces);
    SampleSource replay_state =
        smp_chain(state, c, num_chains, 0ul, SMP_REPLAY, y.bounces, strata_whole(&frame));
    EvalResult r = eval_state(&sc, &frame, &replay_state);
    out[3u * c + 2u] = (float4)(r.f, as_float(r.bounces));
}

/* Pixel (histogram bin) of each chain's current state, in its tile. */
__kernel void probe_chain_pixel(const Frame frame, STRATA_ARGS, __global const uint* state,
                                const uint num_chains, __global uint* out) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    MltStratum stratum = MLT_STRATUM(c);
    out[c] = mlt_state_pixel(&frame, &stratum.tile, state, c, num_chains);
}

#ifndef PSS_FLOAT32
/* out[i] = v[i] moved by the small step of stream number r[i] at `scale`
 * (smp_small_delta) on the grid of a `bits`-wide slot, for i < n. */
__kernel void probe_small_step(__global const uint* r, __global const uint* v, const uint bits,
                               const uint scale, const uint n, __global uint* out) {
    uint i = get_global_id(0);
    if (i < n) out[i] = smp_perturb_bits(v[i], r[i], bits, smp_small_delta(r[i], bits, scale));
}

/* The stretch of a film number's small step (x, then y) in each of n tiles. */
__kernel void probe_film_stretch(__global const FilmTile* tiles, const uint n, __global uint* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    SampleSource s;
    s.tile = tiles[i];
    out[2u * i] = smp_film_stretch(&s, 0u);
    out[2u * i + 1u] = smp_film_stretch(&s, 1u);
}

/* Chain c (live bounces c % (depth + 1)) proposes with key rng_key(seed, c,
 * 1), a small step for even c, a large one for odd c: prior[c * dims + d] is
 * number d of the state before, lazy[c * dims + d] number d as the path reads
 * it, times 2^bits; then the proposal is committed
 * with (3c) % (depth + 1) bounces and stored[c * dims + d] is number d of the
 * state (the committed numbers, the film's and those bounces', must equal
 * lazy). */
__kernel void probe_commit_agrees(__global uint* state, const uint num_chains, const uint depth,
                                  const ulong seed, __global uint* prior, __global uint* lazy,
                                  __global uint* stored) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    uint dims = probe_dims(depth);
    for (uint d = 0; d < dims; ++d) {
        LayoutSlot at = probe_slot(d);
        prior[c * dims + d] = pss_read_bits(state, c, num_chains, at.bit_offset, at.bits);
    }
    /* A whole film of 64x64, whose film numbers (no film point is read) step
     * at most 4 pixels (--film-step auto's floor), a 16th of their interval. */
    FilmTile film = {0u, 0u, 64u, 64u, 0.0f, 0.0f, 1.0f, 1.0f};
    SampleSource src = smp_chain(state, c, num_chains, rng_key(seed, c, 1u),
                                 (c & 1u) ? SMP_LARGE : SMP_SMALL, c % (depth + 1u), film);
    for (uint d = 0; d < dims; ++d) {
        LayoutSlot at = probe_slot(d);
        uint bounce =
            d < LAYOUT_CAMERA_DIMS ? 0u : (d - LAYOUT_CAMERA_DIMS) / max(LAYOUT_BOUNCE_DIMS, 1u);
        lazy[c * dims + d] = (uint)(smp_uniform(&src, bounce, at) * (float)(1u << at.bits));
    }
    smp_commit(&src, (3u * c) % (depth + 1u));
    for (uint d = 0; d < dims; ++d) {
        LayoutSlot at = probe_slot(d);
        stored[c * dims + d] = pss_read_bits(state, c, num_chains, at.bit_offset, at.bits);
    }
}
#endif

/* Where each chain is, number by number: out[c * (n + 1) + j] is the integer
 * value (below 2^bits) that chain c stores in number dims[j] (numbered as
 * probe_slot numbers them), and out[c * (n + 1) + n] its live bounces (the
 * ChainValue meta). Numbers of bounces at or past the live count are stale. */
__kernel void probe_chain_numbers(__global const uint* state, __global const ChainValue* values,
                                  const uint num_chains, __global const uint* dims, const uint n,
                                  __global uint* out) {
    uint c = get_global_id(0);
    if (c >= num_chains) return;
    for (uint j = 0; j < n; ++j) {
        LayoutSlot at = probe_slot(dims[j]);
        out[c * (n + 1u) + j] = (uint)(pss_load(state, c, num_chains, at) * (float)(1u << at.bits));
    }
    out[c * (n + 1u) + n] = values[c].meta & CHAIN_BOUNCES_MASK;
}

/* Burn-in samples first .. first + n - 1 (burnin_film.cl): out[3i], out[3i + 1]
 * are the film numbers of sample first + i, out[3i + 2] the pixel they
 * splat to. */
__kernel void probe_burnin_film(const BurnInFilm film, const Frame frame, const ulong first,
                                const uint n, __global uint* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    uint2 v = burnin_sample(&film, &frame, first + i).film;
    out[3u * i] = v.x;
    out[3u * i + 1u] = v.y;
    FilmTile whole = strata_whole(&frame);
    out[3u * i + 2u] = strata_point(&whole, &frame, layout_unit(v.x, LAYOUT_CAMERA_BITS),
                                    layout_unit(v.y, LAYOUT_CAMERA_BITS))
                           .pixel;
}
