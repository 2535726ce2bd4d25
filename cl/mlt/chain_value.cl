/* A chain's ChainValue (cl/core/shared_types.h): G(x) = F(x) w(x) of its current
 * state x (the contribution times the target's weight, cl/mlt/mlt_step.cl),
 * its live bounces, its run of rejections with the stuck mark, and the stay
 * weight x has gathered but not yet splatted. */

inline uint chain_bounces(ChainValue v) {
    return v.meta & CHAIN_BOUNCES_MASK;
}

inline uint chain_run(ChainValue v) {
    return v.meta >> CHAIN_RUN_SHIFT;
}

inline float3 chain_g(ChainValue v) {
    return (float3)(v.rgb[0], v.rgb[1], v.rgb[2]);
}

/* The value of a chain started at a path with G = f and `bounces` live
 * bounces: no rejections yet, not stuck. */
inline ChainValue chain_started(float3 f, uint bounces) {
    ChainValue v = {{f.x, f.y, f.z}, bounces, 0u};
    return v;
}

/* The value of a chain that moved to a path with G = f and `bounces` live
 * bounces: its run of rejections starts again, its stuck mark stays. */
inline ChainValue chain_moved(ChainValue x, float3 f, uint bounces) {
    ChainValue v = {{f.x, f.y, f.z}, bounces | (x.meta & CHAIN_STUCK_BIT), 0u};
    return v;
}

/* The value of chain x after it stayed where it is: its run of rejections
 * grows by one (saturating); reaching stuck_run sets the stuck mark. It
 * writes a copy, never x itself: Mesa's compiler (rusticl) passes a struct
 * parameter by reference, so a write to x would change the caller's. */
inline ChainValue chain_stayed(ChainValue x, uint stuck_run) {
    uint run = min(chain_run(x) + 1u, CHAIN_RUN_MAX);
    uint meta = (x.meta & (CHAIN_BOUNCES_MASK | CHAIN_STUCK_BIT)) | (run << CHAIN_RUN_SHIFT);
    if (run >= stuck_run) meta |= CHAIN_STUCK_BIT;
    ChainValue v = x;
    v.meta = meta;
    return v;
}

/* A stay weight in [0, 64] in the fixed point of ChainValue.stay, and back. */
inline uint chain_stay_fixed(float w) {
    return (uint)(w * (float)(1u << MLT_STAY_FRAC_BITS) + 0.5f);
}

inline float chain_stay_weight(uint fixed) {
    return (float)fixed * (1.0f / (float)(1u << MLT_STAY_FRAC_BITS));
}

inline bool chain_stuck(ChainValue v) {
    return (v.meta & CHAIN_STUCK_BIT) != 0u;
}
