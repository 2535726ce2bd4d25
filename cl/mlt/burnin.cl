/* Burn-in by ordinary Monte Carlo (Frolov and Galaktionov, section 3.1),
 * pooled over rounds by a weighted reservoir: T rounds of n OMC samples
 * each, one round in memory at a time; in round r every chain replaces its
 * pick, with probability s_r / (s_0 + .. + s_r) (s: a round's luminance
 * sum in the chain's stratum), by a sample of round r in its stratum drawn
 * in proportion to luminance. Each
 * chain's start is then an independent draw from all T n samples in
 * proportion to luminance. The draw within a round is a binary search in the
 * inclusive prefix sum (scan.cl) of the weights: the luminances in 64-bit
 * fixed point, so the sums are exact and a sample keeps its share however
 * small it is next to the total. A pick is kept as (round r, index i): the
 * key rng_key(omc_round_seed(r), i, 0) regenerates its path. */

/* Fixed-point weight of each luminance, in the order `order` (the round's
 * samples sorted by their stratum, src/render/strata.hpp): weight[i] is that
 * of lum[order[i]], lum * 2^exponent rounded to nearest, at least 1 if
 * lum > 0, 0 if lum is 0 or not finite. The host picks the exponent so that
 * the luminances' sum times 2^exponent is below 2^62: the weights' total
 * then stays below 2^63 (each rounding adds at most 1). */
__kernel void burnin_weights(__global const float* lum, __global const uint* order, const uint n,
                             const int exponent, __global ulong* weight) {
    uint i = get_global_id(0);
    if (i >= n) return;
    float x = ldexp(lum[order[i]], exponent);
    weight[i] = x > 0.0f && x <= 0x1p62f ? max(convert_ulong_rte(x), 1ul) : 0ul;
}

/* First i in [lo, hi) with scan[i] > u (scan non-decreasing, u < scan[hi - 1]). */
inline uint burnin_search(const __global ulong* scan, uint lo, uint hi, ulong u) {
    hi -= 1u;
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (scan[mid] > u)
            hi = mid;
        else
            lo = mid + 1u;
    }
    return lo;
}

/* Chain j of `count` (j = get_global_id(0)), of stratum
 * s = group_tile[j / group_chains] (mlt_step.cl, STRATA_ARGS),
 * replaces its pick picks[j] with probability replace[s] / 2^32 (2^32:
 * always) by a sample of this round in its stratum, (round, order[i]) with
 * first[s] <= i < first[s + 1], drawn from the samples whose weights `scan`
 * sums in that order. The streams are those of key rng_key(seed, j,
 * round): dimension 2 decides the replacement; u = floor(r total / 2^64)
 * for r, dimensions 0 and 1 (64 bits), where total is the stratum's part of
 * the sums: (b - a) 2^64 / total values of r, give or take one, map into
 * [a, b), so sample i is drawn with probability weight_i / total within
 * 2^-64, and a zero-weight sample never is. If the stratum's samples found
 * no light, the draw is uniform among them (such chains accept any proposal
 * that finds some); a stratum without samples this round keeps its picks. */
__kernel void burnin_pick(__global const ulong* scan, __global const uint* order,
                          __global const uint* first, __global const uint* group_tile,
                          const uint group_chains, const ulong seed, const uint round,
                          __global const ulong* replace, const uint count, __global uint2* picks) {
    uint j = get_global_id(0);
    if (j >= count) return;
    uint s = group_tile[j / group_chains], lo = first[s], hi = first[s + 1u];
    if (lo == hi) return;
    ulong key = rng_key(seed, j, round);
    if ((ulong)rng_u32(key, 2u) >= replace[s]) return;
    uint r_hi = rng_u32(key, 0u);
    ulong base = lo ? scan[lo - 1u] : 0ul, total = scan[hi - 1u] - base;
    uint i;
    if (total > 0ul)
        i = burnin_search(scan, lo, hi,
                          base + mul_hi(((ulong)r_hi << 32) | rng_u32(key, 1u), total));
    else
        i = lo + (uint)(((ulong)r_hi * (hi - lo)) >> 32);
    picks[j] = (uint2)(round, order[i]);
}
