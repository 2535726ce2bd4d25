/* Pinhole camera: film position (fx, fy) in [0,1)^2 to a primary ray. */

inline Ray camera_ray(const Frame* f, float fx, float fy) {
    Ray r;
    r.o = (float3)(f->eye[0], f->eye[1], f->eye[2]);
    float3 d = (float3)(f->top_left[0], f->top_left[1], f->top_left[2]) +
               (float3)(f->du[0], f->du[1], f->du[2]) * fx +
               (float3)(f->dv[0], f->dv[1], f->dv[2]) * fy;
    r.d = normalize(d);
    r.tmax = INFINITY;
    return r;
}

/* The inverse of camera_ray: the film position of direction d from the eye
 * (false where d misses the film), and the film's pixels per steradian
 * there: width * height * |w|^3 / |(du x dv) . top_left|, w = top_left +
 * fx du + fy dv the unnormalized ray (solid angle per unit film area is
 * |(du x dv) . w| / |w|^3, and (du x dv) . w = (du x dv) . top_left). */
inline bool camera_film_position(const Frame* f, float3 d, float2* film, float* pixels_per_sr) {
    float3 tl = (float3)(f->top_left[0], f->top_left[1], f->top_left[2]);
    float3 du = (float3)(f->du[0], f->du[1], f->du[2]);
    float3 dv = (float3)(f->dv[0], f->dv[1], f->dv[2]);
    float3 n = cross(du, dv);
    float nt = dot(n, tl), nd = dot(n, d);
    if (!(nd * nt > 0.0f)) return false; /* behind the eye, or along the film */
    float3 w = d * (nt / nd);            /* on the film's plane */
    float3 q = w - tl;
    float uu = dot(du, du), uv = dot(du, dv), vv = dot(dv, dv), det = uu * vv - uv * uv;
    float fx = (dot(q, du) * vv - dot(q, dv) * uv) / det;
    float fy = (dot(q, dv) * uu - dot(q, du) * uv) / det;
    if (!(fx >= 0.0f && fx < 1.0f && fy >= 0.0f && fy < 1.0f)) return false;
    *film = (float2)(fx, fy);
    float len = length(w);
    *pixels_per_sr = (float)f->width * (float)f->height * len * len * len / fabs(nt);
    return true;
}
