/* What evaluating a chain's state yields: shared by every evaluator
 * (eval_path.cl, eval_target.cl). */

typedef struct {
    float3 f;              /* F: RGB contribution (the MLT part) */
    float3 omc;            /* the OMC part of the split, RGB (0 without one) */
    float behind_specular; /* PathResult.behind_specular (0 for other evaluators) */
    uint pixel;            /* where it splats */
    uint bounces;          /* live bounces of the state (PathResult.bounces) */
    uint rays;
} EvalResult;

/* What an idle work-item holds: no contribution, no rays. */
inline EvalResult eval_nothing(void) {
    EvalResult s;
    s.f = (float3)(0.0f);
    s.omc = (float3)(0.0f);
    s.behind_specular = 0.0f;
    s.pixel = 0u;
    s.bounces = 0u;
    s.rays = 0u;
    return s;
}
