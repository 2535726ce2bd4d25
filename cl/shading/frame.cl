/* The shading frame of a surface point: an orthonormal (t, b, n) around the
 * shading normal n, and the geometric normal ng (the triangle's front face),
 * which alone decides sides, ray offsets and what is inside a dielectric.
 * n lies on ng's side. Models work in local coordinates of this frame
 * (z along n). */

typedef struct {
    float3 t, b, n;
    float3 ng;
} ShadingFrame;

/* The frame around unit shading normal n (on unit ng's side). The tangent
 * is chosen away from n's largest axis, so that it is never degenerate. */
inline ShadingFrame frame_make(float3 n, float3 ng) {
    ShadingFrame f;
    float3 t = fabs(n.x) > 0.5f ? (float3)(n.z, 0.0f, -n.x) : (float3)(0.0f, -n.z, n.y);
    f.t = normalize(t);
    f.b = cross(n, f.t);
    f.n = n;
    f.ng = ng;
    return f;
}

inline float3 frame_to_local(const ShadingFrame* f, float3 v) {
    return (float3)(dot(v, f->t), dot(v, f->b), dot(v, f->n));
}

inline float3 frame_to_world(const ShadingFrame* f, float3 v) {
    return normalize(f->t * v.x + f->b * v.y + f->n * v.z);
}
