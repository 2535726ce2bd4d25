// The BVH: its structure is sound, and the device traversal finds the same
// closest hits as brute-force intersection of every triangle.
#include "scene/bvh.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace smallmlt;

namespace {

// Moller-Trumbore in double precision: distance or +inf.
double brute_hit(const Triangle& t, const double o[3], const double d[3]) {
    double e1[3] = {t.e1[0], t.e1[1], t.e1[2]}, e2[3] = {t.e2[0], t.e2[1], t.e2[2]};
    double p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
                   d[0] * e2[1] - d[1] * e2[0]};
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0) return INFINITY;
    double s[3] = {o[0] - t.v0[0], o[1] - t.v0[1], o[2] - t.v0[2]};
    double b1 = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    double q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
                   s[0] * e1[1] - s[1] * e1[0]};
    double b2 = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    double dist = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    if (b1 < 0 || b2 < 0 || b1 + b2 > 1 || dist <= 0) return INFINITY;
    return dist;
}

} // namespace

TEST(Bvh, EveryTriangleOnceAndChildrenInsideParents) {
    Scene s = test::scene("cornell-water", 8, 8);
    Bvh bvh = bvh_build(s.triangles);
    std::vector<int> seen(s.triangles.size(), 0);
    for (std::uint32_t t : bvh.order)
        ++seen[t];
    for (int c : seen)
        ASSERT_EQ(c, 1);
    std::size_t leaf_tris = 0;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& n = bvh.nodes[i];
        if (n.count > 0) {
            leaf_tris += n.count;
            continue;
        }
        for (std::uint32_t c : {std::uint32_t(i + 1), n.offset}) {
            ASSERT_LT(c, bvh.nodes.size());
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(bvh.nodes[c].lo[a], n.lo[a]);
                EXPECT_LE(bvh.nodes[c].hi[a], n.hi[a]);
            }
        }
    }
    EXPECT_EQ(leaf_tris, s.triangles.size());
    EXPECT_LE(bvh.depth, kBvhMaxDepth);
}

TEST(Bvh, DeviceClosestHitsMatchBruteForce) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 8, 8));
    const std::size_t n = 4000;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<cl_float4> o(n), d(n);
    for (std::size_t i = 0; i < n; ++i) {
        // Origins inside and outside the box, directions uniform on the sphere;
        // a quarter of the rays get a finite tmax.
        float dir[3];
        float len2;
        do {
            dir[0] = u(rng), dir[1] = u(rng), dir[2] = u(rng);
            len2 = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
        } while (len2 > 1 || len2 < 1e-4f);
        float inv = 1 / std::sqrt(len2);
        o[i] = {{1.5f * u(rng), 1.0f + 1.5f * u(rng), 1.5f * u(rng),
                 i % 4 == 0 ? 0.8f : std::numeric_limits<float>::infinity()}};
        d[i] = {{dir[0] * inv, dir[1] * inv, dir[2] * inv, 0}};
    }
    ClProgram prog(test::probe_program());
    ClKernel k(prog.p, "probe_closest");
    ClBuffer tris(test::cl(), CL_MEM_READ_ONLY, ds.tris.size() * sizeof(Triangle), ds.tris.data());
    ClBuffer nodes(test::cl(), CL_MEM_READ_ONLY, ds.nodes.size() * sizeof(BvhNode),
                   ds.nodes.data());
    ClBuffer ob(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), o.data());
    ClBuffer db(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), d.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_uint2));
    k.set_args(tris, nodes, ob, db, out, cl_uint(n));
    k.run(test::cl(), n);
    std::vector<cl_uint2> hits(n);
    out.read(test::cl(), hits.data());

    int hit_count = 0, mismatches = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double od[3] = {o[i].s[0], o[i].s[1], o[i].s[2]}, dd[3] = {d[i].s[0], d[i].s[1], d[i].s[2]};
        double best = INFINITY;
        for (const Triangle& t : ds.tris)
            best = std::min(best, brute_hit(t, od, dd));
        if (!(best < o[i].s[3])) best = INFINITY;
        bool dev_hit = hits[i].s[0] != 0xFFFFFFFFu;
        float dev_t;
        std::memcpy(&dev_t, &hits[i].s[1], sizeof(float));
        // Rays grazing an edge shared by two triangles may hit either one at
        // the same distance; a miss on one side and a hit on the other within
        // float rounding of an edge is counted separately and must be rare.
        if (std::isinf(best) != !dev_hit) {
            ++mismatches;
            continue;
        }
        if (!dev_hit) continue;
        ++hit_count;
        EXPECT_NEAR(dev_t, best, 1e-4 * std::max(1.0, best)) << "ray " << i;
    }
    EXPECT_GT(hit_count, int(n / 4)) << "too few rays hit anything to test";
    EXPECT_LE(mismatches, 2) << "hit/miss disagreements beyond float rounding at edges";
}
