/* A known target in place of the path, for the sampler tests: F(u0, u1) is
 * grey with value
 *   f(x, y) = (1 + 3x) (1 + sin^2(2 pi y)), and 0 where x < 1/4 and y < 1/4,
 * over the film position (x, y) = (u0, u1); the film's pixels are the bins of
 * a histogram. test/test_mlt.cpp integrates f over each bin in closed form. */

inline float target_value(float x, float y) {
    if (x < 0.25f && y < 0.25f) return 0.0f;
    float s = sin(2.0f * M_PI_F * y);
    return (1.0f + 3.0f * x) * (1.0f + s * s);
}

inline EvalResult eval_state(const SceneView* sc, const Frame* frame, SampleSource* src) {
    float x = smp_uniform(src, 0u, layout_film(0u)), y = smp_uniform(src, 0u, layout_film(1u));
    EvalResult s;
    s.f = (float3)(target_value(x, y));
    s.pixel = eval_pixel(frame, x, y);
    s.bounces = 0u;
    s.rays = 0u;
    return s;
}
