/* What an MLT chain evaluates for a state: the film position from numbers 0
 * and 1 (uniform over the whole film), then the path. The sampler tests swap
 * this file for one with a known target function. */

typedef struct {
    float3 f;     /* F: RGB contribution */
    uint pixel;   /* where it splats */
    uint bounces; /* live bounces of the state (PathResult.bounces) */
    uint rays;
} MltSample;

inline uint mlt_pixel(const Frame* frame, float fx, float fy) {
    uint px = min((uint)(fx * (float)frame->width), frame->width - 1u);
    uint py = min((uint)(fy * (float)frame->height), frame->height - 1u);
    return py * frame->width + px;
}

inline MltSample mlt_evaluate(const SceneView* sc, const Frame* frame, SampleSource* src) {
    float fx = smp_uniform(src, 0u, layout_film(0u)), fy = smp_uniform(src, 0u, layout_film(1u));
    PathResult r = path_trace(sc, src, camera_ray(frame, fx, fy));
    MltSample s;
    s.f = r.radiance;
    s.pixel = mlt_pixel(frame, fx, fy);
    s.bounces = r.bounces;
    s.rays = r.rays;
    return s;
}
