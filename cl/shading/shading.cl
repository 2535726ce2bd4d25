/* The one interface through which the path scatters (cl/path/path.cl):
 * sample, evaluate and pdf of a vertex's material, dispatched on its type.
 * Each material reads its own numbers of the bounce by slot (layout.cl):
 * a pair for a direction, a choice where it has lobes. Only the materials
 * a scene uses are compiled in (LAYOUT_HAS_*, src/scene/sample_layout.cpp).
 * wo and wi point away from the surface; n is the geometric normal, n_wo
 * the side of it that wo is on. pdf_w is per unit solid angle. */

/* Whether next-event estimation runs at the vertex: the material has a
 * lobe that is not a Dirac delta, so light sampling can reach it. */
inline bool shading_has_nee(const Material* m) {
    return m->type == MAT_DIFFUSE;
}

/* f(wo, wi), RGB, of the non-specular lobes (0 where wi is below n_wo). */
inline float3 shading_eval(const Material* m, float3 wo, float3 wi, float3 n_wo) {
    (void)wo;
    if (m->type != MAT_DIFFUSE || dot(wi, n_wo) <= 0.0f) return (float3)(0.0f);
    return (float3)(m->kd[0], m->kd[1], m->kd[2]) * M_1_PI_F;
}

/* The solid-angle density with which shading_sample draws wi from wo (its
 * non-specular lobes). */
inline float shading_pdf_w(const Material* m, float3 wo, float3 wi, float3 n_wo) {
    (void)wo;
    if (m->type != MAT_DIFFUSE) return 0.0f;
    return fmax(dot(wi, n_wo), 0.0f) * M_1_PI_F;
}

/* Draws wi from the bounce's numbers; the weight is f |cos| / pdf_w. */
inline BsdfSample shading_sample(SampleSource* src, uint bounce, const Material* m, float3 wo,
                                 float3 n, float3 n_wo) {
#if LAYOUT_HAS_DIELECTRIC
    if (m->type == MAT_DIELECTRIC)
        return bsdf_sample_dielectric(m, wo, n, smp_number(src, bounce, SLOT_BSDF_CHOICE),
                                      SLOT_BSDF_CHOICE_BITS);
#endif
#if LAYOUT_HAS_CONDUCTOR
    if (m->type == MAT_CONDUCTOR) return bsdf_sample_mirror(m, wo, n_wo);
#endif
#if LAYOUT_HAS_DIFFUSE
    float u1 = smp_number(src, bounce, SLOT_BSDF_U);
    float u2 = smp_number(src, bounce, SLOT_BSDF_V);
    return bsdf_sample_diffuse(m, n_wo, u1, u2);
#else
    BsdfSample none;
    none.weight = (float3)(0.0f);
    none.pdf_w = 0.0f;
    none.wi = n_wo;
    return none;
#endif
}
