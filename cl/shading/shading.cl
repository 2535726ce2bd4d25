/* The one interface through which the path scatters (cl/path/path.cl):
 * sample, and evaluate with pdf, a vertex's material, dispatched on its
 * model (MAT_MODELS). A model works in its shading frame (cl/shading/frame.cl)
 * and takes the same numbers everywhere: the lobe choice uc and the BSDF
 * pair (u1, u2), read by slot only where it declares them. Only the models
 * a scene uses are compiled in (LAYOUT_HAS_*, src/scene/sample_layout.cpp).
 *
 * Side rules. The geometric normal ng decides sides: a direction whose side
 * of ng differs from its side of the shading normal carries nothing, wo or
 * wi alike (so shading normals create no energy and leak no light). Opaque
 * models reflect on wo's side; MAT_FLAG_TWO_SIDED ones are mirrored to the
 * front when seen from the back, one-sided ones are black there.
 * Dielectrics are entered from the front. No path here carries
 * importance, so Veach's adjoint correction for shading normals has no
 * place to apply. wo and wi point away from the surface; pdf_w is per unit
 * solid angle. */

#define SHADING_MODEL_USES(NAME, id, uses) uses,
__constant uint shading_uses[MAT_TYPES] = {MAT_MODELS(SHADING_MODEL_USES)};
#undef SHADING_MODEL_USES

typedef struct {
    float3 f_cos; /* f(wo, wi) |cos| at the shading normal, RGB */
    float pdf_w;  /* the density with which shading_sample draws wi */
} ShadingEval;

/* Whether next-event estimation runs at the vertex: the material has a
 * lobe that is not a Dirac delta, so light sampling can reach it. */
inline bool shading_has_nee(const Material* m) {
    return (shading_uses[m->type] & MAT_USES_NEE) != 0u;
}

inline bool shading_opaque(const Material* m) {
    return m->type != MAT_DIELECTRIC && m->type != MAT_ROUGH_DIELECTRIC &&
           m->type != MAT_THIN_DIELECTRIC;
}

/* The model's sample in its local frame (wo.z > 0 for opaque models). */
inline BsdfSample shading_local_sample(const Material* m, float3 wo, float uc, float u1, float u2) {
    switch (m->type) {
#if LAYOUT_HAS_DIFFUSE
    case MAT_DIFFUSE:
        return diffuse_sample(m, wo, uc, u1, u2);
#endif
#if LAYOUT_HAS_CONDUCTOR
    case MAT_CONDUCTOR:
        return conductor_sample(m, wo, uc, u1, u2);
#endif
#if LAYOUT_HAS_ROUGH_CONDUCTOR
    case MAT_ROUGH_CONDUCTOR:
        return rough_conductor_sample(m, wo, uc, u1, u2);
#endif
#if LAYOUT_HAS_DIELECTRIC
    case MAT_DIELECTRIC:
        return dielectric_sample(m, wo, uc, u1, u2);
#endif
#if LAYOUT_HAS_ROUGH_DIELECTRIC
    case MAT_ROUGH_DIELECTRIC:
        return rough_dielectric_sample(m, wo, uc, u1, u2);
#endif
#if LAYOUT_HAS_PLASTIC || LAYOUT_HAS_ROUGH_PLASTIC
    case MAT_PLASTIC:
    case MAT_ROUGH_PLASTIC:
        return plastic_sample(m, wo, uc, u1, u2);
#endif
#if LAYOUT_HAS_THIN_DIELECTRIC
    case MAT_THIN_DIELECTRIC:
        return thin_dielectric_sample(m, wo, uc, u1, u2);
#endif
    default:
        return bsdf_none();
    }
}

/* f (RGB, without the cosine) of the model's non-Dirac lobes. */
inline float3 shading_local_eval(const Material* m, float3 wo, float3 wi) {
    switch (m->type) {
#if LAYOUT_HAS_DIFFUSE
    case MAT_DIFFUSE:
        return diffuse_eval(m, wo, wi);
#endif
#if LAYOUT_HAS_ROUGH_CONDUCTOR
    case MAT_ROUGH_CONDUCTOR:
        return rough_conductor_eval(m, wo, wi);
#endif
#if LAYOUT_HAS_ROUGH_DIELECTRIC
    case MAT_ROUGH_DIELECTRIC:
        return rough_dielectric_eval(m, wo, wi);
#endif
#if LAYOUT_HAS_PLASTIC || LAYOUT_HAS_ROUGH_PLASTIC
    case MAT_PLASTIC:
    case MAT_ROUGH_PLASTIC:
        return plastic_eval(m, wo, wi);
#endif
    default:
        return (float3)(0.0f);
    }
}

inline float shading_local_pdf_w(const Material* m, float3 wo, float3 wi) {
    switch (m->type) {
#if LAYOUT_HAS_DIFFUSE
    case MAT_DIFFUSE:
        return diffuse_pdf_w(m, wo, wi);
#endif
#if LAYOUT_HAS_ROUGH_CONDUCTOR
    case MAT_ROUGH_CONDUCTOR:
        return rough_conductor_pdf_w(m, wo, wi);
#endif
#if LAYOUT_HAS_ROUGH_DIELECTRIC
    case MAT_ROUGH_DIELECTRIC:
        return rough_dielectric_pdf_w(m, wo, wi);
#endif
#if LAYOUT_HAS_PLASTIC || LAYOUT_HAS_ROUGH_PLASTIC
    case MAT_PLASTIC:
    case MAT_ROUGH_PLASTIC:
        return plastic_pdf_w(m, wo, wi);
#endif
    default:
        return 0.0f;
    }
}

/* wo in the model's local frame, after the side rules; false where the
 * vertex reflects nothing toward wo. *mirror: work with z mirrored. */
inline bool shading_local_wo(const Material* m, const ShadingFrame* f, float3 wo_w, float3* wo,
                             bool* mirror) {
    float3 l = frame_to_local(f, wo_w);
    *mirror = false;
    if (dot(wo_w, f->ng) * l.z <= 0.0f) return false;
    if (l.z < 0.0f && shading_opaque(m)) {
        if ((m->flags & MAT_FLAG_TWO_SIDED) == 0u) return false;
        l.z = -l.z;
        *mirror = true;
    }
    *wo = l;
    return true;
}

inline float3 shading_mirror(float3 v, bool mirror) {
    return mirror ? (float3)(v.x, v.y, -v.z) : v;
}

/* Draws wi (world) from the bounce's numbers; the weight is f |cos| / pdf_w. */
inline BsdfSample shading_sample(SampleSource* src, uint bounce, const Material* m,
                                 const ShadingFrame* f, float3 wo_w) {
    float3 wo;
    bool mirror;
    if (!shading_local_wo(m, f, wo_w, &wo, &mirror)) return bsdf_none();
    uint uses = shading_uses[m->type];
    float uc = 0.0f, u1 = 0.0f, u2 = 0.0f;
#if SLOT_BSDF_CHOICE >= 0
    if (uses & MAT_USES_CHOICE) uc = smp_number(src, bounce, SLOT_BSDF_CHOICE);
#endif
#if SLOT_BSDF_U >= 0
    if (uses & MAT_USES_PAIR) {
        u1 = smp_number(src, bounce, SLOT_BSDF_U);
        u2 = smp_number(src, bounce, SLOT_BSDF_V);
    }
#endif
    (void)uses;
    BsdfSample s = shading_local_sample(m, wo, uc, u1, u2);
    float3 wi = shading_mirror(s.wi, mirror);
    s.wi = frame_to_world(f, wi);
    if (dot(s.wi, f->ng) * wi.z <= 0.0f) return bsdf_none();
    return s;
}

/* f |cos| and pdf_w of the non-Dirac lobes for the world pair (wo, wi). */
inline ShadingEval shading_eval(const Material* m, const ShadingFrame* f, float3 wo_w,
                                float3 wi_w) {
    ShadingEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf_w = 0.0f;
    float3 wo;
    bool mirror;
    if (!shading_local_wo(m, f, wo_w, &wo, &mirror)) return e;
    float3 wi = frame_to_local(f, wi_w);
    if (dot(wi_w, f->ng) * wi.z <= 0.0f) return e;
    wi = shading_mirror(wi, mirror);
    e.f_cos = shading_local_eval(m, wo, wi) * fabs(wi.z);
    e.pdf_w = shading_local_pdf_w(m, wo, wi);
    return e;
}
