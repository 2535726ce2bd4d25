/* Rays, triangle access and ray/triangle intersection (Moller-Trumbore on
 * the stored edges). Lengths are in scene units. */

typedef struct {
    float3 o;
    float3 d;
    float tmax;
} Ray;

typedef struct {
    float t;
    uint tri;
} Hit;

inline float3 geo_load3(const __global f32* v) {
    return (float3)(v[0], v[1], v[2]);
}

inline float3 geo_tri_normal(const __global Triangle* t) {
    return cross(geo_load3(t->e1), geo_load3(t->e2));
}

inline float geo_tri_area(const __global Triangle* t) {
    return 0.5f * length(geo_tri_normal(t));
}

/* Distance along the ray to triangle t if it lies in (0, ray->tmax), else -1. */
inline float geo_intersect(const Ray* ray, const __global Triangle* t) {
    float3 e1 = geo_load3(t->e1);
    float3 e2 = geo_load3(t->e2);
    float3 p = cross(ray->d, e2);
    float det = dot(e1, p);
    if (det == 0.0f) return -1.0f;
    float inv_det = 1.0f / det;
    float3 s = ray->o - geo_load3(t->v0);
    float b1 = dot(s, p) * inv_det;
    if (b1 < 0.0f || b1 > 1.0f) return -1.0f;
    float3 q = cross(s, e1);
    float b2 = dot(ray->d, q) * inv_det;
    if (b2 < 0.0f || b1 + b2 > 1.0f) return -1.0f;
    float dist = dot(e2, q) * inv_det;
    return (dist > 0.0f && dist < ray->tmax) ? dist : -1.0f;
}

/* Barycentrics (b1, b2) of v1 and v2 at the point where `ray` meets
 * triangle t (the arithmetic of geo_intersect). */
inline float2 geo_barycentrics(const Ray* ray, const __global Triangle* t) {
    float3 e1 = geo_load3(t->e1);
    float3 e2 = geo_load3(t->e2);
    float3 p = cross(ray->d, e2);
    float inv_det = 1.0f / dot(e1, p);
    float3 s = ray->o - geo_load3(t->v0);
    float b1 = dot(s, p) * inv_det;
    float b2 = dot(ray->d, cross(s, e1)) * inv_det;
    return (float2)(b1, b2);
}

/* Start point for a ray leaving surface point p on the side of normal n,
 * pushed off by a distance relative to the coordinates' magnitude. */
inline float3 geo_offset(float3 p, float3 n) {
    float scale = fmax(1.0f, fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
    return p + n * (1e-4f * scale);
}
