/* Burn-in by ordinary Monte Carlo (Frolov and Galaktionov, section 3.1),
 * pooled over rounds by a weighted reservoir: T rounds of n OMC samples
 * each, one round in memory at a time; in round r every chain replaces its
 * pick, with probability s_r / (s_0 + .. + s_r) (s: a round's luminance
 * sum), by a sample of round r drawn in proportion to luminance. Each
 * chain's start is then an independent draw from all T n samples in
 * proportion to luminance. The draw within a round is a binary search in the
 * inclusive prefix sum (scan.cl) of the weights: the luminances in 64-bit
 * fixed point, so the sums are exact and a sample keeps its share however
 * small it is next to the total. A pick is kept as (round r, index i): the
 * key rng_key(omc_round_seed(r), i, 0) regenerates its path. */

/* Fixed-point weight of each luminance: lum * 2^exponent rounded to nearest,
 * at least 1 if lum > 0, 0 if lum is 0 or not finite. The host picks the
 * exponent so that the luminances' sum times 2^exponent is below 2^62: the
 * weights' total then stays below 2^63 (each rounding adds at most 1). */
__kernel void burnin_weights(__global const float* lum, const uint n, const int exponent,
                             __global ulong* weight) {
    uint i = get_global_id(0);
    if (i >= n) return;
    float x = ldexp(lum[i], exponent);
    weight[i] = x > 0.0f && x <= 0x1p62f ? max(convert_ulong_rte(x), 1ul) : 0ul;
}

/* First i with scan[i] > u (scan non-decreasing, u < scan[n - 1]). */
inline uint burnin_search(const __global ulong* scan, uint n, ulong u) {
    uint lo = 0u, hi = n - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (scan[mid] > u)
            hi = mid;
        else
            lo = mid + 1u;
    }
    return lo;
}

/* Chain j of `count` (j = get_global_id(0)) replaces its pick picks[j] with
 * probability replace / 2^32 (replace = 2^32: always) by a sample of this
 * round, (round, i), drawn from the n samples whose weights `scan` sums. The
 * streams are those of key rng_key(seed, j, round): dimension 2 decides the
 * replacement; u = floor(r total / 2^64) for r, dimensions 0 and 1 (64
 * bits): (b - a) 2^64 / total values of r, give or take one, map into
 * [a, b), so sample i is drawn with probability weight_i / total within
 * 2^-64, and a zero-weight sample never is. If the round found no light, the
 * draw is uniform (such chains accept any proposal that finds some). */
__kernel void burnin_pick(__global const ulong* scan, const uint n, const ulong seed,
                          const uint round, const ulong replace, const uint count,
                          __global uint2* picks) {
    uint j = get_global_id(0);
    if (j >= count) return;
    ulong key = rng_key(seed, j, round);
    if ((ulong)rng_u32(key, 2u) >= replace) return;
    uint hi = rng_u32(key, 0u);
    ulong total = scan[n - 1u];
    uint i;
    if (total > 0ul)
        i = burnin_search(scan, n, mul_hi(((ulong)hi << 32) | rng_u32(key, 1u), total));
    else
        i = (uint)(((ulong)hi * n) >> 32);
    picks[j] = (uint2)(round, i);
}
