/* A chain's ChainValue (cl/shared_types.h): F(x) of its current state x,
 * its live bounces, and its run of rejections with the stuck mark. */

inline uint chain_bounces(ChainValue v) {
    return v.meta & CHAIN_BOUNCES_MASK;
}

inline uint chain_run(ChainValue v) {
    return v.meta >> CHAIN_RUN_SHIFT;
}

inline float3 chain_f(ChainValue v) {
    return (float3)(v.rgb[0], v.rgb[1], v.rgb[2]);
}

/* The value of a chain started at a path with F = f and `bounces` live
 * bounces: no rejections yet, not stuck. */
inline ChainValue chain_started(float3 f, uint bounces) {
    ChainValue v = {{f.x, f.y, f.z}, bounces};
    return v;
}

/* The value of a chain that moved to a path with F = f and `bounces` live
 * bounces: its run of rejections starts again, its stuck mark stays. */
inline ChainValue chain_moved(ChainValue x, float3 f, uint bounces) {
    ChainValue v = {{f.x, f.y, f.z}, bounces | (x.meta & CHAIN_STUCK_BIT)};
    return v;
}

/* The value of chain x after it stayed where it is: its run of rejections
 * grows by one (saturating); reaching stuck_run sets the stuck mark. */
inline ChainValue chain_stayed(ChainValue x, uint stuck_run) {
    uint run = min(chain_run(x) + 1u, CHAIN_RUN_MAX);
    uint meta = (x.meta & (CHAIN_BOUNCES_MASK | CHAIN_STUCK_BIT)) | (run << CHAIN_RUN_SHIFT);
    if (run >= stuck_run) meta |= CHAIN_STUCK_BIT;
    x.meta = meta;
    return x;
}

inline bool chain_stuck(ChainValue v) {
    return (v.meta & CHAIN_STUCK_BIT) != 0u;
}
