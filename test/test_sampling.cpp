// Chi-square tests of the sampling routines every method shares (after
// Mitsuba's): light picking, points on a light triangle, cosine-weighted
// diffuse directions and the dielectric's reflect/refract choice. Each draws
// from fixed streams on the device, bins what it drew into cells of equal
// probability under the density the routine claims, and rejects at
// significance 1e-3 per test (fixed seeds: a pass is repeatable).
#include "render/programs.hpp"
#include "scene/material.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace smallmlt;

namespace {

const double kPi = 3.14159265358979323846;

// Pearson's statistic of counts against expected counts (all > 0).
double chi2(const std::vector<double>& observed, const std::vector<double>& expected) {
    double t = 0;
    for (std::size_t i = 0; i < observed.size(); ++i)
        t += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    return t;
}

// A floor lit by five triangles of different area and emission, so that
// the light table has five different pick probabilities.
DeviceScene five_lights_scene() {
    Scene s;
    s.width = s.height = 4;
    s.depth = 2;
    s.camera.eye = {0, 1, 3};
    s.camera.target = {0, 0, 0};
    s.materials.push_back(diffuse_material({0.5f, 0.5f, 0.5f}));
    s.triangles.push_back(SceneTriangle::flat({-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, 0));
    const float ke[5] = {1.0f, 4.0f, 0.5f, 9.0f, 2.0f};
    for (int k = 0; k < 5; ++k) {
        Material light = diffuse_material({0, 0, 0});
        set_emission(light, {ke[k], ke[k], ke[k]});
        s.materials.push_back(light);
        float x = -1.0f + 0.4f * float(k), size = 0.1f + 0.07f * float(k);
        s.triangles.push_back(SceneTriangle::flat(
            {x, 2, 0}, {x + size, 2, 0}, {x, 2, size * (1.0f + float(k))}, std::uint32_t(k + 1)));
    }
    return prepare_scene(s);
}

ClProgram sampling_program(const DeviceScene& ds) {
    return ClProgram(test::cl().build(
        program_files(
            {Program::PathTracer, "cl/sampling/sample_omc.cl", "", {"test/cl/probe_sampling.cl"}},
            Stage::Shading),
        ds.layout.defines()));
}

template <typename T> std::vector<T> read_all(const ClBuffer& b, std::size_t n) {
    std::vector<T> v(n);
    b.read(test::cl(), v.data());
    return v;
}

} // namespace

// The table's probabilities are exactly the integer CDF's steps over
// 2^bits, sum to 1, and follow power (area x luminance of Ke) within the
// grid's rounding: each light gets 1 + floor(share x spare) grid points and
// the last one the remainder, so |p - share| <= (lights + 1) / 2^bits.
TEST(LightPick, ProbabilitiesAreExactAndFollowPower) {
    DeviceScene ds = five_lights_scene();
    ASSERT_EQ(ds.lights.size(), 5u);
    int bits = ds.layout.bits[kLightPick];
    double grid = std::ldexp(1.0, bits), total_power = 0, sum_p = 0;
    std::vector<double> power;
    for (const LightEntry& l : ds.lights) {
        const Triangle& t = ds.tris[l.triangle];
        Vec3 e1{t.e1[0], t.e1[1], t.e1[2]}, e2{t.e2[0], t.e2[1], t.e2[2]};
        const Material& m = ds.materials[t.material];
        power.push_back(0.5 * length(cross(e1, e2)) * rgb_luminance(m.ke[0], m.ke[1], m.ke[2]));
        total_power += power.back();
    }
    std::uint32_t lo = 0;
    for (std::size_t k = 0; k < ds.lights.size(); ++k) {
        const Triangle& t = ds.tris[ds.lights[k].triangle];
        double exact = double(ds.lights[k].cdf_hi - lo) / grid;
        EXPECT_EQ(double(t.light_pick_prob), exact) << "light " << k;
        EXPECT_NEAR(exact, power[k] / total_power, (ds.lights.size() + 1) / grid) << "light " << k;
        EXPECT_EQ(t.light_index, k);
        sum_p += exact;
        lo = ds.lights[k].cdf_hi;
    }
    EXPECT_EQ(lo, std::uint32_t(grid)) << "the CDF ends at 2^bits";
    EXPECT_DOUBLE_EQ(sum_p, 1.0);
}

// light_pick on the device picks each light as often as its
// light_pick_prob says (the probability its MIS weights and pdf_w assume).
TEST(LightPick, DeviceFrequenciesFollowTheProbabilities) {
    DeviceScene ds = five_lights_scene();
    ClProgram prog = sampling_program(ds);
    const std::uint32_t n = 1u << 20;
    ClBuffer lights(test::cl(), CL_MEM_READ_ONLY, ds.lights.size() * sizeof(LightEntry),
                    ds.lights.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_uint));
    ClKernel k(prog.p, "probe_light_picks");
    k.set_args(lights, cl_uint(ds.lights.size()), cl_uint(ds.layout.bits[kLightPick]), cl_ulong(11),
               n, out);
    k.run(test::cl(), n);
    std::vector<double> observed(ds.lights.size()), expected(ds.lights.size());
    for (cl_uint pick : read_all<cl_uint>(out, n)) {
        ASSERT_LT(pick, ds.lights.size());
        observed[pick] += 1;
    }
    for (std::size_t i = 0; i < ds.lights.size(); ++i)
        expected[i] = n * double(ds.tris[ds.lights[i].triangle].light_pick_prob);
    double t = chi2(observed, expected);
    EXPECT_LT(t, test::chi2_critical_001(double(ds.lights.size() - 1))) << "chi-square " << t;
}

// light_sample_tri puts points uniformly on the triangle. Cells of equal
// area: with p = v0 + a e1 + b e2, cell (i, j) holds the points with
// (a + b)^2 in [i, i+1)/16 and b / (a + b) in [j, j+1)/16; the barycentrics
// are recovered from the point in double precision, whatever the sampler's
// parametrization. A skinny triangle and a large one.
TEST(LightSampling, PointsAreUniformOnTheTriangle) {
    DeviceScene ds = five_lights_scene();
    ClProgram prog = sampling_program(ds);
    ClBuffer tris(test::cl(), CL_MEM_READ_ONLY, ds.tris.size() * sizeof(Triangle), ds.tris.data());
    ClBuffer mats(test::cl(), CL_MEM_READ_ONLY, ds.materials.size() * sizeof(Material),
                  ds.materials.data());
    const std::uint32_t n = 1u << 18, side = 16;
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClKernel k(prog.p, "probe_light_points");
    for (std::uint32_t light : {0u, 4u}) {
        std::uint32_t ti = ds.lights[light].triangle;
        k.set_args(tris, mats, ti, cl_ulong(5 + light), n, out);
        k.run(test::cl(), n);
        const Triangle& t = ds.tris[ti];
        double e1[3] = {t.e1[0], t.e1[1], t.e1[2]}, e2[3] = {t.e2[0], t.e2[1], t.e2[2]};
        double g11 = 0, g12 = 0, g22 = 0;
        for (int c = 0; c < 3; ++c)
            g11 += e1[c] * e1[c], g12 += e1[c] * e2[c], g22 += e2[c] * e2[c];
        double det = g11 * g22 - g12 * g12;
        std::vector<double> observed(side * side, 0.0),
            expected(side * side, double(n) / (side * side));
        for (const cl_float4& p : read_all<cl_float4>(out, n)) {
            ASSERT_EQ(p.s[3], 1.0f) << "a sample failed";
            double d1 = 0, d2 = 0;
            for (int c = 0; c < 3; ++c) {
                double r = double(p.s[c]) - t.v0[c];
                d1 += r * e1[c];
                d2 += r * e2[c];
            }
            double a = (g22 * d1 - g12 * d2) / det, b = (g11 * d2 - g12 * d1) / det;
            double s = std::clamp(a + b, 0.0, 1.0), frac = s > 0 ? std::clamp(b / s, 0.0, 1.0) : 0;
            std::uint32_t i = std::min(side - 1, std::uint32_t(s * s * side));
            std::uint32_t j = std::min(side - 1, std::uint32_t(frac * side));
            observed[i * side + j] += 1;
        }
        double stat = chi2(observed, expected);
        EXPECT_LT(stat, test::chi2_critical_001(side * side - 1))
            << "light " << light << ": chi-square " << stat;
    }
}

// diffuse_sample draws directions with density cos(theta) / pi: then
// cos^2(theta) and the azimuth are uniform and independent (cells of equal
// probability), and pdf_w is cos(theta) / pi.
TEST(DiffuseSampling, DirectionsAreCosineWeighted) {
    DeviceScene ds = five_lights_scene();
    ClProgram prog = sampling_program(ds);
    const std::uint32_t n = 1u << 18, side = 16;
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClKernel k(prog.p, "probe_diffuse_dirs");
    double nn[3] = {0.3, 0.8, -0.52};
    double len = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
    for (double& c : nn)
        c /= len;
    cl_float4 normal = {{float(nn[0]), float(nn[1]), float(nn[2]), 0.0f}};
    k.set_args(normal, cl_ulong(3), n, out);
    k.run(test::cl(), n);
    // Any frame around the normal: the azimuth is uniform in all of them.
    double t1[3] = {nn[2], 0, -nn[0]};
    double l1 = std::sqrt(t1[0] * t1[0] + t1[2] * t1[2]);
    for (double& c : t1)
        c /= l1;
    double t2[3] = {nn[1] * t1[2] - nn[2] * t1[1], nn[2] * t1[0] - nn[0] * t1[2],
                    nn[0] * t1[1] - nn[1] * t1[0]};
    std::vector<double> observed(side * side, 0.0),
        expected(side * side, double(n) / (side * side));
    double worst_pdf = 0;
    for (const cl_float4& w : read_all<cl_float4>(out, n)) {
        double c = 0, x = 0, y = 0;
        for (int i = 0; i < 3; ++i)
            c += w.s[i] * nn[i], x += w.s[i] * t1[i], y += w.s[i] * t2[i];
        ASSERT_GE(c, -1e-6);
        double phi = std::atan2(y, x) + kPi;
        std::uint32_t i = std::min(side - 1, std::uint32_t(c * c * side));
        std::uint32_t j = std::min(side - 1, std::uint32_t(phi / (2 * kPi) * side));
        observed[i * side + j] += 1;
        worst_pdf = std::max(worst_pdf, std::fabs(w.s[3] - std::max(c, 0.0) / kPi));
    }
    double stat = chi2(observed, expected);
    EXPECT_LT(stat, test::chi2_critical_001(side * side - 1)) << "chi-square " << stat;
    EXPECT_LT(worst_pdf, 1e-5) << "pdf_w is not cos(theta) / pi";
}

// dielectric_sample reflects with probability p = Fresnel rounded up
// to the choice slot's grid, and weights the two branches F / p and
// (1 - F) / (1 - p) eta^2, so the expected weight is exact. Checked from
// outside and inside at three angles (binomial z-test, Bonferroni over the
// six cases at 1e-3).
TEST(DielectricSampling, ChoiceFollowsTheQuantizedFresnelTerm) {
    DeviceScene ds = five_lights_scene();
    ClProgram prog = sampling_program(ds);
    const std::uint32_t n = 1u << 18, bits = 16;
    const float ior = 1.5f;
    ClBuffer refl(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_uint));
    ClBuffer wts(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(float));
    ClKernel k(prog.p, "probe_dielectric_choice");
    const double z_crit = 3.94; // two-sided 1e-3 / 6
    for (float cos_o : {0.9f, 0.5f, 0.1f, -0.95f, -0.8f, -0.5f}) {
        k.set_args(cos_o, ior, cl_ulong(17), n, refl, wts);
        k.run(test::cl(), n);
        double ci = std::fabs(double(cos_o));
        double eta = cos_o > 0 ? 1.0 / ior : double(ior);
        double sin2_t = eta * eta * (1 - ci * ci), f = 1.0, ct = 0.0;
        if (sin2_t < 1) {
            ct = std::sqrt(1 - sin2_t);
            double rs = (eta * ci - ct) / (eta * ci + ct), rp = (ci - eta * ct) / (ci + eta * ct);
            f = 0.5 * (rs * rs + rp * rp);
        }
        double p = std::min(1.0, std::ceil(f * (1 << bits)) / (1 << bits));
        std::vector<cl_uint> r = read_all<cl_uint>(refl, n);
        std::vector<float> w = read_all<float>(wts, n);
        double count = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            count += r[i];
            double want = r[i] ? f / p : (1 - f) / (1 - p) * eta * eta;
            ASSERT_NEAR(w[i], want, 1e-4 * want) << "cos " << cos_o << " sample " << i;
        }
        double sd = std::sqrt(n * p * (1 - p));
        if (sd > 0)
            EXPECT_LT(std::fabs(count - n * p) / sd, z_crit)
                << "cos " << cos_o << ": reflected " << count << " of " << n << ", p " << p;
        else
            EXPECT_EQ(count, n * p) << "cos " << cos_o << " (total internal reflection)";
    }
}
