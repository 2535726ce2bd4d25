/* Probe kernels for tests: they report what the device sees, so the host
 * can check it agrees (struct layout, BVH traversal). */

/* Offset of a field within an object of the kernel's own: offsets taken
 * from a null pointer come out wrong where null is not address 0 (Mesa's
 * OpenCL gives every field one byte less). */
#define PROBE_OFFSET(obj, field)                                                                   \
    ((uint)((__private const char*)&(obj).field - (__private const char*)&(obj)))

/* Writes sizeof and field offsets of every shared struct, in the order of
 * SHARED_LAYOUT (cl/core/shared_types.h), as host_layout does. */
#define PROBE_SIZE(T, size) out[i++] = sizeof(T);
#define PROBE_FIELD(T, field, off)                                                                 \
    {                                                                                              \
        T obj;                                                                                     \
        out[i++] = PROBE_OFFSET(obj, field);                                                       \
    }
__kernel void probe_layout(__global uint* out) {
    uint i = 0;
    SHARED_LAYOUT(PROBE_SIZE, PROBE_FIELD)
}

/* Closest hit of each ray (origin xyz, tmax in o; direction in d):
 * (triangle index or 0xFFFFFFFF, distance bits). */
__kernel void probe_closest(__global const Triangle* tris, __global const BvhNode* nodes,
                            __global const float4* o, __global const float4* d, __global uint2* out,
                            const uint n) {
    uint i = get_global_id(0);
    if (i >= n) return;
    Ray r;
    r.o = o[i].xyz;
    r.tmax = o[i].w;
    r.d = d[i].xyz;
    Hit h;
    bool found = bvh_trace(nodes, tris, &r, &h, false);
    out[i] = found ? (uint2)(h.tri, as_uint(h.t)) : (uint2)(0xFFFFFFFFu, 0u);
}

/* Adds n ones read from `ones` (64 of them) in one loop of n iterations:
 * n, unless the compiler ends loops after a count of iterations
 * (DeviceInfo::loop_iteration_limit). The loads keep the loop from being
 * folded away. Work-item 0 writes *out. */
__kernel void probe_loop_count(__global const uint* ones, const uint n, __global uint* out) {
    uint r = 0u;
    for (uint a = 0u; a < n; ++a)
        r += ones[a & 63u];
    if (get_global_id(0) == 0u) *out = r;
}

/* Reads scalar, 64-bit and struct arguments where work-items diverge: in a
 * branch some take, in a loop whose trip count differs per work-item, and
 * after some have returned (Mesa's llvmpipe warns that it treats such reads
 * as uniform; an argument's offset is a constant, so they are). Work-item
 * i writes out[i] = what it read, or ~0u where it returned first. */
__kernel void probe_divergent_args(__global uint* out, const uint a, const ulong b, const Frame f,
                                   const TargetCells c) {
    uint i = get_global_id(0);
    if (i % 7u == 3u) {
        out[i] = ~0u;
        return;
    }
    uint r = 0u;
    if (i % 3u == 1u) r += a + f.depth;
    for (uint k = 0u; k < i % 5u; ++k)
        r += (uint)(b >> 32) + c.columns + f.width;
    if (i & 1u) r ^= (uint)b + c.shift + f.num_lights;
    out[i] = r;
}

/* b's fixed point of each luminance, as the device computes it
 * (fixed_b_sample, cl/core/fixed_point.h). */
__kernel void probe_fixed_b(__global const float* lum, const uint n, __global ulong* out) {
    uint i = get_global_id(0);
    if (i < n) out[i] = fixed_b_sample(lum[i]);
}
