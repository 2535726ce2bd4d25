/* Burn-in by ordinary Monte Carlo (Frolov and Galaktionov, section 3.1): of
 * the n OMC samples of one round, keep picks chosen with probability
 * proportional to their luminance, by binary search in the inclusive prefix
 * sum (scan.cl) of their weights: the luminances in 64-bit fixed point, so
 * the sums are exact and a sample keeps its share however small it is next
 * to the total. A kept sample is kept as its index i in the round: the key
 * rng_key(round seed, i, 0) regenerates its path. */

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

/* Pick j of `count` (j = get_global_id(0)) from the n samples whose weights
 * `scan` sums; writes the picked index to picks[first_pick + j]. u =
 * floor(r total / 2^64) for r, 64 bits of the pick's stream: (b - a) 2^64 /
 * total values of r, give or take one, map into [a, b), so sample i is
 * picked with probability weight_i / total within 2^-64, and a zero-weight
 * sample never is. If the round found no light, picks are
 * uniform (such chains accept any proposal that finds some). */
__kernel void burnin_pick(__global const ulong* scan, const uint n, const ulong seed,
                          const uint round, const uint first_pick, const uint count,
                          __global uint* picks) {
    uint j = get_global_id(0);
    if (j >= count) return;
    ulong key = rng_key(seed, first_pick + j, round);
    uint hi = rng_u32(key, 0u);
    ulong total = scan[n - 1u];
    uint i;
    if (total > 0ul)
        i = burnin_search(scan, n, mul_hi(((ulong)hi << 32) | rng_u32(key, 1u), total));
    else
        i = (uint)(((ulong)hi * n) >> 32);
    picks[first_pick + j] = i;
}
