/* Burn-in by ordinary Monte Carlo (Frolov and Galaktionov, section 3.1): of
 * the M OMC samples of one iteration, keep picks chosen with probability
 * proportional to their luminance, by binary search in the inclusive prefix
 * sum of the luminances (scan.cl). A kept sample is kept as its index i in
 * the round: the key rng_key(round seed, i, 0) regenerates its path. */

/* First i with scan[i] > u (scan non-decreasing, u < scan[n - 1]). */
inline uint burnin_search(const __global float* scan, uint n, float u) {
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

/* Pick j of `count` (j = get_global_id(0)) from the n samples whose
 * luminances `scan` sums; writes sample number first_sample + i to
 * picks[first_pick + j]. A zero-weight sample is never picked. If the
 * iteration found no light, picks are uniform (such chains accept any
 * proposal that finds some). */
__kernel void burnin_pick(__global const float* scan, const uint n, const ulong seed,
                          const uint iteration, const uint first_sample, const uint first_pick,
                          const uint count, __global uint* picks) {
    uint j = get_global_id(0);
    if (j >= count) return;
    uint r = rng_u32(rng_key(seed, first_pick + j, iteration), 0u);
    float total = scan[n - 1u];
    uint i;
    if (total > 0.0f) {
        float u = fmin((float)(r >> 8) * (1.0f / 16777216.0f) * total, nextafter(total, 0.0f));
        i = burnin_search(scan, n, u);
    } else {
        i = (uint)(((ulong)r * n) >> 32);
    }
    picks[first_pick + j] = first_sample + i;
}
