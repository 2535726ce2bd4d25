/* A smooth conductor: mirror reflection of weight ks Fc(cos), Fc the
 * conductor Fresnel term of eta + i k (cl/shading/fresnel.cl). A Dirac
 * lobe: nothing to evaluate. Local frame, wo.z > 0. */

inline BsdfSample conductor_sample(const Material* m, float3 wo, float uc, float u1, float u2) {
    (void)uc;
    (void)u1;
    (void)u2;
    BsdfSample s;
    s.wi = bsdf_reflect_z(wo);
    s.weight = bsdf_rgb(m->ks) * fresnel_conductor(wo.z, bsdf_rgb(m->eta), bsdf_rgb(m->k));
    s.pdf_w = 0.0f;
    return s;
}
