/* Work-efficient inclusive prefix sum (Blelloch 1990) of SCAN_T values
 * (ulong unless defined otherwise: the burn-in's fixed-point weights, whose
 * sums are exact in any order). Each work-group of SCAN_WG work-items
 * scans 2 * SCAN_WG elements in local memory (up-sweep, then down-sweep) and
 * writes its total; the host scans the totals the same way and scan_add adds
 * each block's offset (src/device/scan.cpp). SCAN_WG is a power of two that the
 * host picks from the device's work-group limit. `in` and `out` may be the
 * same buffer: each work-item reads its two elements before it writes them. */

#ifndef SCAN_T
#define SCAN_T ulong
#endif

__kernel void scan_blocks(__global const SCAN_T* in, __global SCAN_T* out,
                          __global SCAN_T* block_sums, const uint n) {
    __local SCAN_T tmp[2 * SCAN_WG];
    uint lid = get_local_id(0);
    uint base = get_group_id(0) * 2u * SCAN_WG;
    uint i0 = base + 2u * lid, i1 = i0 + 1u;
    SCAN_T x0 = i0 < n ? in[i0] : (SCAN_T)0;
    SCAN_T x1 = i1 < n ? in[i1] : (SCAN_T)0;
    tmp[2u * lid] = x0;
    tmp[2u * lid + 1u] = x1;
    uint offset = 1u;
    for (uint d = SCAN_WG; d > 0u; d >>= 1) {
        barrier(CLK_LOCAL_MEM_FENCE);
        if (lid < d) {
            uint a = offset * (2u * lid + 1u) - 1u, b = offset * (2u * lid + 2u) - 1u;
            tmp[b] += tmp[a];
        }
        offset <<= 1;
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    if (lid == 0u) {
        block_sums[get_group_id(0)] = tmp[2u * SCAN_WG - 1u];
        tmp[2u * SCAN_WG - 1u] = (SCAN_T)0;
    }
    for (uint d = 1u; d < 2u * SCAN_WG; d <<= 1) {
        offset >>= 1;
        barrier(CLK_LOCAL_MEM_FENCE);
        if (lid < d) {
            uint a = offset * (2u * lid + 1u) - 1u, b = offset * (2u * lid + 2u) - 1u;
            SCAN_T t = tmp[a];
            tmp[a] = tmp[b];
            tmp[b] += t;
        }
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    if (i0 < n) out[i0] = tmp[2u * lid] + x0;
    if (i1 < n) out[i1] = tmp[2u * lid + 1u] + x1;
}

/* Adds the inclusive prefix of the block totals before each block. */
__kernel void scan_add(__global SCAN_T* out, __global const SCAN_T* block_prefix, const uint n) {
    uint block = get_group_id(0);
    if (block == 0u) return;
    uint base = block * 2u * SCAN_WG;
    uint lid = get_local_id(0);
    SCAN_T add = block_prefix[block - 1u];
    if (base + 2u * lid < n) out[base + 2u * lid] += add;
    if (base + 2u * lid + 1u < n) out[base + 2u * lid + 1u] += add;
}
