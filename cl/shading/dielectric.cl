/* A smooth dielectric of index ior (inside: wo.z < 0): Fresnel reflection
 * or refraction, chosen with probability F rounded to the choice slot's grid
 * (layout_quantize_prob), so that the weight is exact. Radiance is scaled by
 * (eta_wo / eta_wi)^2 on refraction; ks scales both lobes. Dirac lobes. */

inline BsdfSample dielectric_sample(const Material* m, float3 wo, float uc, float u1, float u2) {
    (void)u1;
    (void)u2;
    bool entering = wo.z > 0.0f;
    float eta = entering ? 1.0f / m->ior : m->ior;
    float cos_i = fabs(wo.z), cos_t;
    float f = fresnel_dielectric(cos_i, eta, &cos_t);
    float side = entering ? 1.0f : -1.0f;
    float3 wt = normalize((float3)(-wo.x * eta, -wo.y * eta, -side * cos_t));
    return bsdf_dirac_pair(wo, wt, f, eta, bsdf_rgb(m->ks), uc);
}
