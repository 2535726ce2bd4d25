/* Probe kernels for tests: they report what the device sees, so the host
 * can check it agrees (struct layout, BVH traversal). */

#define PROBE_OFFSET(T, field) ((uint)((size_t) & ((T*)0)->field))

/* Writes sizeof and field offsets of every shared struct, in the order that
 * src/shared_layout.cpp expects. */
__kernel void probe_layout(__global uint* out) {
    uint i = 0;
    out[i++] = sizeof(Triangle);
    out[i++] = PROBE_OFFSET(Triangle, material);
    out[i++] = PROBE_OFFSET(Triangle, e1);
    out[i++] = PROBE_OFFSET(Triangle, light_pick_prob);
    out[i++] = PROBE_OFFSET(Triangle, e2);
    out[i++] = PROBE_OFFSET(Triangle, light_index);
    out[i++] = sizeof(BvhNode);
    out[i++] = PROBE_OFFSET(BvhNode, offset);
    out[i++] = PROBE_OFFSET(BvhNode, hi);
    out[i++] = PROBE_OFFSET(BvhNode, count);
    out[i++] = sizeof(Material);
    out[i++] = PROBE_OFFSET(Material, type);
    out[i++] = PROBE_OFFSET(Material, ke);
    out[i++] = PROBE_OFFSET(Material, ior);
    out[i++] = PROBE_OFFSET(Material, ks);
    out[i++] = PROBE_OFFSET(Material, emissive);
    out[i++] = sizeof(LightEntry);
    out[i++] = PROBE_OFFSET(LightEntry, cdf_hi);
    out[i++] = sizeof(Frame);
    out[i++] = PROBE_OFFSET(Frame, width);
    out[i++] = PROBE_OFFSET(Frame, top_left);
    out[i++] = PROBE_OFFSET(Frame, height);
    out[i++] = PROBE_OFFSET(Frame, du);
    out[i++] = PROBE_OFFSET(Frame, depth);
    out[i++] = PROBE_OFFSET(Frame, dv);
    out[i++] = PROBE_OFFSET(Frame, num_lights);
    out[i++] = sizeof(ChainValue);
    out[i++] = PROBE_OFFSET(ChainValue, meta);
    out[i++] = PROBE_OFFSET(ChainValue, stay);
    out[i++] = sizeof(TargetCells);
    out[i++] = PROBE_OFFSET(TargetCells, columns);
    out[i++] = sizeof(BurnInFilm);
    out[i++] = PROBE_OFFSET(BurnInFilm, seed_hi);
    out[i++] = PROBE_OFFSET(BurnInFilm, offset);
    out[i++] = PROBE_OFFSET(BurnInFilm, step);
    out[i++] = PROBE_OFFSET(BurnInFilm, per_round);
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
