/* Plastic: a diffuse base of albedo kd under a dielectric coat of index
 * ior, smooth (MAT_PLASTIC: the coat is a Dirac reflection of weight
 * ks F(wo.z)) or rough (MAT_ROUGH_PLASTIC: the coat is a microfacet lobe
 * ks F(wo.h) D G / (4 wo.z wi.z)). The base, seen through the coat (the
 * model of Mitsuba 3's plastic and roughplastic):
 *   f_base = kd / pi t(wo.z) t(wi.z) / (ior^2 (1 - fdr_int)),
 * t the coat's transmittance (1 - F for a smooth coat; the host's table for
 * a rough one, src/scene/plastic_coat.cpp) and fdr_int its hemispherical
 * reflectance from inside (inner reflections summed linearly), so that
 * kd = ks = 1 reflects everything under a smooth coat and loses only the
 * microfacets' shadowing under a rough one. The choice picks the coat with
 * probability q = F s / (F s + (1 - F)(1 - s)), F = F(wo.z),
 * s = spec_weight, rounded to the choice slot's grid. Local frame,
 * wo.z > 0. */

inline float plastic_fresnel(const Material* m, float cos_i) {
    float cos_t;
    return fresnel_dielectric(cos_i, 1.0f / m->ior, &cos_t);
}

inline bool plastic_rough(const Material* m) {
    return m->type == MAT_ROUGH_PLASTIC;
}

inline float plastic_coat_entry(const Material* m, int i) {
    return (float)((m->coat_t[COAT_T_WORD(i)] >> COAT_T_SHIFT(i)) & 0xFFFFu) * (1.0f / COAT_T_ONE);
}

/* t(cos_i): the light the coat lets through from (or to) a direction at
 * cosine cos_i. */
inline float plastic_transmittance(const Material* m, float cos_i) {
    if (!plastic_rough(m)) return 1.0f - plastic_fresnel(m, cos_i);
    float x = clamp(cos_i, 0.0f, 1.0f) * (float)(COAT_T_SIZE - 1);
    int i = min((int)x, COAT_T_SIZE - 2);
    return mix(plastic_coat_entry(m, i), plastic_coat_entry(m, i + 1), x - (float)i);
}

inline float plastic_coat_prob(const Material* m, float f_o) {
    float s = m->spec_weight;
    float a = f_o * s, b = (1.0f - f_o) * (1.0f - s);
    return layout_quantize_prob(a + b > 0.0f ? a / (a + b) : 0.0f, LAYOUT_CHOICE_BITS);
}

inline float3 plastic_base(const Material* m, float3 wo, float3 wi) {
    if (wi.z <= 0.0f) return (float3)(0.0f);
    float k = plastic_transmittance(m, wo.z) * plastic_transmittance(m, wi.z) /
              (m->ior * m->ior * (1.0f - m->fdr_int));
    return bsdf_rgb(m->kd) * (k * M_1_PI_F);
}

/* The rough coat's f and its pdf (before the choice). */
inline float3 plastic_coat(const Material* m, float3 wo, float3 wi, float* pdf_w) {
    *pdf_w = 0.0f;
    if (wi.z <= 0.0f) return (float3)(0.0f);
    bool bk = (m->flags & MAT_FLAG_BECKMANN) != 0u;
    float3 h = normalize(wo + wi);
    float wo_h = dot(wo, h);
    if (wo_h <= 0.0f) return (float3)(0.0f);
    *pdf_w = mf_pdf_visible(wo, h, m->alpha, bk) / (4.0f * wo_h);
    float g = mf_g1(wo, h, m->alpha, bk) * mf_g1(wi, h, m->alpha, bk);
    return bsdf_rgb(m->ks) *
           (plastic_fresnel(m, wo_h) * mf_d(h, m->alpha, bk) * g / (4.0f * wo.z * wi.z));
}

inline float3 plastic_eval(const Material* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return (float3)(0.0f);
    float3 f = plastic_base(m, wo, wi);
    if (plastic_rough(m)) {
        float pdf;
        f += plastic_coat(m, wo, wi, &pdf);
    }
    return f;
}

inline float plastic_pdf_w(const Material* m, float3 wo, float3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float q = plastic_coat_prob(m, plastic_fresnel(m, wo.z));
    float pdf = (1.0f - q) * wi.z * M_1_PI_F;
    if (plastic_rough(m)) {
        float pdf_coat;
        plastic_coat(m, wo, wi, &pdf_coat);
        pdf += q * pdf_coat;
    }
    return pdf;
}

inline BsdfSample plastic_sample(const Material* m, float3 wo, float uc, float u1, float u2) {
    float f_o = plastic_fresnel(m, wo.z);
    float q = plastic_coat_prob(m, f_o);
    BsdfSample s;
    if (!plastic_rough(m)) {
        if (uc < q) {
            s.wi = bsdf_reflect_z(wo);
            s.weight = bsdf_rgb(m->ks) * (f_o / q);
            s.pdf_w = 0.0f;
            return s;
        }
        s.wi = bsdf_cosine_dir(u1, u2);
        s.pdf_w = (1.0f - q) * s.wi.z * M_1_PI_F;
        s.weight = plastic_base(m, wo, s.wi) * (M_PI_F / (1.0f - q));
        return s;
    }
    if (uc < q) {
        float3 h = mf_sample_visible(wo, m->alpha, (m->flags & MAT_FLAG_BECKMANN) != 0u, u1, u2);
        s.wi = bsdf_reflect(wo, h);
    } else {
        s.wi = bsdf_cosine_dir(u1, u2);
    }
    if (s.wi.z <= 0.0f) return bsdf_none();
    s.pdf_w = plastic_pdf_w(m, wo, s.wi);
    if (!(s.pdf_w > 0.0f)) return bsdf_none();
    s.weight = plastic_eval(m, wo, s.wi) * (s.wi.z / s.pdf_w);
    return s;
}
