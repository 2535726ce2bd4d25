/* Next-event estimation to emissive triangles. A triangle is picked by the
 * light-pick number through the integer CDF in LightEntry (probability
 * exactly Triangle.light_pick_prob), then a point uniformly on it. */

typedef struct {
    float3 wi;   /* unit direction from the shading point to the light */
    float dist;  /* distance to the light point */
    float pdf_w; /* solid-angle density of wi under light sampling */
    float3 radiance;
} LightSample;

inline uint light_pick(const __global LightEntry* lights, uint num_lights, uint u) {
    uint lo = 0, hi = num_lights - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (u < lights[mid].cdf_hi)
            hi = mid;
        else
            lo = mid + 1u;
    }
    return lo;
}

/* Solid-angle density of light sampling toward a point at distance dist on
 * triangle t seen under cos_l (> 0) from its front. */
inline float light_pdf_w(const __global Triangle* t, float dist, float cos_l) {
    return t->light_pick_prob * dist * dist / (geo_tri_area(t) * cos_l);
}

/* Samples a point on triangle t from (u1, u2); false if x is behind it. */
inline bool light_sample_tri(const __global Triangle* t, const __global Material* mats, float3 x,
                             float u1, float u2, LightSample* ls) {
    float su = sqrt(u1);
    float3 p =
        geo_load3(t->v0) + geo_load3(t->e1) * (su * (1.0f - u2)) + geo_load3(t->e2) * (su * u2);
    float3 nl = normalize(geo_tri_normal(t));
    float3 d = p - x;
    float dist = length(d);
    if (!(dist > 0.0f)) return false;
    ls->wi = d / dist;
    float cos_l = -dot(nl, ls->wi);
    if (cos_l <= 0.0f) return false;
    ls->dist = dist;
    ls->pdf_w = light_pdf_w(t, dist, cos_l);
    const __global Material* m = &mats[t->material];
    ls->radiance = (float3)(m->ke[0], m->ke[1], m->ke[2]);
    return true;
}

inline float light_power_heuristic(float pdf_a, float pdf_b) {
    float a2 = pdf_a * pdf_a;
    return a2 / (a2 + pdf_b * pdf_b);
}
