/* Probe kernels for the tests of the scattering models (test/test_bsdf.cpp),
 * in the models' local frame (z the shading normal, directions pointing away
 * from the surface). A material comes in a one-element buffer and is copied
 * to private memory, where the models read it. Sample i reads stream
 * rng_key(seed, i, 0): dimension 0 is the lobe choice, on the 16-bit grid of
 * the layout's choice slot; dimensions 1 and 2 are the BSDF pair, 24 bits
 * each, as the layout stores them. */

inline void probe_bsdf_numbers(ulong seed, uint i, float* uc, float* u1, float* u2) {
    ulong key = rng_key(seed, i, 0u);
    *uc = layout_unit(rng_u32(key, 0u) >> 16, 16u);
    *u1 = layout_unit(rng_u32(key, 1u) >> 8, 24u);
    *u2 = layout_unit(rng_u32(key, 2u) >> 8, 24u);
}

/* n samples of shading_local_sample at wo (xyz): out[3i] = (wi, pdf_w),
 * out[3i + 1] = (weight, shading_local_pdf_w(wo, wi)), out[3i + 2] =
 * (shading_local_eval(wo, wi), 0): the model's own evaluation at the
 * direction it drew, where with_eval is not 0 (else zeros). */
__kernel void probe_bsdf_sample(__global const Material* mat, const float4 wo, const ulong seed,
                                const uint n, const uint with_eval, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    Material m = mat[0];
    float uc, u1, u2;
    probe_bsdf_numbers(seed, i, &uc, &u1, &u2);
    BsdfSample s = shading_local_sample(&m, wo.xyz, uc, u1, u2);
    float pdf = 0.0f;
    float3 f = (float3)(0.0f);
    if (with_eval != 0u) {
        pdf = shading_local_pdf_w(&m, wo.xyz, s.wi);
        f = shading_local_eval(&m, wo.xyz, s.wi);
    }
    out[3 * i] = (float4)(s.wi, s.pdf_w);
    out[3 * i + 1] = (float4)(s.weight, pdf);
    out[3 * i + 2] = (float4)(f, 0.0f);
}

/* The white furnace's numbers: n samples at wo, out[i] = (weight, wi.z). */
__kernel void probe_bsdf_weights(__global const Material* mat, const float4 wo, const ulong seed,
                                 const uint n, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    Material m = mat[0];
    float uc, u1, u2;
    probe_bsdf_numbers(seed, i, &uc, &u1, &u2);
    BsdfSample s = shading_local_sample(&m, wo.xyz, uc, u1, u2);
    out[i] = (float4)(s.weight, s.wi.z);
}

/* f and pdf_w for pairs: out[i] = (shading_local_eval(wo[i], wi[i]),
 * shading_local_pdf_w(wo[i], wi[i])). */
__kernel void probe_bsdf_eval(__global const Material* mat, __global const float4* wo,
                              __global const float4* wi, const uint n, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    Material m = mat[0];
    float3 o = wo[i].xyz, d = wi[i].xyz;
    out[i] = (float4)(shading_local_eval(&m, o, d), shading_local_pdf_w(&m, o, d));
}

/* The chi-square tests' expected counts at wo, on a grid of nc x nphi cells
 * of the sphere in (c, phi), c = wi.y in [-1, 1] and phi = atan2(wi.z, wi.x)
 * in [-pi, pi) (an equal-area map: a cell's solid angle is its area in (c,
 * phi)). For the count cells listed in `cells` (index i * nphi + j):
 * out[k] = the sum of shading_local_pdf_w(wo, wi) over the sub x sub
 * midpoints of cell cells[k], for the host to scale by the sub-cells' solid
 * angle. */
__kernel void probe_bsdf_pdf_cells(__global const Material* mat, const float4 wo, const uint nc,
                                   const uint nphi, const uint sub, __global const uint* cells,
                                   const uint count, __global float* out) {
    uint k = get_global_id(0);
    if (k >= count) return;
    Material m = mat[0];
    uint i = cells[k] / nphi, j = cells[k] % nphi;
    float dc = 2.0f / (float)(nc * sub), dphi = 2.0f * M_PI_F / (float)(nphi * sub);
    float sum = 0.0f;
    for (uint a = 0; a < sub; ++a) {
        float c = -1.0f + ((float)(i * sub + a) + 0.5f) * dc;
        float s = sqrt(fmax(0.0f, 1.0f - c * c));
        for (uint b = 0; b < sub; ++b) {
            float phi = -M_PI_F + ((float)(j * sub + b) + 0.5f) * dphi;
            float cp, sp = sincos(phi, &cp);
            sum += shading_local_pdf_w(&m, wo.xyz, (float3)(s * cp, c, s * sp));
        }
    }
    out[k] = sum;
}

/* The microfacet functions at pairs of wo[i] and normals m[i]:
 * out[i] = (mf_d(m), mf_g1(wo, m), mf_pdf_visible(wo, m), mf_lambda(wo)).
 * mf_d and mf_pdf_visible are read only where m.z > 0 and (for the latter)
 * wo.z > 0, as they are defined. */
__kernel void probe_mf_eval(const float alpha, const uint beckmann, __global const float4* wo,
                            __global const float4* m, const uint n, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    float3 o = wo[i].xyz, h = m[i].xyz;
    bool b = beckmann != 0u;
    float d = h.z > 0.0f ? mf_d(h, alpha, b) : 0.0f;
    float pv = (h.z > 0.0f && o.z > 0.0f) ? mf_pdf_visible(o, h, alpha, b) : 0.0f;
    out[i] = (float4)(d, mf_g1(o, h, alpha, b), pv, mf_lambda(o, alpha, b));
}

/* n visible normals of wo (wo.z > 0) from mf_sample_visible, drawn from the
 * BSDF pair of stream i: out[i] = (m, 0). */
__kernel void probe_mf_sample(const float alpha, const uint beckmann, const float4 wo,
                              const ulong seed, const uint n, __global float4* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    float uc, u1, u2;
    probe_bsdf_numbers(seed, i, &uc, &u1, &u2);
    out[i] = (float4)(mf_sample_visible(wo.xyz, alpha, beckmann != 0u, u1, u2), 0.0f);
}
