// Shading normals (cl/path/path.cl, cl/shading/shading.cl): vertex normals
// are interpolated by the hit's barycentrics, and the side rules keep them
// from creating energy or letting light through a surface.
#include "device/scene_buffers.hpp"
#include "render/path_tracer.hpp"
#include "render/programs.hpp"
#include "scene/material.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace smallmlt;

namespace {

// Every triangle of `s` smooth, its vertex normals the geometric normal
// tilted by `tilt_deg` towards a random direction (seeded).
void tilt_normals(Scene& s, float tilt_deg, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    float tilt = tilt_deg * 3.14159265f / 180.0f;
    for (SceneTriangle& t : s.triangles) {
        Vec3 ng = normalize(cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));
        Vec3 a = normalize(cross(ng, std::fabs(ng.x) > 0.5f ? Vec3{0, 1, 0} : Vec3{1, 0, 0}));
        Vec3 b = cross(ng, a);
        for (Vec3& n : t.n) {
            float phi = 6.2831853f * u(rng);
            Vec3 side = a * std::cos(phi) + b * std::sin(phi);
            n = normalize(ng * std::cos(tilt) + side * std::sin(tilt));
        }
        t.smooth = true;
    }
}

// A closed box room, all diffuse, and outside it a light facing one wall:
// no light can reach the room's inside.
Scene sealed_room() {
    Scene s;
    s.width = s.height = 16;
    s.depth = 6;
    s.camera.eye = {0, 0, 0};
    s.camera.target = {0, 0, -1};
    s.camera.fov_y_deg = 90;
    s.materials.push_back(diffuse_material({0.8f, 0.8f, 0.8f}));
    Material lamp = diffuse_material({0, 0, 0});
    set_emission(lamp, {50, 50, 50});
    s.materials.push_back(lamp);
    s.material_names = {"wall", "lamp"};
    Vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = {i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f};
    // Faces as quads (a, b, c, d) counter-clockwise seen from inside.
    const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        s.triangles.push_back(SceneTriangle::flat(c[f[0]], c[f[1]], c[f[2]], 0));
        s.triangles.push_back(SceneTriangle::flat(c[f[0]], c[f[2]], c[f[3]], 0));
    }
    // The lamp at z = -1.5, facing +z (the room's far wall, z = -1).
    s.triangles.push_back(
        SceneTriangle::flat({-0.5f, -0.5f, -1.5f}, {0.5f, -0.5f, -1.5f}, {0.5f, 0.5f, -1.5f}, 1));
    s.triangles.push_back(
        SceneTriangle::flat({-0.5f, -0.5f, -1.5f}, {0.5f, 0.5f, -1.5f}, {-0.5f, 0.5f, -1.5f}, 1));
    return s;
}

} // namespace

// The room's walls face inward (the lamp sees their backs). With shading
// normals tilted by 60 degrees, many sampled and light directions lie on
// the wrong side of a wall's geometric normal; the rule that such a
// direction carries nothing keeps all of them from passing through: every
// pixel is exactly black. Without the rule (for BSDF samples or for
// next-event estimation) light leaks through the far wall.
TEST(ShadingNormals, AWallWithTiltedNormalsLetsNoLightThrough) {
    Scene s = sealed_room();
    tilt_normals(s, 60.0f, 7);
    DeviceScene tilted = prepare_scene(s);
    ASSERT_TRUE(tilted.layout.features.shading_normals);
    Image img = test::render_pt(tilted, 3, 64);
    double worst = 0;
    for (float v : img.rgb)
        worst = std::max(worst, double(v));
    EXPECT_EQ(worst, 0.0) << "light leaked through a wall";
    // The scene is not black for want of light: a room with its far wall
    // removed sees the lamp.
    Scene open = sealed_room();
    open.triangles.erase(open.triangles.begin(), open.triangles.begin() + 2); // z = -1
    EXPECT_GT(test::render_pt(prepare_scene(open), 3, 16).mean_luminance(), 0.1);
}

// The furnace (every face Kd 0.5, Ke 1, depth 4) carries sum 0.5^i,
// i = 0..4 = 1.9375 with geometric normals. Shading normals tilted by 30
// degrees may lose energy (directions the side rules reject) but must not
// create any: the image mean stays below 1.9375 plus 4 standard errors of
// the mean (over pixels of independent samples). It also stays above 1.5,
// so that the test does not pass by rendering black.
TEST(ShadingNormals, TiltedNormalsCreateNoEnergyInAFurnace) {
    Scene s = test::scene("furnace", 32, 32, 4);
    tilt_normals(s, 30.0f, 11);
    DeviceScene ds = prepare_scene(s);
    Image img = test::render_pt(ds, 5, 64, PtSampler::Random);
    double sum = 0, sum2 = 0;
    const std::size_t n = std::size_t(img.width) * img.height;
    for (std::size_t p = 0; p < n; ++p) {
        double v = img.luminance(p);
        sum += v;
        sum2 += v * v;
    }
    double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
    std::printf("furnace with tilted normals: mean %.5f (+-%.5f), flat 1.9375\n", mean, se);
    EXPECT_LT(mean, 1.9375 + 4 * se) << "shading normals created energy";
    EXPECT_GT(mean, 1.5);
}

// A triangle with three different vertex normals: at points of known
// barycentrics (b1, b2) the shading normal is the normalized
// (1 - b1 - b2) n0 + b1 n1 + b2 n2, turned to the geometric normal's side
// (n2 points away from it, so near v2 the sum is turned back).
TEST(ShadingNormals, AreInterpolatedByTheHitsBarycentrics) {
    Scene s;
    s.width = s.height = 4;
    s.camera.eye = {0, 0, 3};
    s.camera.target = {0, 0, 0};
    s.materials.push_back(diffuse_material({0.5f, 0.5f, 0.5f}));
    Material lamp = diffuse_material({0, 0, 0});
    set_emission(lamp, {1, 1, 1});
    s.materials.push_back(lamp);
    s.material_names = {"white", "lamp"};
    SceneTriangle t = SceneTriangle::flat({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 0);
    t.n[0] = normalize(Vec3{0.3f, 0, 1});
    t.n[1] = normalize(Vec3{0, 0.4f, 1});
    t.n[2] = normalize(Vec3{-0.2f, 0.1f, -1}); // the back side
    t.smooth = true;
    s.triangles.push_back(t);
    s.triangles.push_back(SceneTriangle::flat({5, 5, 5}, {6, 5, 5}, {5, 6, 5}, 1));
    DeviceScene ds = prepare_scene(s);
    std::uint32_t tri = 0;
    while (ds.tris[tri].material != 0)
        ++tri;
    const float bary[][2] = {{0.1f, 0.2f}, {0.6f, 0.3f}, {0.05f, 0.9f}, {0.33f, 0.33f}};
    const std::uint32_t n = 4;
    std::vector<cl_float4> o(n), d(n);
    Vec3 want[n];
    for (std::uint32_t i = 0; i < n; ++i) {
        float b1 = bary[i][0], b2 = bary[i][1];
        Vec3 p = t.v[0] * (1 - b1 - b2) + t.v[1] * b1 + t.v[2] * b2;
        o[i] = {{p.x + 0.1f, p.y - 0.2f, 1.0f, 0}};
        Vec3 dir = normalize(p - Vec3{o[i].s[0], o[i].s[1], o[i].s[2]});
        d[i] = {{dir.x, dir.y, dir.z, 0}};
        want[i] = normalize(t.n[0] * (1 - b1 - b2) + t.n[1] * b1 + t.n[2] * b2);
        if (want[i].z < 0) want[i] = want[i] * -1.0f; // the geometric normal is +z
    }
    ClProgram prog(test::cl().build(
        program_files(
            {Program::PathTracer, "cl/sampling/sample_omc.cl", "", {"test/cl/probe_shading.cl"}},
            Stage::Path),
        ds.layout.defines()));
    SceneBuffers sb(test::cl(), ds);
    ClBuffer ob(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), o.data());
    ClBuffer db(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), d.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClKernel k(prog.p, "probe_shading_normal");
    cl_uint arg = 0;
    kernel_arg(k, arg, sb);
    k.set_arg(arg++, tri);
    k.set_arg(arg++, ob);
    k.set_arg(arg++, db);
    k.set_arg(arg++, n);
    k.set_arg(arg++, out);
    k.run(test::cl(), n);
    std::vector<cl_float4> got(n);
    out.read(test::cl(), got.data());
    for (std::uint32_t i = 0; i < n; ++i) {
        EXPECT_NEAR(got[i].s[3], bary[i][0] + bary[i][1], 1e-5) << "point " << i;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[i].s[c], want[i][c], 1e-5) << "point " << i << " axis " << c;
    }
}
