/* What every scattering model shares: the sample it returns and the
 * directions of the local frame (cl/shading/frame.cl: z is the shading
 * normal on the front side). Directions point away from the surface;
 * pdf_w is per unit solid angle. */

typedef struct {
    float3 wi;
    float3 weight; /* f |wi.z| / pdf_w, the factor the path throughput takes (0: no sample) */
    float pdf_w;   /* 0 for a Dirac lobe, whose weight is its throughput factor */
} BsdfSample;

inline BsdfSample bsdf_none(void) {
    BsdfSample s;
    s.wi = (float3)(0.0f, 0.0f, 1.0f);
    s.weight = (float3)(0.0f);
    s.pdf_w = 0.0f;
    return s;
}

inline float3 bsdf_rgb(const f32 c[3]) {
    return (float3)(c[0], c[1], c[2]);
}

/* Mirror reflection about the local normal. */
inline float3 bsdf_reflect_z(float3 wo) {
    return (float3)(-wo.x, -wo.y, wo.z);
}

/* Two Dirac lobes of a smooth interface: the mirror direction of wo,
 * carrying r, and wt, carrying (1 - r) eta^2 (eta: the radiance scaling of
 * a refraction, 1 for none). The reflection is chosen with probability r
 * rounded to the choice slot's grid (layout_quantize_prob), so that each
 * weight is exact; ks scales both. */
inline BsdfSample bsdf_dirac_pair(float3 wo, float3 wt, float r, float eta, float3 ks, float uc) {
    float p_reflect = layout_quantize_prob(r, LAYOUT_CHOICE_BITS);
    BsdfSample s;
    s.pdf_w = 0.0f;
    if (uc < p_reflect) {
        s.wi = bsdf_reflect_z(wo);
        s.weight = ks * (r / p_reflect);
    } else {
        s.wi = wt;
        s.weight = ks * ((1.0f - r) / (1.0f - p_reflect) * eta * eta);
    }
    return s;
}

/* Mirror reflection of wo about unit microfacet normal m. */
inline float3 bsdf_reflect(float3 wo, float3 m) {
    return 2.0f * dot(wo, m) * m - wo;
}

/* Cosine-weighted direction in the upper hemisphere from two numbers in
 * [0, 1): density z / pi. */
inline float3 bsdf_cosine_dir(float u1, float u2) {
    float r = sqrt(u1);
    float cos_phi;
    float sin_phi = sincos(2.0f * M_PI_F * u2, &cos_phi);
    return (float3)(r * cos_phi, r * sin_phi, sqrt(fmax(0.0f, 1.0f - u1)));
}
