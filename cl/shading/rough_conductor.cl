/* A rough conductor (Cook-Torrance with a GGX or Beckmann distribution,
 * cl/shading/microfacet.cl): f = ks Fc(wo.h) D(h) G1(wo) G1(wi) /
 * (4 wo.z wi.z), h the half vector, sampled by the normals visible from wo.
 * Local frame, wo.z > 0. */

inline bool rough_conductor_beckmann(const Material* m) {
    return (m->flags & MAT_FLAG_BECKMANN) != 0u;
}

inline BsdfSample rough_conductor_sample(const Material* m, float3 wo, float uc, float u1,
                                         float u2) {
    (void)uc;
    bool bk = rough_conductor_beckmann(m);
    float3 h = mf_sample_visible(wo, m->alpha, bk, u1, u2);
    BsdfSample s;
    s.wi = bsdf_reflect(wo, h);
    float wo_h = dot(wo, h);
    if (s.wi.z <= 0.0f || wo_h <= 0.0f) return bsdf_none();
    /* f wi.z / pdf with pdf = pdf_visible(h) / (4 wo.h): D and G1(wo) cancel. */
    s.weight = bsdf_rgb(m->ks) * fresnel_conductor(wo_h, bsdf_rgb(m->eta), bsdf_rgb(m->k)) *
               mf_g1(s.wi, h, m->alpha, bk);
    s.pdf_w = mf_pdf_visible(wo, h, m->alpha, bk) / (4.0f * wo_h);
    return s;
}

inline float3 rough_conductor_eval(const Material* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    bool bk = rough_conductor_beckmann(m);
    float3 h = normalize(wo + wi);
    float g = mf_g1(wo, h, m->alpha, bk) * mf_g1(wi, h, m->alpha, bk);
    float3 f = fresnel_conductor(dot(wo, h), bsdf_rgb(m->eta), bsdf_rgb(m->k));
    return bsdf_rgb(m->ks) * f * (mf_d(h, m->alpha, bk) * g / (4.0f * wo.z * wi.z));
}

inline float rough_conductor_pdf_w(const Material* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float3 h = normalize(wo + wi);
    return mf_pdf_visible(wo, h, m->alpha, rough_conductor_beckmann(m)) / (4.0f * dot(wo, h));
}
