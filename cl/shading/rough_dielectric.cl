/* A rough dielectric (Walter et al. 2007) of index ior (inside: z < 0),
 * GGX or Beckmann. The model is worked in the frame mirrored to wo's side
 * (wo.z > 0 there), with eta_t = eta_wi / eta_wo across the interface. A
 * normal m visible from wo is drawn, then reflection with probability
 * F(wo.m) rounded to the choice slot's grid, else refraction. With h the
 * (generalized) half vector:
 *   reflection   f = ks F D G / (4 |wo.z| |wi.z|),
 *   transmission f = ks (1 - F) D G |wo.h| |wi.h| / (|wo.z| |wi.z| (wo.h + eta_t wi.h)^2),
 * the latter for radiance, so that f(wo, wi) / eta_wo^2 = f(wi, wo) / eta_wi^2. */

typedef struct {
    float3 wo, wi; /* mirrored so that wo.z > 0 */
    float eta_t;   /* eta on wi's side of the interface over eta on wo's (if wi is transmitted) */
    bool flip;
} RoughDielectricFrame;

inline RoughDielectricFrame rough_dielectric_frame(const Material* m, float3 wo, float3 wi) {
    RoughDielectricFrame f;
    f.flip = wo.z < 0.0f;
    f.wo = f.flip ? (float3)(wo.x, wo.y, -wo.z) : wo;
    f.wi = f.flip ? (float3)(wi.x, wi.y, -wi.z) : wi;
    f.eta_t = f.flip ? 1.0f / m->ior : m->ior;
    return f;
}

inline bool rough_dielectric_beckmann(const Material* m) {
    return (m->flags & MAT_FLAG_BECKMANN) != 0u;
}

/* The half vector of the pair (facing wo), false where the pair has none. */
inline bool rough_dielectric_half(const RoughDielectricFrame* f, float3* h) {
    bool reflect = f->wi.z > 0.0f;
    float3 v = reflect ? f->wo + f->wi : f->wo + f->wi * f->eta_t;
    float l = length(v);
    if (!(l > 0.0f)) return false;
    v /= l;
    if (v.z < 0.0f) v = -v;
    *h = v;
    return dot(f->wo, v) > 0.0f && (reflect ? dot(f->wi, v) > 0.0f : dot(f->wi, v) < 0.0f);
}

/* Sets f (RGB, without the cosine) and pdf_w of the pair. */
inline void rough_dielectric_eval_pdf(const Material* m, float3 wo, float3 wi, float3* f_out,
                                      float* pdf_out) {
    *f_out = (float3)(0.0f);
    *pdf_out = 0.0f;
    if (wo.z == 0.0f || wi.z == 0.0f) return;
    RoughDielectricFrame fr = rough_dielectric_frame(m, wo, wi);
    float3 h;
    if (!rough_dielectric_half(&fr, &h)) return;
    bool bk = rough_dielectric_beckmann(m);
    float wo_h = dot(fr.wo, h), wi_h = dot(fr.wi, h), cos_t;
    /* For a transmitted pair both cosines are known: F from them is the
     * same from either side and well conditioned near the critical angle. */
    float F = fr.wi.z > 0.0f ? fresnel_dielectric(wo_h, 1.0f / fr.eta_t, &cos_t)
                             : fresnel_refracted(wo_h, -wi_h, fr.eta_t);
    float p = layout_quantize_prob(F, LAYOUT_CHOICE_BITS);
    float d = mf_d(h, m->alpha, bk);
    float g = mf_g1(fr.wo, h, m->alpha, bk) * mf_g1(fr.wi, h, m->alpha, bk);
    float pdf_h = mf_pdf_visible(fr.wo, h, m->alpha, bk);
    float cos_o = fr.wo.z, cos_i = fabs(fr.wi.z);
    if (fr.wi.z > 0.0f) {
        *f_out = bsdf_rgb(m->ks) * (F * d * g / (4.0f * cos_o * cos_i));
        *pdf_out = p * pdf_h / (4.0f * wo_h);
    } else {
        float den = wo_h + fr.eta_t * wi_h;
        den *= den;
        *f_out = bsdf_rgb(m->ks) * ((1.0f - F) * d * g * wo_h * fabs(wi_h) / (cos_o * cos_i * den));
        *pdf_out = (1.0f - p) * pdf_h * fabs(wi_h) * fr.eta_t * fr.eta_t / den;
    }
}

inline BsdfSample rough_dielectric_sample(const Material* m, float3 wo, float uc, float u1,
                                          float u2) {
    if (wo.z == 0.0f) return bsdf_none();
    RoughDielectricFrame fr = rough_dielectric_frame(m, wo, wo);
    bool bk = rough_dielectric_beckmann(m);
    float3 h = mf_sample_visible(fr.wo, m->alpha, bk, u1, u2);
    float wo_h = dot(fr.wo, h), cos_t;
    if (wo_h <= 0.0f) return bsdf_none();
    float eta = 1.0f / fr.eta_t; /* eta_wo / eta_wi, as fresnel_dielectric takes it */
    float F = fresnel_dielectric(wo_h, eta, &cos_t);
    float p = layout_quantize_prob(F, LAYOUT_CHOICE_BITS);
    BsdfSample s;
    float3 wi;
    float w;
    if (uc < p) {
        wi = bsdf_reflect(fr.wo, h);
        if (wi.z <= 0.0f) return bsdf_none();
        w = F / p;
    } else {
        wi = normalize(-fr.wo * eta + h * (eta * wo_h - cos_t));
        if (wi.z >= 0.0f) return bsdf_none();
        w = (1.0f - F) / (1.0f - p) * eta * eta;
    }
    /* f |wi.z| / pdf: D, G1(wo) and the Jacobians cancel. */
    s.weight = bsdf_rgb(m->ks) * (w * mf_g1(wi, h, m->alpha, bk));
    s.wi = fr.flip ? (float3)(wi.x, wi.y, -wi.z) : wi;
    float3 f;
    rough_dielectric_eval_pdf(m, wo, s.wi, &f, &s.pdf_w);
    return s;
}

inline float3 rough_dielectric_eval(const Material* m, float3 wo, float3 wi) {
    float3 f;
    float pdf;
    rough_dielectric_eval_pdf(m, wo, wi, &f, &pdf);
    return f;
}

inline float rough_dielectric_pdf_w(const Material* m, float3 wo, float3 wi) {
    float3 f;
    float pdf;
    rough_dielectric_eval_pdf(m, wo, wi, &f, &pdf);
    return pdf;
}
