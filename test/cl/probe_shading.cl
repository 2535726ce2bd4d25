/* Probes of the path's shading normals (test/test_shading_normals.cpp). */

/* The shading normal path_shading_normal gives where ray i (origin xyz in
 * o, direction in d) meets triangle `tri`; in w, the barycentrics' sum. */
__kernel void probe_shading_normal(SCENE_ARGS, const uint tri, __global const float4* o,
                                   __global const float4* d, const uint n, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    SceneView sc = SCENE_VIEW();
    Ray r;
    r.o = o[i].xyz;
    r.d = d[i].xyz;
    r.tmax = INFINITY;
    float3 ng = normalize(geo_tri_normal(&sc.tris[tri]));
    float2 b = geo_barycentrics(&r, &sc.tris[tri]);
    out[i] = (float4)(path_shading_normal(&sc, tri, b, ng), b.x + b.y);
}
