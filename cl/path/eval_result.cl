/* What evaluating a chain's state yields, and which pixel a film position
 * splats to: shared by every evaluator (eval_path.cl, eval_target.cl). */

typedef struct {
    float3 f;     /* F: RGB contribution (the MLT part) */
    float3 omc;   /* the OMC part of the split, RGB (0 without one) */
    uint pixel;   /* where it splats */
    uint bounces; /* live bounces of the state (PathResult.bounces) */
    uint rays;
} EvalResult;

inline uint eval_pixel(const Frame* frame, float fx, float fy) {
    uint px = min((uint)(fx * (float)frame->width), frame->width - 1u);
    uint py = min((uint)(fy * (float)frame->height), frame->height - 1u);
    return py * frame->width + px;
}

/* What an idle work-item holds: no contribution, no rays. */
inline EvalResult eval_nothing(void) {
    EvalResult s;
    s.f = (float3)(0.0f);
    s.omc = (float3)(0.0f);
    s.pixel = 0u;
    s.bounces = 0u;
    s.rays = 0u;
    return s;
}
