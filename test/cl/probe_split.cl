/* Probe for the split's test (test/test_split.cpp): the parts of the OMC
 * path of key rng_key(seed, i, 0) through a film position drawn from its
 * numbers, as the program's PATH_SPLIT divides them. */

__kernel void probe_split(SCENE_ARGS, const ulong seed, const uint n, __global float4* omc,
                          __global float4* rest) {
    uint i = get_global_id(0);
    if (i >= n) return;
    SceneView sc = SCENE_VIEW();
    SampleSource src = smp_omc(rng_key(seed, i, 0u));
    float fx = smp_uniform(&src, 0u, layout_film(0u)), fy = smp_uniform(&src, 0u, layout_film(1u));
    PathResult r = path_trace(&sc, &src, camera_ray(&frame, fx, fy));
    omc[i] = (float4)(r.omc, (float)r.rays);
    rest[i] = (float4)(r.rest, 0.0f);
}
