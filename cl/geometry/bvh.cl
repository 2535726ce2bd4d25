/* BVH traversal over the flattened tree of src/scene/bvh.cpp: nearer child first,
 * the farther one on a stack with its entry distance, so subtrees behind the
 * closest hit so far are skipped. */

#define BVH_STACK_SIZE 64

/* Plain comparisons compile to single min/max instructions; fmin/fmax add
 * NaN handling that does not help here: a NaN slab (0 * inf, a ray lying
 * exactly in a box face's plane) is a measure-zero case either way. */
inline float3 bvh_min3(float3 a, float3 b) {
    return select(b, a, a < b);
}
inline float3 bvh_max3(float3 a, float3 b) {
    return select(b, a, a > b);
}
inline float bvh_min(float a, float b) {
    return a < b ? a : b;
}
inline float bvh_max(float a, float b) {
    return a > b ? a : b;
}

/* Entry distance of the ray into a node's box, or INFINITY if it misses or
 * enters beyond tmax. */
inline float bvh_box_entry(const __global BvhNode* n, float3 o, float3 inv_d, float tmax) {
    float3 t0 = (geo_load3(n->lo) - o) * inv_d;
    float3 t1 = (geo_load3(n->hi) - o) * inv_d;
    float3 tn = bvh_min3(t0, t1);
    float3 tf = bvh_max3(t0, t1);
    float enter = bvh_max(bvh_max(tn.x, tn.y), bvh_max(tn.z, 0.0f));
    float leave = bvh_min(bvh_min(tf.x, tf.y), bvh_min(tf.z, tmax));
    return enter <= leave ? enter : INFINITY;
}

/* Closest hit in (0, ray->tmax); on a hit, shortens ray->tmax to it. With
 * any_hit, returns at the first hit found (shadow rays). */
bool bvh_trace(const __global BvhNode* nodes, const __global Triangle* tris, Ray* ray, Hit* hit,
               bool any_hit) {
    float3 inv_d = 1.0f / ray->d;
    uint stack[BVH_STACK_SIZE];
    float stack_t[BVH_STACK_SIZE];
    int sp = 0;
    bool found = false;
    if (bvh_box_entry(&nodes[0], ray->o, inv_d, ray->tmax) == INFINITY) return false;
    uint node = 0;
    for (;;) {
        const __global BvhNode* n = &nodes[node];
        if (n->count > 0) {
            for (uint i = n->offset; i < n->offset + n->count; ++i) {
                float t = geo_intersect(ray, &tris[i]);
                if (t > 0.0f) {
                    ray->tmax = t;
                    hit->t = t;
                    hit->tri = i;
                    found = true;
                    if (any_hit) return true;
                }
            }
        } else {
            uint a = node + 1, b = n->offset;
            float ta = bvh_box_entry(&nodes[a], ray->o, inv_d, ray->tmax);
            float tb = bvh_box_entry(&nodes[b], ray->o, inv_d, ray->tmax);
            if (tb < ta) {
                uint tmp = a;
                a = b;
                b = tmp;
                float tt = ta;
                ta = tb;
                tb = tt;
            }
            if (ta != INFINITY) {
                if (tb != INFINITY && sp < BVH_STACK_SIZE) {
                    stack[sp] = b;
                    stack_t[sp] = tb;
                    ++sp;
                }
                node = a;
                continue;
            }
        }
        for (;;) {
            if (sp == 0) return found;
            --sp;
            if (stack_t[sp] < ray->tmax) break;
        }
        node = stack[sp];
    }
}
