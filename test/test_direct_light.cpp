// Direct light against Lambert's formula for the irradiance of a polygon:
// a diffuse floor seen straight down, lit by a small quad light off to the
// side and low, so that every shadow ray leaves the floor at a shallow angle
// and meets the light's plane at a grazing one (the case where a shadow ray
// offset from its surface but not re-aimed at the light's point would meet
// the light's plane short of the point and shadow the light with itself).
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

struct V3 {
    double x, y, z;
};
V3 sub(V3 a, V3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
double dotp(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 crossp(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 unit(V3 a) {
    double l = std::sqrt(dotp(a, a));
    return {a.x / l, a.y / l, a.z / l};
}

// Irradiance at x (normal n) from a polygon of radiance L wholly above x's
// horizon, facing x: Lambert's formula, E = L/2 |sum over edges of the angle
// the edge subtends times n . (unit normal of the edge's plane through x)|.
double lambert_irradiance(V3 x, V3 n, const V3* poly, int count, double radiance) {
    double sum = 0;
    for (int i = 0; i < count; ++i) {
        V3 a = unit(sub(poly[i], x)), b = unit(sub(poly[(i + 1) % count], x));
        double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, dotp(a, b))));
        sum += angle * dotp(n, unit(crossp(a, b)));
    }
    return radiance / 2 * std::fabs(sum);
}

} // namespace

TEST(DirectLight, FloorUnderALowLightMatchesLambertsFormula) {
    // Floor y = 0, kd 0.5, seen from (0, 2, 0) straight down with a 2 atan(1/2)
    // field of view: the square film sees x, z in [-1, 1], pixels evenly
    // (the floor is parallel to the film). The light, 0.4 x 0.4 at y = 0.3,
    // x in [1.4, 1.8], faces down, outside the view.
    const double kd = 0.5, radiance = 20, h = 0.3;
    const V3 light[4] = {{1.4, h, -0.2}, {1.8, h, -0.2}, {1.8, h, 0.2}, {1.4, h, 0.2}};
    std::string dir = test::scratch_dir("direct-light");
    test::write_file(dir + "/m.obj",
                     "mtllib m.mtl\nv -3 0 -3\nv 3 0 -3\nv 3 0 3\nv -3 0 3\n"
                     "v 1.4 0.3 -0.2\nv 1.8 0.3 -0.2\nv 1.8 0.3 0.2\nv 1.4 0.3 0.2\n"
                     "usemtl floor\nf 1 3 2\nf 1 4 3\nusemtl lamp\nf 5 6 7\nf 5 7 8\n");
    test::write_file(dir + "/m.mtl",
                     "newmtl floor\nKd 0.5 0.5 0.5\nnewmtl lamp\nKd 0 0 0\nKe 20 20 20\n");
    const double fov = 2 * std::atan(0.5) * 180 / M_PI;
    test::write_file(dir + "/s.scene", "film 16 16\ncamera 0 2 0  0 0 0  0 0 -1  " +
                                           std::to_string(fov) + "\ndepth 1\nmesh m.obj\n");
    DeviceScene ds = prepare_scene(load_scene(dir + "/s.scene"));

    // The exact mean radiance over the square, by the midpoint rule (the
    // integrand is smooth there: 400 x 400 points, error below 1e-6).
    const int n = 400;
    double exact = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            V3 x{-1 + (i + 0.5) * 2.0 / n, 0, -1 + (j + 0.5) * 2.0 / n};
            exact += kd / M_PI * lambert_irradiance(x, {0, 1, 0}, light, 4, radiance);
        }
    exact /= double(n) * n;

    // 32 independent batches of 64 samples per pixel: the mean and its
    // standard error; fails beyond 4.4 standard errors (two-sided 1e-5).
    std::vector<Image> batches = test::render_pt_batches(ds, 12345, 2048, 32);
    double sum = 0, sum2 = 0;
    for (const Image& b : batches) {
        double m = b.mean_luminance();
        sum += m, sum2 += m * m;
    }
    const double k = double(batches.size()), mean = sum / k;
    const double se = std::sqrt((sum2 / k - mean * mean) / (k - 1));
    std::printf("floor under a low light: PT %.6g +- %.2g, Lambert %.6g (%+.2f%%)\n", mean, se,
                exact, 100 * (mean / exact - 1));
    EXPECT_LT(std::fabs(mean - exact), 4.4 * se);
    EXPECT_LT(se, 0.01 * exact) << "too few samples to tell";
}
