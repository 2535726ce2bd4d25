/* A thin dielectric sheet of index ior (Mitsuba 3's thindielectric): two
 * smooth parallel interfaces with no distance between them. Light bounces
 * between them, so the sheet reflects R = F + (1 - F)^2 F / (1 - F^2) =
 * 2F / (1 + F), F = F(|wo.z|), and lets the rest, 1 - R, through unbent
 * (the two refractions cancel: wi = -wo). Reflection is chosen with
 * probability R rounded to the choice slot's grid, so the weights are exact;
 * ks scales both lobes. The same from either side; Dirac lobes. */

inline BsdfSample thin_dielectric_sample(const Material* m, float3 wo, float uc, float u1,
                                         float u2) {
    (void)u1;
    (void)u2;
    float cos_t;
    float f = fresnel_dielectric(fabs(wo.z), 1.0f / m->ior, &cos_t);
    return bsdf_dirac_pair(wo, -wo, 2.0f * f / (1.0f + f), 1.0f, bsdf_rgb(m->ks), uc);
}
