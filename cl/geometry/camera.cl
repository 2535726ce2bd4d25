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
