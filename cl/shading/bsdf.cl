/* Materials: Lambertian diffuse, ideal mirror, smooth dielectric (Fresnel
 * reflection and refraction). Directions point away from the surface; n is
 * the geometric normal (front face). pdf_w is per unit solid angle. */

typedef struct {
    float3 wi;
    float3 weight; /* f * |cos| / pdf_w, the factor the path throughput takes */
    float pdf_w;   /* 0 for a specular (Dirac) lobe */
} BsdfSample;

/* Cosine-weighted direction around n from two numbers in [0,1). */
inline float3 bsdf_cosine_dir(float3 n, float u1, float u2) {
    float r = sqrt(u1);
    float cos_phi;
    float sin_phi = sincos(2.0f * M_PI_F * u2, &cos_phi);
    float3 t = fabs(n.x) > 0.5f ? (float3)(n.z, 0.0f, -n.x) : (float3)(0.0f, -n.z, n.y);
    t = normalize(t);
    float3 b = cross(n, t);
    return normalize(t * (r * cos_phi) + b * (r * sin_phi) + n * sqrt(fmax(0.0f, 1.0f - u1)));
}

inline float3 bsdf_reflect(float3 wo, float3 n) {
    return 2.0f * dot(wo, n) * n - wo;
}

/* Unpolarized Fresnel reflectance; cos_i >= 0 on the incident side,
 * eta = eta_incident / eta_transmitted. Sets *cos_t for refraction. */
inline float bsdf_fresnel(float cos_i, float eta, float* cos_t) {
    float sin2_t = eta * eta * fmax(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
        *cos_t = 0.0f;
        return 1.0f;
    }
    float ct = sqrt(1.0f - sin2_t);
    *cos_t = ct;
    float r_s = (eta * cos_i - ct) / (eta * cos_i + ct);
    float r_p = (cos_i - eta * ct) / (cos_i + eta * ct);
    return 0.5f * (r_s * r_s + r_p * r_p);
}

inline BsdfSample bsdf_sample_diffuse(const Material* m, float3 n_wo, float u1, float u2) {
    BsdfSample s;
    s.wi = bsdf_cosine_dir(n_wo, u1, u2);
    s.weight = (float3)(m->kd[0], m->kd[1], m->kd[2]);
    s.pdf_w = fmax(dot(s.wi, n_wo), 0.0f) * M_1_PI_F;
    return s;
}

inline BsdfSample bsdf_sample_mirror(const Material* m, float3 wo, float3 n_wo) {
    BsdfSample s;
    s.wi = bsdf_reflect(wo, n_wo);
    s.weight = (float3)(m->ks[0], m->ks[1], m->ks[2]);
    s.pdf_w = 0.0f;
    return s;
}

/* Reflection or refraction through a smooth interface, chosen with
 * probability F rounded to the choice slot's grid (layout_quantize_prob), so
 * the weight is exact. Radiance is scaled by 1/eta^2 on refraction. */
inline BsdfSample bsdf_sample_dielectric(const Material* m, float3 wo, float3 n, float u_choice,
                                         uint choice_bits) {
    float cos_o = dot(wo, n);
    bool entering = cos_o > 0.0f;
    float3 n_wo = entering ? n : -n;
    float eta = entering ? 1.0f / m->ior : m->ior;
    float cos_i = fabs(cos_o), cos_t;
    float f = bsdf_fresnel(cos_i, eta, &cos_t);
    float p_reflect = layout_quantize_prob(f, choice_bits);
    BsdfSample s;
    s.pdf_w = 0.0f;
    if (u_choice < p_reflect) {
        s.wi = bsdf_reflect(wo, n_wo);
        s.weight = (float3)(f / p_reflect);
    } else {
        s.wi = normalize(-wo * eta + n_wo * (eta * cos_i - cos_t));
        s.weight = (float3)((1.0f - f) / (1.0f - p_reflect) * eta * eta);
    }
    return s;
}
