/* What an MLT chain evaluates for a state: the film position from numbers 0
 * and 1 (uniform over the whole film), then the path; F is the path's MLT
 * part (cl/path/path.cl), and its OMC part comes along for the burn-in. The sampler tests swap
 * this file for one with a known target function. */

inline EvalResult eval_state(const SceneView* sc, const Frame* frame, SampleSource* src) {
    float fx = smp_uniform(src, 0u, layout_film(0u)), fy = smp_uniform(src, 0u, layout_film(1u));
    PathResult r = path_trace(sc, src, camera_ray(frame, fx, fy));
    EvalResult s;
    s.f = r.rest;
    s.omc = r.omc;
    s.pixel = eval_pixel(frame, fx, fy);
    s.bounces = r.bounces;
    s.rays = r.rays;
    return s;
}
