/* Probes of texture lookups (test/test_texture.cpp). */

/* RGBA of texture `index` at uv[i]; hole[i]: whether a material with it as
 * its cut-out has a hole there. */
__kernel void probe_tex_lookup(__global const TextureInfo* infos, __global const Texel* texels,
                               const uint index, __global const float2* uv, const uint n,
                               __global float4* out, __global uint* hole) {
    uint i = get_global_id(0);
    if (i >= n) return;
    out[i] = tex_lookup(infos, texels, index, uv[i]);
    Material m;
    m.alpha_tex = index;
    hole[i] = tex_is_hole(&m, infos, texels, uv[i]) ? 1u : 0u;
}
