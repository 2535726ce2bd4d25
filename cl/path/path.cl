/* The path: unidirectional path tracing with next-event estimation and MIS
 * (power heuristic) at every vertex whose material has a non-specular lobe,
 * Russian roulette by the throughput (path_survives). Written once for every
 * method: it reads its numbers only through smp_number and does not know who
 * provides them, and it reaches materials only through cl/shading/shading.cl.
 * Bounce b owns the numbers for scattering at the b-th surface vertex, so a
 * path of depth D (D bounces at most) consumes bounces 0 .. D-1.
 *
 * The split (src/render/split.hpp): each term of the estimator is light
 * reaching the camera after L surface vertices (emission hit at bounce b:
 * L = b; next-event estimation at bounce b: L = b + 1). Terms with
 * L < PATH_SPLIT form the OMC part, rendered by per-pixel samples; the rest
 * is the MLT part. PATH_SPLIT 0 puts everything in the rest. The parts are
 * accumulated apart, so omc + rest is the path tracer's estimate. */

#ifndef PATH_SPLIT
#define PATH_SPLIT 0
#endif

/* Holes of cut-outs a ray may pass through before it counts as blocked
 * (bounded, so that no loop runs forever). */
#define PATH_MAX_HOLES 16u

typedef struct {
    const __global Triangle* tris;
    const __global TriangleNormals* normals;
    const __global TriangleUVs* uvs;
    const __global TextureInfo* textures;
    const __global Texel* texels;
    const __global BvhNode* nodes;
    const __global Material* mats;
    const __global LightEntry* lights;
    uint num_lights;
    uint depth;
} SceneView;

typedef struct {
    float3 omc;  /* terms with L < PATH_SPLIT: the OMC part, RGB */
    float3 rest; /* the other terms: the MLT part F(x), RGB */
    /* Luminance of the MLT part's next-event estimates that a smooth
     * transmitter (glass, water) blocked, valued as if it had let the
     * shadow ray through: light that reaches those vertices only through a
     * Dirac lobe, which path tracing finds only by hitting the light. */
    float behind_specular;
    uint rays;    /* rays traced: closest-hit and shadow */
    uint bounces; /* surface vertices that scattered (read their bounce's numbers) */
} PathResult;

inline float3 path_rgb(const f32 c[3]) {
    return (float3)(c[0], c[1], c[2]);
}

inline float path_max3(float3 v) {
    return fmax(v.x, fmax(v.y, v.z));
}

/* The hit's barycentrics, where shading normals or textures need them. */
inline float2 path_barycentrics(const SceneView* sc, const Ray* ray, const Hit* hit) {
#if LAYOUT_HAS_SHADING_NORMALS || LAYOUT_HAS_TEXTURES
    return geo_barycentrics(ray, &sc->tris[hit->tri]);
#else
    (void)sc;
    (void)ray;
    (void)hit;
    return (float2)(0.0f);
#endif
}

/* The shading normal at barycentrics b of triangle `tri`: its vertex
 * normals interpolated, turned to the geometric normal ng's side; ng itself
 * where the scene has no vertex normals. */
inline float3 path_shading_normal(const SceneView* sc, uint tri, float2 b, float3 ng) {
#if LAYOUT_HAS_SHADING_NORMALS
    const __global TriangleNormals* tn = &sc->normals[tri];
    float3 n =
        geo_load3(tn->n0) * (1.0f - b.x - b.y) + geo_load3(tn->n1) * b.x + geo_load3(tn->n2) * b.y;
    float l = length(n);
    if (!(l > 0.0f)) return ng;
    n /= l;
    return dot(n, ng) < 0.0f ? -n : n;
#else
    (void)sc;
    (void)tri;
    (void)b;
    return ng;
#endif
}

/* Texture coordinates at barycentrics b of triangle `tri`. */
inline float2 path_uv(const SceneView* sc, uint tri, float2 b) {
#if LAYOUT_HAS_TEXTURES
    const __global TriangleUVs* t = &sc->uvs[tri];
    return (float2)(t->uv0[0], t->uv0[1]) * (1.0f - b.x - b.y) +
           (float2)(t->uv1[0], t->uv1[1]) * b.x + (float2)(t->uv2[0], t->uv2[1]) * b.y;
#else
    (void)sc;
    (void)tri;
    (void)b;
    return (float2)(0.0f);
#endif
}

/* What the hit sees: its material with its textures applied and its shading
 * frame. False where the hit falls in a hole of a cut-out: the ray passes. */
inline bool path_surface(const SceneView* sc, const Ray* ray, const Hit* hit, Material* m,
                         ShadingFrame* f) {
    const __global Triangle* tri = &sc->tris[hit->tri];
    *m = sc->mats[tri->material];
    float3 ng = normalize(geo_tri_normal(tri));
    float2 b = path_barycentrics(sc, ray, hit);
#if LAYOUT_HAS_TEXTURES
    float2 uv = path_uv(sc, hit->tri, b);
    f->ng = ng;
    if (tex_is_hole(m, sc->textures, sc->texels, uv)) return false;
    tex_apply(m, sc->textures, sc->texels, uv);
#endif
    *f = frame_make(path_shading_normal(sc, hit->tri, b, ng), ng);
    return true;
}

/* The ray continued past the point it reached at distance t, on its way. */
inline void path_pass(Ray* ray, float t, float3 ng) {
    float3 x = ray->o + ray->d * t;
    float3 o = geo_offset(x, dot(ray->d, ng) >= 0.0f ? ng : -ng);
    if (ray->tmax < INFINITY) ray->tmax = fmax(ray->tmax - length(o - ray->o), 0.0f);
    ray->o = o;
}

/* What a shadow ray meets. */
#define PATH_LIT 0u             /* nothing: the light is seen */
#define PATH_SHADOWED 1u        /* a surface */
#define PATH_BEHIND_SPECULAR 2u /* a smooth transmitter (no lobe for NEE, not opaque) */

inline uint path_blocker(const Material* m) {
    return !shading_has_nee(m) && !shading_opaque(m) ? PATH_BEHIND_SPECULAR : PATH_SHADOWED;
}

/* What blocks the shadow ray, if anything: with cut-outs, a hole lets it
 * through (at most PATH_MAX_HOLES of them); without, the blocker is any
 * surface on the ray, not necessarily the first. */
inline uint path_shadow(const SceneView* sc, Ray shadow, uint* rays) {
    Hit h;
    Material m;
#if LAYOUT_HAS_CUTOUTS
    for (uint i = 0; i <= PATH_MAX_HOLES; ++i) {
        ++*rays;
        if (!bvh_trace(sc->nodes, sc->tris, &shadow, &h, false)) return PATH_LIT;
        ShadingFrame f;
        if (path_surface(sc, &shadow, &h, &m, &f)) return path_blocker(&m);
        path_pass(&shadow, h.t, normalize(geo_tri_normal(&sc->tris[h.tri])));
    }
    return PATH_SHADOWED;
#else
    ++*rays;
    if (!bvh_trace(sc->nodes, sc->tris, &shadow, &h, true)) return PATH_LIT;
    m = sc->mats[sc->tris[h.tri].material];
    return path_blocker(&m);
#endif
}

/* Direct light at vertex x seen from wo, at material m of shading frame f.
 * Where a smooth transmitter blocks it, *behind is what it would have been
 * without that surface and without MIS (the light's whole direct estimate);
 * otherwise *behind is left as it is. */
float3 path_next_event(const SceneView* sc, SampleSource* src, uint bounce, float3 x, float3 wo,
                       const ShadingFrame* f, const Material* m, uint* rays, float3* behind) {
#if LAYOUT_HAS_NEE
    uint pick = 0;
#if SLOT_LIGHT_PICK >= 0
    float u_pick = smp_number(src, bounce, SLOT_LIGHT_PICK);
    pick = light_pick(sc->lights, sc->num_lights,
                      (uint)(u_pick * (float)(1u << SLOT_LIGHT_PICK_BITS)));
#endif
    const __global Triangle* lt = &sc->tris[sc->lights[pick].triangle];
    float u1 = smp_number(src, bounce, SLOT_LIGHT_U);
    float u2 = smp_number(src, bounce, SLOT_LIGHT_V);
    LightSample ls;
    if (!light_sample_tri(lt, sc->mats, x, u1, u2, &ls)) return (float3)(0.0f);
    ShadingEval e = shading_eval(m, f, wo, ls.wi);
    /* No shadow ray where nothing would be carried; a NaN goes on, to be
     * dropped and counted with its sample. */
    if (e.f_cos.x == 0.0f && e.f_cos.y == 0.0f && e.f_cos.z == 0.0f) return (float3)(0.0f);
    /* Aimed from the offset origin at the light's point, and stopped just
     * short of it: along wi itself, the offset would meet the light's plane
     * before the point wherever wi is shallow to it, and the light would
     * shadow itself. */
    Ray shadow;
    shadow.o = geo_offset(x, dot(ls.wi, f->ng) >= 0.0f ? f->ng : -f->ng);
    float3 to_light = x + ls.wi * ls.dist - shadow.o;
    float reach = length(to_light);
    shadow.d = to_light / reach;
    shadow.tmax = reach * (1.0f - 1e-4f);
    uint blocker = path_shadow(sc, shadow, rays);
    if (blocker == PATH_BEHIND_SPECULAR) *behind = ls.radiance * e.f_cos / ls.pdf_w;
    if (blocker != PATH_LIT) return (float3)(0.0f);
    float w = light_power_heuristic(ls.pdf_w, e.pdf_w);
    return ls.radiance * e.f_cos * (w / ls.pdf_w);
#else
    return (float3)(0.0f);
#endif
}

/* Luminance (Rec. 709 weights): the MLT target function I = lum(F). */
inline float path_luminance(float3 c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

/* Russian roulette after scattering at `bounce` (the rule of Roulette in
 * src/scene/sample_layout.hpp): false ends the path, otherwise *beta is
 * divided by the survival probability. No number is read while the
 * throughput measure is at or above RR_THRESHOLD (and RR_CAP is 1). */
inline bool path_survives(SampleSource* src, uint bounce, float3* beta) {
#if SLOT_RR >= 0
    if (bounce < RR_START_BOUNCE) return true;
#if RR_BY_LUMINANCE
    float m = path_luminance(*beta);
#else
    float m = path_max3(*beta);
#endif
    float p = fmin(RR_CAP, m * (1.0f / RR_THRESHOLD));
    if (p >= 1.0f) return true;
    float q = layout_quantize_prob(p, SLOT_RR_BITS);
    if (smp_number(src, bounce, SLOT_RR) >= q) return false;
    *beta /= q;
#endif
    return true;
}

/* Adds a term of light that reached the camera after `vertices` surface
 * vertices to its part. */
inline void path_add(PathResult* res, uint vertices, float3 c) {
    if (vertices < PATH_SPLIT)
        res->omc += c;
    else
        res->rest += c;
}

/* The whole estimate: both parts. */
inline float3 path_radiance(const PathResult* r) {
    return r->omc + r->rest;
}

/* Radiance carried to the camera along `ray` by the path that src defines. */
PathResult path_trace(const SceneView* sc, SampleSource* src, Ray ray) {
    PathResult res;
    res.omc = (float3)(0.0f);
    res.rest = (float3)(0.0f);
    res.behind_specular = 0.0f;
    res.rays = 0;
    res.bounces = 0;
    float3 beta = (float3)(1.0f);
    float prev_pdf_w = 0.0f; /* 0: previous vertex was specular or the camera */
    uint bounce = 0, holes = 0;
    for (;;) {
        Hit hit;
        ++res.rays;
        if (!bvh_trace(sc->nodes, sc->tris, &ray, &hit, false)) break;
        const __global Triangle* tri = &sc->tris[hit.tri];
        Material m;
        ShadingFrame f;
        if (!path_surface(sc, &ray, &hit, &m, &f)) {
            if (++holes > PATH_MAX_HOLES) break;
            path_pass(&ray, hit.t, f.ng);
            continue;
        }
        float3 wo = -ray.d;
        float cos_o = dot(f.ng, wo);
        if (m.emissive && cos_o > 0.0f) {
            float w = 1.0f;
            if (prev_pdf_w > 0.0f)
                w = light_power_heuristic(prev_pdf_w, light_pdf_w(tri, hit.t, cos_o));
            path_add(&res, bounce, beta * path_rgb(m.ke) * w);
        }
        if (bounce >= sc->depth) break;
        res.bounces = bounce + 1u;
        float3 x = ray.o + ray.d * hit.t;
        if (shading_has_nee(&m)) {
            float3 behind = (float3)(0.0f);
            path_add(&res, bounce + 1u,
                     beta * path_next_event(sc, src, bounce, x, wo, &f, &m, &res.rays, &behind));
            if (bounce + 1u >= PATH_SPLIT) res.behind_specular += path_luminance(beta * behind);
        }
        BsdfSample bs = shading_sample(src, bounce, &m, &f, wo);
        beta *= bs.weight;
        prev_pdf_w = bs.pdf_w;
        if (!(path_max3(beta) > 0.0f) || !path_survives(src, bounce, &beta)) break;
        ray.o = geo_offset(x, dot(bs.wi, f.ng) >= 0.0f ? f.ng : -f.ng);
        ray.d = bs.wi;
        ray.tmax = INFINITY;
        ++bounce;
    }
    return res;
}

/* False for a radiance with a NaN or infinite channel: such a sample is
 * dropped and counted by every method, never added to the image. */
inline bool path_finite(float3 c) {
    return isfinite(c.x) && isfinite(c.y) && isfinite(c.z);
}

inline SceneView path_scene(const __global Triangle* tris, const __global TriangleNormals* normals,
                            const __global TriangleUVs* uvs, const __global BvhNode* nodes,
                            const __global Material* materials, const __global LightEntry* lights,
                            const __global TextureInfo* textures, const __global Texel* texels,
                            const Frame* frame) {
    SceneView sc;
    sc.tris = tris;
    sc.normals = normals;
    sc.uvs = uvs;
    sc.nodes = nodes;
    sc.mats = materials;
    sc.lights = lights;
    sc.textures = textures;
    sc.texels = texels;
    sc.num_lights = frame->num_lights;
    sc.depth = frame->depth;
    return sc;
}

/* The scene as a kernel's parameters (SCENE_BUFFERS, then the frame), and
 * the SceneView of a kernel that took them. */
#define PATH_SCENE_PARAM(T, name) __global const T *name,
#define PATH_SCENE_NAME(T, name) name,
#define SCENE_ARGS SCENE_BUFFERS(PATH_SCENE_PARAM) const Frame frame
#define SCENE_VIEW() path_scene(SCENE_BUFFERS(PATH_SCENE_NAME) & frame)
