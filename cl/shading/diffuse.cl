/* Lambertian reflection of albedo kd: f = kd / pi, cosine-weighted
 * sampling (weight kd). Local frame, wo.z > 0. */

inline BsdfSample diffuse_sample(const Material* m, float3 wo, float uc, float u1, float u2) {
    (void)wo;
    (void)uc;
    BsdfSample s;
    s.wi = bsdf_cosine_dir(u1, u2);
    s.weight = bsdf_rgb(m->kd);
    s.pdf_w = s.wi.z * M_1_PI_F;
    return s;
}

inline float3 diffuse_eval(const Material* m, float3 wo, float3 wi) {
    (void)wo;
    return wi.z > 0.0f ? bsdf_rgb(m->kd) * M_1_PI_F : (float3)(0.0f);
}

inline float diffuse_pdf_w(const Material* m, float3 wo, float3 wi) {
    (void)m;
    (void)wo;
    return fmax(wi.z, 0.0f) * M_1_PI_F;
}
