/* Probe kernels for the chi-square tests of the sampling routines
 * (test/test_sampling.cpp): each draws n samples from stream numbers
 * rng_key(seed, i, 0) and reports them for the host to histogram. */

/* Points that light_sample_tri picks on triangle `tri`, seen from a point
 * one unit in front of its centroid: out[i] = the point (xyz). */
__kernel void probe_light_points(__global const Triangle* tris, __global const Material* mats,
                                 const uint tri, const ulong seed, const uint n,
                                 __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    const __global Triangle* t = &tris[tri];
    float3 c = geo_load3(t->v0) + (geo_load3(t->e1) + geo_load3(t->e2)) * (1.0f / 3.0f);
    float3 x = c + normalize(geo_tri_normal(t));
    ulong key = rng_key(seed, i, 0u);
    LightSample ls;
    bool ok = light_sample_tri(t, mats, x, rng_unit(key, 0u), rng_unit(key, 1u), &ls);
    out[i] = ok ? (float4)(x + ls.wi * ls.dist, 1.0f) : (float4)(0.0f);
}

/* Lights that light_pick chooses for uniform `bits`-wide numbers. */
__kernel void probe_light_picks(__global const LightEntry* lights, const uint num_lights,
                                const uint bits, const ulong seed, const uint n,
                                __global uint* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    uint u = rng_u32(rng_key(seed, i, 0u), 0u) >> (32u - bits);
    out[i] = light_pick(lights, num_lights, u);
}

/* Directions of diffuse_sample around normal n (xyz), in the world through
 * the shading frame of n, with its pdf_w in w. */
__kernel void probe_diffuse_dirs(const float4 n, const ulong seed, const uint n_samples,
                                 __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n_samples) return;
    ulong key = rng_key(seed, i, 0u);
    Material m;
    m.kd[0] = m.kd[1] = m.kd[2] = 0.5f;
    float3 nn = normalize(n.xyz);
    ShadingFrame f = frame_make(nn, nn);
    BsdfSample s =
        diffuse_sample(&m, (float3)(0.0f, 0.0f, 1.0f), 0.0f, rng_unit(key, 0u), rng_unit(key, 1u));
    out[i] = (float4)(frame_to_world(&f, s.wi), s.pdf_w);
}

/* Reflections (1) or refractions (0) that dielectric_sample chooses for an
 * incoming direction at cosine cos_o to the normal (0, 0, 1), with a choice
 * number of LAYOUT_CHOICE_BITS bits; the weight goes to weights[i]. */
__kernel void probe_dielectric_choice(const float cos_o, const float ior, const ulong seed,
                                      const uint n, __global uint* reflected,
                                      __global float* weights) {
    uint i = get_global_id(0);
    if (i >= n) return;
    Material m;
    m.ior = ior;
    m.ks[0] = m.ks[1] = m.ks[2] = 1.0f;
    float3 wo = (float3)(sqrt(fmax(0.0f, 1.0f - cos_o * cos_o)), 0.0f, cos_o);
    uint bits = LAYOUT_CHOICE_BITS;
    float u = layout_unit(rng_u32(rng_key(seed, i, 0u), 0u) >> (32u - bits), bits);
    BsdfSample s = dielectric_sample(&m, wo, u, 0.0f, 0.0f);
    reflected[i] = s.wi.z * cos_o > 0.0f ? 1u : 0u;
    weights[i] = s.weight.x;
}
