/* What an MLT chain evaluates for a state: the film position from numbers 0
 * and 1 (uniform over the chain's tile, cl/sampling/strata.cl), then the path; F is the path's MLT
 * part (cl/path/path.cl), and its OMC part comes along for the burn-in. The sampler tests swap
 * this file for one with a known target function. */

inline EvalResult eval_state(const SceneView* sc, const Frame* frame, SampleSource* src) {
    FilmPoint at = smp_film_point(src, frame);
    PathResult r = path_trace(sc, src, camera_ray(frame, at.x, at.y));
    EvalResult s;
    s.f = r.rest;
    s.omc = r.omc;
    s.behind_specular = r.behind_specular;
    s.pixel = at.pixel;
    s.bounces = r.bounces;
    s.rays = r.rays;
    return s;
}
