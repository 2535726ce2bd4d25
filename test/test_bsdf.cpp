// Tests of the scattering models (cl/shading/) in their local frame, in the
// manner of Mitsuba 3's and pbrt-v4's BSDF tests: a chi-square test per
// sampling routine (what it draws against the density it claims), sample /
// eval / pdf agreement, white-furnace albedos against values derived on the
// host (test/bsdf_reference.hpp), reciprocity and the Fresnel terms.
//
// Every random test uses fixed seeds, so a pass is repeatable; each states
// its significance, 1e-3 per test (TEST), Bonferroni-corrected over its
// cases. Suites: Microfacet*, Bsdf* (the furnace tests are BsdfFurnace).
#include "bsdf_reference.hpp"
#include "render/programs.hpp"
#include "scene/material.hpp"
#include "scene/plastic_coat.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace smallmlt;
using ref::D3;

namespace {

const double kPi = ref::kPi;
const double kAlpha = 1e-3; // significance of each test, over all its cases

// ---- Device plumbing -------------------------------------------------------

// A layout with every model compiled in (LAYOUT_HAS_* of each), for the
// dispatcher shading_local_* to reach them all.
DeviceScene all_models_scene() {
    SceneFeatures f;
    for (std::uint32_t t = 0; t < MAT_TYPES; ++t)
        f.with(t);
    f.num_lights = 1;
    f.depth = 2;
    return test::layout_only_scene(f);
}

// The shading stage and test/cl/probe_bsdf.cl, built once.
const ClProgram& bsdf_program() {
    static const DeviceScene ds = all_models_scene();
    static const ClProgram p(test::cl().build(
        program_files(
            {Program::PathTracer, "cl/sampling/sample_omc.cl", "", {"test/cl/probe_bsdf.cl"}},
            Stage::Shading),
        ds.layout.defines()));
    return p;
}

template <typename T> std::vector<T> read_all(const ClBuffer& b, std::size_t n) {
    std::vector<T> v(n);
    b.read(test::cl(), v.data());
    return v;
}

cl_float4 f4(D3 v) {
    return {{float(v.x), float(v.y), float(v.z), 0.0f}};
}
D3 d3(const cl_float4& v) {
    return {v.s[0], v.s[1], v.s[2]};
}

ClBuffer material_buffer(const Material& m) {
    return ClBuffer(test::cl(), CL_MEM_READ_ONLY, sizeof(Material), &m);
}

// One sample of shading_local_sample with the model's evaluation at the
// direction it drew (probe_bsdf_sample).
struct Sample {
    D3 wi;
    double pdf_w = 0, pdf_eval = 0;
    double weight[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    bool failed() const { return weight[0] == 0 && weight[1] == 0 && weight[2] == 0; }
    bool dirac() const { return !failed() && pdf_w == 0; }
};

// with_eval: also evaluate f and pdf_w at each sampled direction.
std::vector<Sample> draw_samples(const Material& m, D3 wo, std::uint64_t seed, std::uint32_t n,
                                 bool with_eval = true) {
    ClBuffer mat = material_buffer(m);
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, std::size_t(n) * 3 * sizeof(cl_float4));
    ClKernel k(bsdf_program().p, "probe_bsdf_sample");
    k.set_args(mat, f4(wo), cl_ulong(seed), cl_uint(n), cl_uint(with_eval), out);
    k.run(test::cl(), n);
    std::vector<cl_float4> raw = read_all<cl_float4>(out, std::size_t(n) * 3);
    std::vector<Sample> s(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const cl_float4 *a = &raw[3 * i], *b = a + 1, *c = a + 2;
        s[i].wi = d3(*a);
        s[i].pdf_w = a->s[3];
        s[i].pdf_eval = b->s[3];
        for (int ch = 0; ch < 3; ++ch) {
            s[i].weight[ch] = b->s[ch];
            s[i].f[ch] = c->s[ch];
        }
    }
    return s;
}

// (weight, wi.z) of n samples (probe_bsdf_weights).
std::vector<cl_float4> draw_weights(const Material& m, D3 wo, std::uint64_t seed, std::uint32_t n) {
    ClBuffer mat = material_buffer(m);
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, std::size_t(n) * sizeof(cl_float4));
    ClKernel k(bsdf_program().p, "probe_bsdf_weights");
    k.set_args(mat, f4(wo), cl_ulong(seed), cl_uint(n), out);
    k.run(test::cl(), n);
    return read_all<cl_float4>(out, n);
}

// (f, pdf_w) at pairs (wo[i], wi[i]) (probe_bsdf_eval).
std::vector<cl_float4> eval_pairs(const Material& m, const std::vector<D3>& wo,
                                  const std::vector<D3>& wi) {
    std::vector<cl_float4> a, b;
    for (std::size_t i = 0; i < wo.size(); ++i)
        a.push_back(f4(wo[i])), b.push_back(f4(wi[i]));
    const std::size_t n = a.size();
    ClBuffer mat = material_buffer(m);
    ClBuffer bo(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), a.data());
    ClBuffer bi(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), b.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClKernel k(bsdf_program().p, "probe_bsdf_eval");
    k.set_args(mat, bo, bi, cl_uint(n), out);
    k.run(test::cl(), n);
    return read_all<cl_float4>(out, n);
}

// (D(m), G1(wo, m), pdf_visible(wo, m), Lambda(wo)) at pairs (probe_mf_eval).
std::vector<cl_float4> mf_eval(double alpha, bool beckmann, const std::vector<D3>& wo,
                               const std::vector<D3>& m) {
    std::vector<cl_float4> a, b;
    for (std::size_t i = 0; i < wo.size(); ++i)
        a.push_back(f4(wo[i])), b.push_back(f4(m[i]));
    const std::size_t n = a.size();
    ClBuffer bo(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), a.data());
    ClBuffer bm(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float4), b.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClKernel k(bsdf_program().p, "probe_mf_eval");
    k.set_args(float(alpha), cl_uint(beckmann), bo, bm, cl_uint(n), out);
    k.run(test::cl(), n);
    return read_all<cl_float4>(out, n);
}

// ---- Statistics ------------------------------------------------------------

// Q(a, x), the regularized upper incomplete gamma function: from the series
// of P(a, x) for x < a + 1, else from its continued fraction (modified
// Lentz), the usual split that keeps both convergent.
double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    double lead = std::exp(a * std::log(x) - x - std::lgamma(a));
    if (x < a + 1) {
        double term = 1 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < 1e-16 * std::fabs(sum)) break;
        }
        return std::max(0.0, 1 - lead * sum);
    }
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1 / d;
        double del = d * c;
        h *= del;
        if (std::fabs(del - 1) < 1e-15) break;
    }
    return lead * h;
}

// P(X > x) for chi-square with df degrees of freedom.
double chi2_upper_tail(double x, double df) {
    return gamma_q(df / 2, x / 2);
}

// The exact inverse: the x with P(X > x) = p (bisection on the tail). The
// tests need it at p = 1e-3 / cases, where test::chi2_critical_001 does not
// reach.
double chi2_critical(double p, double df) {
    double lo = 0, hi = df + 10 * std::sqrt(2 * df) + 50;
    while (chi2_upper_tail(hi, df) > p)
        hi *= 2;
    for (int i = 0; i < 200 && hi - lo > 1e-10 * hi; ++i) {
        double mid = (lo + hi) / 2;
        (chi2_upper_tail(mid, df) > p ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Pearson's statistic after pooling: the cells with expected counts below 5
// go into one pool (topped up with the next smallest cells until its
// expectation reaches 5), as Mitsuba's test does. Observations where nothing
// is expected at all make the statistic infinite.
struct Chi2 {
    double stat = 0;
    int df = 0;
    int pooled_cells = 0;
};

Chi2 pooled_chi2(const std::vector<double>& obs, const std::vector<double>& expd) {
    const double min_expected = 5;
    std::vector<std::size_t> order(obs.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return expd[a] < expd[b]; });
    double po = 0, pe = 0;
    std::size_t k = 0;
    while (k < order.size() && expd[order[k]] < min_expected)
        po += obs[order[k]], pe += expd[order[k]], ++k;
    while (k > 0 && k < order.size() && pe < min_expected)
        po += obs[order[k]], pe += expd[order[k]], ++k;
    Chi2 r;
    r.pooled_cells = int(k);
    int bins = 0;
    for (std::size_t j = k; j < order.size(); ++j, ++bins) {
        double o = obs[order[j]], e = expd[order[j]];
        r.stat += (o - e) * (o - e) / e;
    }
    if (pe > 0) {
        r.stat += (po - pe) * (po - pe) / pe;
        ++bins;
    } else if (po > 0) {
        r.stat = INFINITY;
    }
    r.df = bins - 1;
    return r;
}

double rel_diff(double a, double b) {
    double m = std::max(std::fabs(a), std::fabs(b));
    return m > 0 ? std::fabs(a - b) / m : 0.0;
}

// ---- Cases -----------------------------------------------------------------

const char* dist_name(bool beckmann) {
    return beckmann ? "beckmann" : "ggx";
}
Microfacet dist(bool beckmann) {
    return beckmann ? Microfacet::Beckmann : Microfacet::Ggx;
}

// Gold-like complex index (RGB).
const Vec3 kGoldEta = {0.143f, 0.374f, 1.442f};
const Vec3 kGoldK = {3.983f, 2.386f, 1.603f};

struct ModelCase {
    std::string name;
    Material m;
    double cos_o;
};

std::string case_name(const char* model, double cos_o, double alpha = -1, bool beckmann = false) {
    char buf[128];
    if (alpha < 0)
        std::snprintf(buf, sizeof buf, "%s cos_o %.2f", model, cos_o);
    else
        std::snprintf(buf, sizeof buf, "%s %s alpha %.2f cos_o %.2f", model, dist_name(beckmann),
                      alpha, cos_o);
    return buf;
}

std::string model_name(const char* model, double alpha, bool beckmann) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s %s alpha %.2f", model, dist_name(beckmann), alpha);
    return buf;
}

const double kAlphas[3] = {0.1, 0.3, 0.7};
const double kOutside[3] = {0.95, 0.6, 0.2};
const double kBothSides[5] = {0.95, 0.6, 0.2, -0.7, -0.3};

// A probability rounded up to the choice slot's 16-bit grid, as the models
// round their lobe choices.
double grid_prob(double p) {
    return std::min(1.0, std::ceil(p * 65536.0) / 65536.0);
}

// The reference's rough coat of index 1.5 (ref::rough_coat at the model's
// COAT_T_SIZE nodes), integrated once per (alpha, distribution).
const ref::Coat& reference_coat(double alpha, bool beckmann) {
    static std::map<std::pair<double, bool>, ref::Coat> coats;
    auto it = coats.find({alpha, beckmann});
    if (it == coats.end())
        it = coats
                 .emplace(std::make_pair(alpha, beckmann),
                          ref::rough_coat(1.5, alpha, beckmann, COAT_T_SIZE))
                 .first;
    return it->second;
}

std::vector<ModelCase> diffuse_cases() {
    std::vector<ModelCase> c;
    for (double co : kOutside)
        c.push_back({case_name("diffuse", co), diffuse_material({0.8f, 0.5f, 0.3f}), co});
    return c;
}
std::vector<ModelCase> rough_conductor_cases() {
    std::vector<ModelCase> c;
    for (bool b : {false, true})
        for (double a : kAlphas)
            for (double co : kOutside)
                c.push_back({case_name("rough conductor", co, a, b),
                             conductor_material({1, 1, 1}, kGoldEta, kGoldK, float(a), dist(b)),
                             co});
    return c;
}
std::vector<ModelCase> rough_dielectric_cases() {
    std::vector<ModelCase> c;
    for (bool b : {false, true})
        for (double a : kAlphas)
            for (double co : kBothSides)
                c.push_back({case_name("rough dielectric", co, a, b),
                             dielectric_material(1.5f, float(a), dist(b)), co});
    return c;
}
std::vector<ModelCase> plastic_cases() {
    std::vector<ModelCase> c;
    for (double co : kOutside)
        c.push_back({case_name("plastic", co),
                     plastic_material({0.5f, 0.4f, 0.3f}, {0.9f, 0.9f, 0.9f}, 1.5f, 0.0f), co});
    return c;
}
std::vector<ModelCase> rough_plastic_cases() {
    std::vector<ModelCase> c;
    for (bool b : {false, true})
        for (double a : kAlphas)
            for (double co : kOutside)
                c.push_back({case_name("rough plastic", co, a, b),
                             plastic_material({0.5f, 0.4f, 0.3f}, {0.9f, 0.9f, 0.9f}, 1.5f,
                                              float(a), dist(b)),
                             co});
    return c;
}

bool has_dirac_lobe(const Material& m) {
    return m.type == MAT_CONDUCTOR || m.type == MAT_DIELECTRIC || m.type == MAT_PLASTIC ||
           m.type == MAT_THIN_DIELECTRIC;
}

// ---- Chi-square of a model's samples over the sphere ------------------------

// Cells of the sphere in (c, phi): c = wi.y in [-1, 1], phi = atan2(wi.z,
// wi.x) in [-pi, pi). The pole of this grid is y, normal to the plane of
// incidence (wo lies in the xz-plane): the lobes (reflection, refraction,
// the diffuse cosine around z) then lie on its equator, where cells are
// nearly square (0.042 x 0.065 rad), and the surface (wi.z = 0) is the
// cell boundary phi = 0, +-pi. The map is equal-area, so a cell's solid
// angle is its area in (c, phi).
const std::uint32_t kCellsC = 48, kCellsPhi = 96, kSub = 16;
const std::uint32_t kChi2Samples = 1u << 17;

std::size_t sphere_cell(D3 w) {
    w = ref::unit(w);
    double c = std::clamp(w.y, -1.0, 1.0), phi = std::atan2(w.z, w.x);
    std::uint32_t i = std::min(kCellsC - 1, std::uint32_t((c + 1) / 2 * kCellsC));
    std::uint32_t j = std::min(kCellsPhi - 1, std::uint32_t((phi + kPi) / (2 * kPi) * kCellsPhi));
    return std::size_t(i) * kCellsPhi + j;
}

// The expected share of each cell: shading_local_pdf_w integrated over it
// by the midpoint rule (probe_bsdf_pdf_cells; the sub-cells' sums are scaled
// and added in double here), on 6 x 6 sub-cells, then again on kSub x kSub
// for the cells that hold at least 1e-6 of the mass (all that the
// statistic and the integral can notice): the opaque models' pdfs are
// smooth on the sphere (their edge, wi.z = 0, is a cell boundary), but the
// rough dielectric's has the edges described at chi2_cases.
std::vector<double> cell_probabilities(const Material& m, D3 wo) {
    const std::uint32_t cells = kCellsC * kCellsPhi;
    ClBuffer mat = material_buffer(m);
    ClKernel k(bsdf_program().p, "probe_bsdf_pdf_cells");
    auto integrate = [&](const std::vector<cl_uint>& list, std::uint32_t sub) {
        const std::size_t n = list.size();
        ClBuffer in(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_uint), list.data());
        ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(float));
        k.set_args(mat, f4(wo), kCellsC, kCellsPhi, sub, in, cl_uint(n), out);
        k.run(test::cl(), n);
        std::vector<float> sums = read_all<float>(out, n);
        const double area = (2.0 / (kCellsC * sub)) * (2 * kPi / (kCellsPhi * sub));
        std::vector<double> p(n);
        for (std::size_t i = 0; i < n; ++i)
            p[i] = double(sums[i]) * area;
        return p;
    };
    std::vector<cl_uint> all(cells), fine;
    std::iota(all.begin(), all.end(), 0u);
    std::vector<double> p = integrate(all, 6);
    for (cl_uint c = 0; c < cells; ++c)
        if (p[c] >= 1e-6) fine.push_back(c);
    if (!fine.empty()) {
        std::vector<double> q = integrate(fine, kSub);
        for (std::size_t i = 0; i < fine.size(); ++i)
            p[fine[i]] = q[i];
    }
    return p;
}

// The cells that add most to the statistic (of those expecting at least 5),
// by their centre's direction, for the failure's message.
std::string worst_cells(const std::vector<double>& obs, const std::vector<double>& expd) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i + 1 < obs.size(); ++i)
        if (expd[i] >= 5) order.push_back(i);
    auto term = [&](std::size_t i) { return (obs[i] - expd[i]) * (obs[i] - expd[i]) / expd[i]; };
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return term(a) > term(b); });
    std::string msg = "; worst cells:";
    for (std::size_t k = 0; k < std::min<std::size_t>(6, order.size()); ++k) {
        std::size_t i = order[k];
        double c = -1 + (double(i / kCellsPhi) + 0.5) * 2 / kCellsC;
        double phi = -kPi + (double(i % kCellsPhi) + 0.5) * 2 * kPi / kCellsPhi;
        double sn = std::sqrt(1 - c * c);
        char buf[160];
        std::snprintf(buf, sizeof buf, " wi (%.3f %.3f %.3f) observed %.0f expected %.1f;",
                      sn * std::cos(phi), c, sn * std::sin(phi), obs[i], expd[i]);
        msg += buf;
    }
    return msg;
}

// Each case: the non-delta samples binned over the sphere against n times
// each cell's probability, plus one bin for the rest (Dirac samples and
// failed ones, weight 0) expected n (1 - integral of pdf_w); the chi-square
// is rejected at 1e-3 / cases. The Dirac and failed samples are then checked
// against n (1 - integral of pdf_w) by a binomial z-test at the same
// significance (two-sided), with an allowance of n * 1e-3 for the
// quadrature of the integral; a model without a Dirac lobe must draw no Dirac
// sample at all. The quadrature: the pdfs are not smooth everywhere. The
// reflection of the dielectric from inside has F's square-root edge at the
// critical angle, and its transmission jumps where the generalized half
// vector crosses the horizon (GGX's D is not 0 at m.z = 0), which the
// midpoint rule resolves only to O(sub-cell width): measured against a
// 64 x 64 sub-grid, the integral errs by up to 4e-4 on 16 x 16 sub-cells
// (2.4e-3 on 6 x 6), for GGX alpha 0.7 at cos_o 0.2, and the cells'
// expectations by < 1% where the statistic would notice.
void chi2_cases(const std::vector<ModelCase>& cases, std::uint64_t seed) {
    const double case_alpha = kAlpha / double(cases.size());
    const double z_crit = test::normal_quantile(1 - case_alpha / 2);
    const double n = kChi2Samples;
    for (std::size_t ci = 0; ci < cases.size(); ++ci) {
        const ModelCase& c = cases[ci];
        D3 wo = ref::incident(c.cos_o);
        std::vector<Sample> s = draw_samples(c.m, wo, seed + 101 * ci, kChi2Samples, false);
        std::vector<double> p = cell_probabilities(c.m, wo);
        double integral = std::accumulate(p.begin(), p.end(), 0.0);
        std::vector<double> obs(p.size() + 1, 0.0), expd(p.size() + 1, 0.0);
        std::size_t dirac = 0, failed = 0, bad = 0;
        for (const Sample& x : s) {
            if (!std::isfinite(x.wi.x + x.wi.y + x.wi.z + x.pdf_w + x.weight[0] + x.weight[1] +
                               x.weight[2])) {
                ++bad;
                continue;
            }
            if (x.failed() || x.dirac()) {
                (x.failed() ? failed : dirac) += 1;
                obs.back() += 1;
            } else {
                obs[sphere_cell(x.wi)] += 1;
            }
        }
        for (std::size_t i = 0; i < p.size(); ++i)
            expd[i] = n * p[i];
        double rest = std::max(0.0, 1 - integral);
        expd.back() = n * rest;
        Chi2 r = pooled_chi2(obs, expd);
        double crit = chi2_critical(case_alpha, r.df);
        double sd = std::sqrt(n * rest * (1 - rest));
        double z_dev = std::fabs(double(dirac + failed) - n * (1 - integral)); // unclamped
        std::printf("  %-44s chi2 %9.1f df %4d crit %7.1f | int pdf %.5f dirac %6zu failed %6zu "
                    "(expected %.0f)\n",
                    c.name.c_str(), r.stat, r.df, crit, integral, dirac, failed, n * rest);
        EXPECT_EQ(bad, 0u) << c.name << ": samples that are not finite";
        EXPECT_GT(r.df, 0) << c.name;
        EXPECT_LT(r.stat, crit) << c.name << ": chi-square " << r.stat << " with " << r.df
                                << " degrees of freedom (" << r.pooled_cells << " cells pooled)"
                                << worst_cells(obs, expd);
        EXPECT_LE(z_dev, z_crit * sd + n * 1e-3)
            << c.name << ": " << dirac << " Dirac and " << failed << " failed samples of " << n
            << ", the density integrates to " << integral;
        if (!has_dirac_lobe(c.m)) {
            EXPECT_EQ(dirac, 0u) << c.name << ": Dirac samples";
        }
    }
}

// ---- Quadrature grids over microfacet normals --------------------------------

// The midpoints of nv x nphi cells in (v, phi) of ref::normal_map, phi over
// [0, 2 pi), with each point's weight d(solid angle) = jacobian dv dphi.
void normal_grid(double alpha, int nv, int nphi, std::vector<D3>* m, std::vector<double>* dw) {
    m->clear();
    dw->clear();
    double dv = 1.0 / nv, dphi = 2 * kPi / nphi;
    for (int i = 0; i < nv; ++i) {
        double c, jac;
        ref::normal_map((i + 0.5) * dv, alpha, &c, &jac);
        for (int j = 0; j < nphi; ++j) {
            m->push_back(ref::polar(c, (j + 0.5) * dphi));
            dw->push_back(jac * dv * dphi);
        }
    }
}

} // namespace

// ============================================================================
// Statistics used below.

// The exact chi-square quantile agrees with the tabulated values at 1e-3
// (df 1, 2: 10.828, 13.816) and with Wilson-Hilferty for large df.
TEST(BsdfStats, ChiSquareQuantiles) {
    EXPECT_NEAR(chi2_critical(1e-3, 1), 10.828, 2e-3);
    EXPECT_NEAR(chi2_critical(1e-3, 2), 13.816, 2e-3);
    EXPECT_NEAR(chi2_critical(1e-3, 500), test::chi2_critical_001(500), 0.002 * 600);
    EXPECT_NEAR(chi2_upper_tail(chi2_critical(1e-5, 2000), 2000), 1e-5, 1e-8);
}

// ============================================================================
// 1. Microfacet distributions.

// Integral of D(m) m.z over the hemisphere is 1 for GGX and Beckmann at
// alphas 0.05 to 1: midpoint rule on 4096 points of ref::normal_map (a
// variable in which the peak is resolved at any alpha; a narrower peak
// lies in the same cells), at four azimuths (D is isotropic), to 1e-3. The
// visible normals' density mf_pdf_visible integrates to 1 over m for wo at
// cosines 0.95, 0.5, 0.1 (this ties mf_lambda to mf_d: Lambda is defined by
// the projected area), on a 512 x 256 grid, to 1e-3; the same grid with the
// host's formula gives 1 within 1e-5, which bounds the quadrature's error.
TEST(Microfacet, DistributionsAreNormalized) {
    for (bool b : {false, true})
        for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
            const int nv = 4096;
            const double phis[4] = {0.1, 1.7, 3.3, 5.1};
            std::vector<D3> wo, m;
            std::vector<double> dw;
            for (double phi : phis)
                for (int i = 0; i < nv; ++i) {
                    double c, jac;
                    ref::normal_map((i + 0.5) / nv, alpha, &c, &jac);
                    m.push_back(ref::polar(c, phi));
                    wo.push_back({0, 0, 1});
                    dw.push_back(jac / nv * 2 * kPi);
                }
            std::vector<cl_float4> out = mf_eval(alpha, b, wo, m);
            for (int k = 0; k < 4; ++k) {
                double sum = 0;
                for (int i = 0; i < nv; ++i) {
                    std::size_t j = std::size_t(k) * nv + i;
                    sum += double(out[j].s[0]) * m[j].z * dw[j];
                }
                EXPECT_NEAR(sum, 1.0, 1e-3)
                    << dist_name(b) << " alpha " << alpha << " phi " << phis[k];
            }

            for (double co : {0.95, 0.5, 0.1}) {
                D3 o = ref::incident(co);
                normal_grid(alpha, 512, 256, &m, &dw);
                wo.assign(m.size(), o);
                out = mf_eval(alpha, b, wo, m);
                double sum = 0, host = 0;
                for (std::size_t j = 0; j < m.size(); ++j) {
                    sum += double(out[j].s[2]) * dw[j];
                    host += ref::visible_pdf(o, m[j], alpha, b) * dw[j];
                }
                ASSERT_NEAR(host, 1.0, 1e-5) << "the quadrature itself";
                EXPECT_NEAR(sum, 1.0, 1e-3) << dist_name(b) << " alpha " << alpha << " cos_o " << co
                                            << ": integral of mf_pdf_visible";
            }
        }
}

// mf_d, mf_lambda, mf_g1 and mf_pdf_visible against the host's formulas
// (test/bsdf_reference.hpp) at random directions and normals: relative
// 1e-4 (float evaluation of the same expressions; Beckmann's Lambda by
// erf), Lambda by the relative error it causes in G1. Normals are drawn
// around the lobe (tan theta up to 4 alpha) and include back-facing ones,
// where G1 must be 0.
TEST(MicrofacetReference, FunctionsMatchTheDefinitions) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0, 1);
    for (bool b : {false, true})
        for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
            std::vector<D3> wo, m;
            for (int i = 0; i < 2000; ++i) {
                double co = 0.02 + 0.98 * u(rng);
                D3 o = ref::polar(co, 2 * kPi * u(rng));
                double t = 4 * alpha * u(rng);
                D3 h = ref::polar(1 / std::sqrt(1 + t * t), 2 * kPi * u(rng));
                wo.push_back(o);
                m.push_back(h);
            }
            std::vector<cl_float4> out = mf_eval(alpha, b, wo, m);
            double worst[4] = {0, 0, 0, 0};
            std::size_t at[4] = {0, 0, 0, 0};
            for (std::size_t i = 0; i < wo.size(); ++i) {
                double want[4] = {ref::ndf(m[i], alpha, b), ref::smith_g1(wo[i], m[i], alpha, b),
                                  ref::visible_pdf(wo[i], m[i], alpha, b),
                                  ref::smith_lambda(wo[i], alpha, b)};
                for (int q = 0; q < 4; ++q) {
                    // Lambda by the error it makes in G1 = 1 / (1 + Lambda): near
                    // the pole Lambda is ~1e-6 and float's (sqrt(1 + x) - 1) / 2
                    // keeps few of its digits, which G1 never sees.
                    double e = q == 3 ? std::fabs(out[i].s[3] - want[3]) / (1 + want[3])
                                      : rel_diff(out[i].s[q], want[q]);
                    if (e > worst[q]) worst[q] = e, at[q] = i;
                }
            }
            const char* what[4] = {"mf_d", "mf_g1", "mf_pdf_visible", "mf_lambda"};
            for (int q = 0; q < 4; ++q)
                EXPECT_LT(worst[q], 1e-4) << dist_name(b) << " alpha " << alpha << ": " << what[q]
                                          << " at wo.z " << wo[at[q]].z << ", m.z " << m[at[q]].z
                                          << ", dot " << ref::dot(wo[at[q]], m[at[q]]);
        }
}

// ============================================================================
// 2. mf_sample_visible draws normals with density mf_pdf_visible: chi-square
// on 32 x 32 cells in (v, phi) of ref::normal_map (cells in cos theta_m
// whose edges follow the lobe, and azimuth), 2^17 normals per case; each
// cell's expectation is mf_pdf_visible integrated over 8 x 8 sub-cells (the
// midpoint rule, summed in double). Cells expecting fewer than 5 are pooled.
// 24 cases (GGX and Beckmann, alpha 0.05 to 1, cos_o 0.95, 0.5, 0.1), each
// rejected at 1e-3 / 24 by the exact chi-square quantile.
TEST(Microfacet, VisibleNormalsFollowTheirPdf) {
    const int nv = 32, nphi = 32, sub = 8;
    const std::uint32_t n = 1u << 17;
    const double alphas[4] = {0.05, 0.2, 0.5, 1.0}, cosines[3] = {0.95, 0.5, 0.1};
    const double case_alpha = kAlpha / 24;
    std::uint64_t seed = 7;
    for (bool b : {false, true})
        for (double alpha : alphas)
            for (double co : cosines) {
                D3 o = ref::incident(co);
                ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
                ClKernel k(bsdf_program().p, "probe_mf_sample");
                k.set_args(float(alpha), cl_uint(b), f4(o), cl_ulong(seed++), n, out);
                k.run(test::cl(), n);
                std::vector<double> obs(nv * nphi, 0.0), expd(nv * nphi, 0.0);
                std::size_t below = 0, not_unit = 0;
                for (const cl_float4& x : read_all<cl_float4>(out, n)) {
                    D3 m = d3(x);
                    double len = ref::norm(m);
                    if (!(std::fabs(len - 1) < 1e-4)) ++not_unit;
                    m = ref::unit(m);
                    if (!(m.z > 0)) {
                        ++below;
                        continue;
                    }
                    double t = (1 - m.z * m.z) / (m.z * m.z), uu = t / (alpha * alpha + t);
                    double v = 1 - std::sqrt(std::max(0.0, 1 - uu));
                    double phi = std::atan2(m.y, m.x);
                    if (phi < 0) phi += 2 * kPi;
                    int i = std::min(nv - 1, int(v * nv)),
                        j = std::min(nphi - 1, int(phi / (2 * kPi) * nphi));
                    obs[std::size_t(i) * nphi + j] += 1;
                }
                std::vector<D3> m, wo;
                std::vector<double> dw;
                normal_grid(alpha, nv * sub, nphi * sub, &m, &dw);
                wo.assign(m.size(), o);
                std::vector<cl_float4> pv = mf_eval(alpha, b, wo, m);
                for (std::size_t q = 0; q < m.size(); ++q) {
                    std::size_t row = q / (nphi * sub), col = q % (nphi * sub);
                    expd[(row / sub) * nphi + col / sub] += n * double(pv[q].s[2]) * dw[q];
                }
                Chi2 r = pooled_chi2(obs, expd);
                double crit = chi2_critical(case_alpha, r.df);
                std::printf("  visible normals %-8s alpha %.2f cos_o %.2f: chi2 %7.1f df %4d "
                            "crit %6.1f\n",
                            dist_name(b), alpha, co, r.stat, r.df, crit);
                EXPECT_EQ(below, 0u) << "normals with m.z <= 0";
                EXPECT_EQ(not_unit, 0u) << "normals that are not unit vectors";
                EXPECT_LT(r.stat, crit) << dist_name(b) << " alpha " << alpha << " cos_o " << co
                                        << ": chi-square with " << r.df << " degrees of freedom";
            }
}

// ============================================================================
// 3. Chi-square of each model's sampling against its pdf_w, over the whole
// sphere (so that transmission is covered), 2^17 samples per case; see
// chi2_cases for the cells, the pooling and the Dirac mass.

TEST(BsdfChi2, Diffuse) {
    chi2_cases(diffuse_cases(), 1000);
}
TEST(BsdfChi2, RoughConductor) {
    chi2_cases(rough_conductor_cases(), 2000);
}
TEST(BsdfChi2, RoughDielectric) {
    chi2_cases(rough_dielectric_cases(), 3000);
}
// The smooth plastic: the diffuse lobe's density against its samples, the
// coat's Dirac samples against 1 - integral (the coat's choice probability).
TEST(BsdfChi2, Plastic) {
    chi2_cases(plastic_cases(), 4000);
}
TEST(BsdfChi2, RoughPlastic) {
    chi2_cases(rough_plastic_cases(), 5000);
}

// The smooth conductor, dielectric and thin dielectric are Dirac lobes alone: every sample
// has pdf_w 0 and a weight, and eval and pdf_w are 0 everywhere (checked at
// the sampled directions and on the sphere's grid).
TEST(BsdfChi2, DiracModelsHaveNoDensity) {
    std::vector<ModelCase> cases;
    for (double co : kOutside)
        cases.push_back({case_name("conductor", co),
                         conductor_material({1, 1, 1}, kGoldEta, kGoldK, 0.0f), co});
    for (double co : kBothSides)
        cases.push_back({case_name("dielectric", co), dielectric_material(1.5f, 0.0f), co});
    for (double co : kBothSides)
        cases.push_back({case_name("thin dielectric", co), thin_dielectric_material(1.5f), co});
    for (const ModelCase& c : cases) {
        D3 wo = ref::incident(c.cos_o);
        std::vector<Sample> s = draw_samples(c.m, wo, 77, 1u << 12);
        std::size_t not_dirac = 0, density = 0;
        for (const Sample& x : s) {
            if (!x.dirac()) ++not_dirac;
            if (x.pdf_eval != 0 || x.f[0] != 0 || x.f[1] != 0 || x.f[2] != 0) ++density;
        }
        std::vector<double> p = cell_probabilities(c.m, wo);
        EXPECT_EQ(not_dirac, 0u) << c.name;
        EXPECT_EQ(density, 0u) << c.name << ": eval or pdf_w not 0 at the sampled directions";
        EXPECT_EQ(std::accumulate(p.begin(), p.end(), 0.0), 0.0) << c.name << ": pdf_w on the grid";
    }
}

// The thin dielectric (index 1.5), from both sides: every sample is the
// mirror direction or wo passed straight through (-wo); the share of
// reflections is the rounded R = 2F / (1 + F), F the host's Fresnel term,
// within the binomial quantile at 1e-3 over the five angles (Bonferroni);
// the weights are exactly R / p and (1 - R) / (1 - p) (relative 1e-5), so
// that the sheet conserves energy.
TEST(BsdfThinDielectric, ReflectsTwoFOverOnePlusFAndPassesTheRestStraight) {
    const std::uint32_t n = 1u << 16;
    const double z = test::normal_quantile(1 - kAlpha / (2.0 * 5));
    Material m = thin_dielectric_material(1.5f);
    std::uint64_t seed = 91;
    for (double co : kBothSides) {
        D3 wo = ref::incident(co);
        double f = ref::fresnel(std::fabs(co), 1.5), r = 2 * f / (1 + f), p = grid_prob(r);
        std::vector<Sample> s = draw_samples(m, wo, seed++, n, false);
        std::size_t reflected = 0, other = 0, bad_weight = 0;
        for (const Sample& x : s) {
            bool refl = std::fabs(x.wi.x + wo.x) < 1e-6 && std::fabs(x.wi.z - wo.z) < 1e-6;
            bool through = std::fabs(x.wi.x + wo.x) < 1e-6 && std::fabs(x.wi.z + wo.z) < 1e-6;
            if (refl) ++reflected;
            if (!refl && !through) ++other;
            double want = refl ? r / p : (1 - r) / (1 - p);
            for (double w : x.weight)
                if (!(std::fabs(w - want) <= 1e-5 * want)) ++bad_weight;
        }
        double share = double(reflected) / n, se = std::sqrt(p * (1 - p) / n);
        std::printf("  thin dielectric cos_o %+.2f: R %.5f, reflected %.5f (bound %.5f)\n", co, r,
                    share, z * se);
        EXPECT_EQ(other, 0u) << "cos_o " << co << ": neither mirrored nor straight through";
        EXPECT_NEAR(share, p, z * se) << "cos_o " << co;
        EXPECT_EQ(bad_weight, 0u) << "cos_o " << co;
    }
}

// ============================================================================
// 4. For every non-delta sample (pdf_w > 0, weight not 0) of every case of
// the chi-square tests (2^14 samples each): pdf_w equals shading_local_pdf_w
// at the sampled wi, and each channel of the weight equals shading_local_eval
// |wi.z| / shading_local_pdf_w there, to a relative 1e-3 (both sides are a
// few float operations on the same quantities, at most ~1e-5 apart in
// rounding; 1e-3 is far below any modelling error, e.g. a lost cosine or a
// lobe's missing choice probability).
TEST(BsdfConsistency, SampleEvalAndPdfAgree) {
    std::vector<ModelCase> cases = diffuse_cases();
    for (auto more : {rough_conductor_cases(), rough_dielectric_cases(), plastic_cases(),
                      rough_plastic_cases()})
        cases.insert(cases.end(), more.begin(), more.end());
    for (std::size_t ci = 0; ci < cases.size(); ++ci) {
        const ModelCase& c = cases[ci];
        std::vector<Sample> s = draw_samples(c.m, ref::incident(c.cos_o), 9000 + ci, 1u << 14);
        std::size_t checked = 0, pdf_bad = 0, weight_bad = 0;
        double worst_pdf = 0, worst_weight = 0;
        D3 worst_wi;
        for (const Sample& x : s) {
            if (x.failed() || x.dirac()) continue;
            ++checked;
            double e = rel_diff(x.pdf_w, x.pdf_eval);
            worst_pdf = std::max(worst_pdf, e);
            if (!(e <= 1e-3)) ++pdf_bad;
            double ew = 0;
            for (int ch = 0; ch < 3; ++ch) {
                double want = x.pdf_eval > 0 ? x.f[ch] * std::fabs(x.wi.z) / x.pdf_eval : INFINITY;
                ew = std::max(ew, std::isfinite(want) ? rel_diff(x.weight[ch], want) : 1.0);
            }
            if (ew > worst_weight) worst_weight = ew, worst_wi = x.wi;
            if (!(ew <= 1e-3)) ++weight_bad;
        }
        EXPECT_GT(checked, 0u) << c.name;
        EXPECT_EQ(pdf_bad, 0u) << c.name << ": pdf_w differs from the pdf at wi (worst relative "
                               << worst_pdf << ")";
        EXPECT_EQ(weight_bad, 0u) << c.name << ": weight differs from f |cos| / pdf (worst "
                                  << worst_weight << " at wi.z " << worst_wi.z << ")";
    }
}

// ============================================================================
// 5. White furnace: the albedo along wo, estimated as the mean sample weight
// over 2^18 samples (transmitted weights times (eta_i / eta_o)^2, which undoes
// the radiance scaling of refraction: the expected value is then the share
// of energy scattered), against a stated expected value. The bound is the
// normal quantile at 1e-3 / cases (two-sided) times the standard error from
// the sample standard deviation, plus 1e-4 for float rounding (each weight
// is exact to ~1e-6; the sums are double) and the host quadratures (below
// 1e-6, see ref::visible_expectation).
namespace {

struct Albedo {
    double mean = 0, bound = 0;
};

// `ior`: where the model refracts, the index of its inside (0: opaque).
Albedo furnace(const Material& m, D3 wo, std::uint64_t seed, double z, double ior = 0) {
    const std::uint32_t n = 1u << 18;
    std::vector<cl_float4> w = draw_weights(m, wo, seed, n);
    double sum = 0, sum2 = 0;
    for (const cl_float4& x : w) {
        double v = (double(x.s[0]) + x.s[1] + x.s[2]) / 3;
        if (ior > 0 && double(x.s[3]) * wo.z < 0) {
            double eo = wo.z > 0 ? 1 : ior, ei = wo.z > 0 ? ior : 1;
            v *= (ei / eo) * (ei / eo);
        }
        if (!std::isfinite(v)) v = 1e30; // fails the test, visibly
        sum += v;
        sum2 += v * v;
    }
    Albedo a;
    a.mean = sum / n;
    double var = std::max(0.0, (sum2 - n * a.mean * a.mean) / (n - 1));
    a.bound = z * std::sqrt(var / n) + 1e-4;
    return a;
}

double furnace_z(std::size_t cases) {
    return test::normal_quantile(1 - kAlpha / (2.0 * double(cases)));
}

void print_albedo(const std::string& name, const Albedo& a, double want) {
    std::printf("  %-48s albedo %.6f expected %.6f (bound %.1e)\n", name.c_str(), a.mean, want,
                a.bound);
}

} // namespace

// Lambertian kd = 1 reflects everything: 1 at every wo.
TEST(BsdfFurnace, DiffuseReflectsAll) {
    double z = furnace_z(3);
    for (double co : kOutside) {
        Albedo a = furnace(diffuse_material({1, 1, 1}), ref::incident(co), 31, z);
        print_albedo(case_name("diffuse", co), a, 1);
        EXPECT_NEAR(a.mean, 1.0, a.bound) << "cos_o " << co;
    }
}

// The smooth conductor with eta 0, k 1 (Fresnel 1) and ks 1: 1.
TEST(BsdfFurnace, SmoothConductorReflectsAll) {
    double z = furnace_z(3);
    for (double co : kOutside) {
        Albedo a = furnace(conductor_material({1, 1, 1}, {0, 0, 0}, {1, 1, 1}, 0.0f),
                           ref::incident(co), 32, z);
        print_albedo(case_name("conductor eta 0 k 1", co), a, 1);
        EXPECT_NEAR(a.mean, 1.0, a.bound) << "cos_o " << co;
    }
}

// The smooth dielectric of index 1.5 from both sides (inside at -0.3 is past
// the critical angle: all reflected): reflection plus transmission with the
// radiance scaling undone is 1 (F + (1 - F)), exactly at the grid.
TEST(BsdfFurnace, SmoothDielectricConservesEnergy) {
    const double cosines[6] = {0.95, 0.6, 0.2, -0.95, -0.7, -0.3};
    double z = furnace_z(6);
    for (double co : cosines) {
        Albedo a = furnace(dielectric_material(1.5f, 0.0f), ref::incident(co), 33, z, 1.5);
        print_albedo(case_name("dielectric", co), a, 1);
        EXPECT_NEAR(a.mean, 1.0, a.bound) << "cos_o " << co;
    }
}

// The rough dielectric of index 1.5 from both sides: the single-scattering
// albedo computed on the host from the model's definition (ref::
// rough_dielectric_albedo: F G1(reflected) + (1 - F) G1(refracted) over the
// visible normals, separable Smith G, Fresnel of the facet), 30 cases.
TEST(BsdfFurnace, RoughDielectricMatchesReference) {
    std::vector<ModelCase> cases = rough_dielectric_cases();
    double z = furnace_z(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const ModelCase& c = cases[i];
        D3 wo = ref::incident(c.cos_o);
        bool b = (c.m.flags & MAT_FLAG_BECKMANN) != 0;
        double want = ref::rough_dielectric_albedo(wo, 1.5, c.m.alpha, b);
        Albedo a = furnace(c.m, wo, 34 + i, z, 1.5);
        print_albedo(c.name, a, want);
        EXPECT_NEAR(a.mean, want, a.bound) << c.name;
        EXPECT_LE(want, 1.0 + 1e-6) << c.name; // the quadrature errs by ~1e-7
    }
}

// A rough dielectric of index 1 (matched to its surroundings) transmits
// everything through every facet: F = 0, and every refracted direction is
// wi = -wo. What the single-scattering model loses is the shadowing of wi
// alone: the separable Smith G1(wi, m) = 1 / (1 + Lambda(-wo)), the same for
// every visible normal, so the albedo is exactly G1(wo) = 1 / (1 +
// Lambda(wo)) (1 within 3e-4 at cos_o 0.95; 0.44 for GGX alpha 0.7 at cos_o
// 0.2). The host's quadrature of the general formula agrees with it (checked
// here too).
TEST(BsdfFurnace, MatchedRoughDielectricLosesOnlyShadowing) {
    std::vector<ModelCase> cases;
    for (bool b : {false, true})
        for (double a : kAlphas)
            for (double co : kOutside)
                cases.push_back({case_name("rough dielectric ior 1", co, a, b),
                                 dielectric_material(1.0f, float(a), dist(b)), co});
    double z = furnace_z(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const ModelCase& c = cases[i];
        D3 wo = ref::incident(c.cos_o);
        bool b = (c.m.flags & MAT_FLAG_BECKMANN) != 0;
        double want = 1 / (1 + ref::smith_lambda(wo, c.m.alpha, b));
        ASSERT_NEAR(ref::rough_dielectric_albedo(wo, 1.0, c.m.alpha, b), want, 1e-5) << c.name;
        Albedo a = furnace(c.m, wo, 35 + i, z, 1.0);
        print_albedo(c.name, a, want);
        EXPECT_NEAR(a.mean, want, a.bound) << c.name;
    }
}

// Smooth plastic kd 1, ks 1: the coat reflects F(wo.z), the base returns
// the rest, (1 - F(wo.z)) times integral of (1 - F(wi.z)) wi.z / pi over
// ior^2 (1 - fdr_int) = 1: the albedo is 1 at every wo (the identity
// 1 - fdr_ext = ior^2 (1 - fdr_int); the host's fdr_int is exact to 1e-6).
TEST(BsdfFurnace, SmoothPlasticIsWhite) {
    double z = furnace_z(3);
    for (double co : kOutside) {
        Material m = plastic_material({1, 1, 1}, {1, 1, 1}, 1.5f, 0.0f);
        Albedo a = furnace(m, ref::incident(co), 36, z);
        print_albedo(case_name("plastic kd 1 ks 1", co), a, 1);
        EXPECT_NEAR(a.mean, 1.0, a.bound) << "cos_o " << co;
    }
    // The identity itself, from the host's Fresnel alone.
    double fe = ref::fresnel_hemispherical(1.5), fi = ref::fresnel_hemispherical(1 / 1.5);
    EXPECT_NEAR((1 - fe) / (1.5 * 1.5 * (1 - fi)), 1.0, 1e-6);
    EXPECT_NEAR(plastic_material({1, 1, 1}, {1, 1, 1}, 1.5f, 0.0f).fdr_int, fi, 1e-6);
}

// The rough conductor with Fresnel 1 (eta 0, k 1, ks 1): the single-
// scattering albedo, the visible normals' mean of G1(wi) for the reflected
// wi (ref::rough_conductor_albedo, the host's own D and Lambda), below 1
// and not increasing with alpha (strictly for alpha >= 0.3 and for GGX).
TEST(BsdfFurnace, RoughConductorSingleScattering) {
    double z = furnace_z(18);
    std::uint64_t seed = 37;
    for (bool b : {false, true})
        for (double co : kOutside) {
            double last = 1.0 + 1e-6; // the quadrature errs by ~1e-7
            for (double alpha : kAlphas) {
                Material m =
                    conductor_material({1, 1, 1}, {0, 0, 0}, {1, 1, 1}, float(alpha), dist(b));
                D3 wo = ref::incident(co);
                double want = ref::rough_conductor_albedo(wo, alpha, b);
                Albedo a = furnace(m, wo, seed++, z);
                std::string name = case_name("rough conductor F 1", co, alpha, b);
                print_albedo(name, a, want);
                EXPECT_NEAR(a.mean, want, a.bound) << name;
                EXPECT_LE(want, last + 1e-6) << name << ": the albedo grows with alpha";
                if (alpha >= 0.3 || !b) {
                    EXPECT_LT(want, last) << name;
                }
                EXPECT_LT(a.mean, 1.0 + a.bound) << name;
                last = want;
            }
        }
}

// The rough plastic kd 1, ks 1: the albedo from the model's definition
// (ref::rough_plastic_albedo: the coat's F(wo.m) G1(wi) over the visible
// normals plus the base seen through the coat's transmittance), and at most
// 1: the coat reflects E[F G1(reflected)] and lets through
// t = E[(1 - F) G1(refracted)], at most 1 together, and the base returns at
// most what enters (its factor T / (ior^2 (1 - inner)) is below 1: by
// reciprocity T / ior^2 is the coat's transmittance from inside, at most
// 1 - inner).
TEST(BsdfFurnace, RoughPlasticAtMostOne) {
    double z = furnace_z(18);
    std::uint64_t seed = 57;
    for (bool b : {false, true})
        for (double alpha : kAlphas)
            for (double co : kOutside) {
                Material m = plastic_material({1, 1, 1}, {1, 1, 1}, 1.5f, float(alpha), dist(b));
                D3 wo = ref::incident(co);
                double want =
                    ref::rough_plastic_albedo(wo, 1, 1, 1.5, reference_coat(alpha, b), alpha, b);
                Albedo a = furnace(m, wo, seed++, z);
                std::string name = case_name("rough plastic kd 1 ks 1", co, alpha, b);
                print_albedo(name, a, want);
                EXPECT_NEAR(a.mean, want, a.bound) << name;
                EXPECT_LE(want, 1.0 + 1e-5) << name << ": the definition creates energy";
                EXPECT_LE(a.mean, 1.0 + a.bound) << name;
            }
}

// The host's rough coat (src/scene/plastic_coat.cpp) against the reference's
// finer quadrature of the same definitions: each transmittance node and the
// inner reflectance to 2e-4; the 16-bit table reads back to half a step; a
// nearly smooth coat (alpha 1e-3) has the smooth interface's 1 - F and
// hemispherical reflectance, to 2e-3 (the smooth F's kink at the critical
// angle is resolved to that); and the table's linear interpolation is
// within 5e-3 of the transmittance itself between nodes, for cos >= 0.05.
TEST(BsdfCoat, RoughCoatMatchesItsDefinition) {
    for (bool b : {false, true}) {
        for (double alpha : kAlphas) {
            RoughCoat c = integrate_rough_coat(1.5, alpha, b);
            const ref::Coat& r = reference_coat(alpha, b);
            std::string name = model_name("coat", alpha, b);
            double worst = 0;
            for (int i = 0; i < COAT_T_SIZE; ++i)
                worst = std::max(worst, std::fabs(c.transmittance[i] - r.t[i]));
            std::printf("  %-30s t worst %.1e, inner %.6f (reference %.6f)\n", name.c_str(), worst,
                        c.inner_reflectance, r.inner);
            EXPECT_LT(worst, 2e-4) << name;
            EXPECT_NEAR(c.inner_reflectance, r.inner, 2e-4) << name;
            Material m{};
            store_coat_transmittance(m, c);
            for (int i = 0; i < COAT_T_SIZE; ++i) {
                double back = double((m.coat_t[COAT_T_WORD(i)] >> COAT_T_SHIFT(i)) & 0xFFFFu) /
                              double(COAT_T_ONE);
                EXPECT_NEAR(back, c.transmittance[i], 0.5 / COAT_T_ONE + 1e-9) << name << " " << i;
            }
            double interp = 0;
            for (int k = 0; k < 16; ++k) {
                double co = 0.05 + 0.95 * (k + 0.37) / 16;
                double exact = ref::coat_energy(false, co, 1.5, alpha, b, 512, 128);
                interp = std::max(interp, std::fabs(r.transmittance(co) - exact));
            }
            std::printf("  %-30s interpolation worst %.1e\n", name.c_str(), interp);
            EXPECT_LT(interp, 5e-3) << name;
        }
        RoughCoat s = integrate_rough_coat(1.5, 1e-3, b);
        for (int i = 2; i < COAT_T_SIZE; ++i) {
            double co = double(i) / (COAT_T_SIZE - 1);
            EXPECT_NEAR(s.transmittance[i], 1 - ref::fresnel(co, 1.5), 2e-3) << "cos " << co;
        }
        EXPECT_NEAR(s.inner_reflectance, ref::fresnel_hemispherical(1 / 1.5), 2e-3);
    }
}

// ============================================================================
// 6. Reciprocity and the evaluation against the definitions.
namespace {

// Direction pairs for reflection on the +z side: half uniformly random, half
// near the specular configuration (wi the reflection of wo about a normal
// drawn with tan theta up to 2 alpha), both with cosines >= 0.05.
void reflection_pairs(double alpha, std::uint64_t seed, int n, std::vector<D3>* wo,
                      std::vector<D3>* wi) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    while (int(wo->size()) < n) {
        D3 o = ref::polar(0.05 + 0.95 * u(rng), 2 * kPi * u(rng)), i;
        if (wo->size() % 2) {
            i = ref::polar(0.05 + 0.95 * u(rng), 2 * kPi * u(rng));
        } else {
            double t = 2 * std::max(alpha, 0.05) * u(rng);
            i = ref::reflect(o, ref::polar(1 / std::sqrt(1 + t * t), 2 * kPi * u(rng)));
            if (i.z < 0.05) continue;
        }
        wo->push_back(o);
        wi->push_back(i);
    }
}

// Transmission pairs of the dielectric of index ior: wo on either side
// (|wo.z| >= 0.1), wi its refraction through a normal with tan theta up to
// 2 alpha, kept where it crosses the surface with |wi.z| >= 0.05.
void transmission_pairs(double alpha, double ior, std::uint64_t seed, int n, std::vector<D3>* wo,
                        std::vector<D3>* wi) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    while (int(wo->size()) < n) {
        double side = wo->size() % 2 ? -1 : 1;
        D3 o = ref::polar(side * (0.1 + 0.9 * u(rng)), 2 * kPi * u(rng)), i;
        double t = 2 * alpha * u(rng);
        D3 m = ref::polar(side / std::sqrt(1 + t * t), 2 * kPi * u(rng));
        if (ref::dot(o, m) <= 0) continue;
        double eta = side > 0 ? ior : 1 / ior;
        if (!ref::refract(o, m, eta, &i) || !(i.z * side < -0.05)) continue;
        wo->push_back(o);
        wi->push_back(i);
    }
}

// Reflection pairs of the dielectric on both sides: those of
// reflection_pairs, every second one mirrored to the inside.
void dielectric_reflection_pairs(double alpha, std::uint64_t seed, int n, std::vector<D3>* wo,
                                 std::vector<D3>* wi) {
    reflection_pairs(alpha, seed, n, wo, wi);
    for (std::size_t k = 1; k < wo->size(); k += 2) {
        (*wo)[k].z = -(*wo)[k].z;
        (*wi)[k].z = -(*wi)[k].z;
    }
}

struct PairCheck {
    std::size_t pairs = 0, positive = 0, bad = 0;
    double worst = 0;
    D3 worst_wo, worst_wi;
};

// f(wo, wi) against f(wi, wo) for each pair, each channel: relative 1e-4
// (the same float expressions with the arguments swapped), where
// scale(wo, wi) multiplies f(wo, wi): 1, or 1 / eta_o^2 for the
// generalized form of a transmission.
template <typename Scale>
PairCheck reciprocity(const Material& m, const std::vector<D3>& wo, const std::vector<D3>& wi,
                      Scale scale) {
    std::vector<cl_float4> fwd = eval_pairs(m, wo, wi), back = eval_pairs(m, wi, wo);
    PairCheck r;
    for (std::size_t i = 0; i < wo.size(); ++i) {
        ++r.pairs;
        bool pos = false;
        for (int ch = 0; ch < 3; ++ch) {
            double a = fwd[i].s[ch] * scale(wo[i], wi[i]), b = back[i].s[ch] * scale(wi[i], wo[i]);
            double e = std::isfinite(a) && std::isfinite(b) ? rel_diff(a, b) : 1.0;
            pos = pos || a > 0;
            if (e > r.worst) r.worst = e, r.worst_wo = wo[i], r.worst_wi = wi[i];
            if (!(e <= 1e-4)) {
                ++r.bad;
                break;
            }
        }
        r.positive += pos;
    }
    return r;
}

double one(D3, D3) {
    return 1.0;
}

void expect_reciprocal(const std::string& name, const PairCheck& r) {
    std::printf("  %-44s %zu pairs, %zu with f > 0, worst relative %.2e\n", name.c_str(), r.pairs,
                r.positive, r.worst);
    EXPECT_EQ(r.bad, 0u) << name << ": " << r.bad << " pairs where f(wo, wi) != f(wi, wo) (worst "
                         << r.worst << " at wo (" << r.worst_wo.x << ", " << r.worst_wo.y << ", "
                         << r.worst_wo.z << "), wi (" << r.worst_wi.x << ", " << r.worst_wi.y
                         << ", " << r.worst_wi.z << "))";
    EXPECT_GE(r.positive, r.pairs / 2) << name << ": too few pairs with f > 0 to test";
}

} // namespace

// f(wo, wi) = f(wi, wo) for the opaque models at 512 pairs each.
TEST(BsdfReciprocity, OpaqueModels) {
    std::vector<D3> wo, wi;
    reflection_pairs(0.3, 1, 512, &wo, &wi);
    expect_reciprocal("diffuse", reciprocity(diffuse_material({0.8f, 0.5f, 0.3f}), wo, wi, one));
    expect_reciprocal(
        "plastic", reciprocity(plastic_material({0.5f, 0.4f, 0.3f}, {0.9f, 0.9f, 0.9f}, 1.5f, 0.0f),
                               wo, wi, one));
    for (bool b : {false, true})
        for (double a : kAlphas) {
            wo.clear(), wi.clear();
            reflection_pairs(a, 2 + std::uint64_t(a * 100), 512, &wo, &wi);
            expect_reciprocal(
                model_name("rough conductor", a, b),
                reciprocity(conductor_material({1, 1, 1}, kGoldEta, kGoldK, float(a), dist(b)), wo,
                            wi, one));
            expect_reciprocal(model_name("rough plastic", a, b),
                              reciprocity(plastic_material({0.5f, 0.4f, 0.3f}, {0.9f, 0.9f, 0.9f},
                                                           1.5f, float(a), dist(b)),
                                          wo, wi, one));
        }
}

// The rough dielectric (index 1.5): plain reciprocity for reflection pairs
// (both sides), and for transmission the generalized form f(wo, wi) /
// eta_o^2 = f(wi, wo) / eta_i^2, eta_o and eta_i the indices on wo's and wi's
// sides, at 512 pairs each.
TEST(BsdfReciprocity, RoughDielectric) {
    auto inv_eta2 = [](D3 o, D3) { return o.z > 0 ? 1.0 : 1.0 / (1.5 * 1.5); };
    for (bool b : {false, true})
        for (double a : kAlphas) {
            Material m = dielectric_material(1.5f, float(a), dist(b));
            std::vector<D3> wo, wi;
            dielectric_reflection_pairs(a, 20 + std::uint64_t(a * 100), 512, &wo, &wi);
            expect_reciprocal(model_name("rough dielectric reflection", a, b),
                              reciprocity(m, wo, wi, one));
            wo.clear(), wi.clear();
            transmission_pairs(a, 1.5, 40 + std::uint64_t(a * 100), 512, &wo, &wi);
            expect_reciprocal(model_name("rough dielectric transmission", a, b),
                              reciprocity(m, wo, wi, inv_eta2));
        }
}

// shading_local_eval and shading_local_pdf_w against the definitions
// written on the host (test/bsdf_reference.hpp) at the pairs above: f of the
// rough conductor (gold), rough dielectric (reflection and transmission,
// both sides), plastic and rough plastic; pdf_w of the rough conductor
// (visible normals: pdf_visible(wo, h) / (4 wo.h)), of the rough dielectric
// (the grid-rounded F(wo.h) times the reflection's, or 1 minus it times the
// refraction's pdf_visible(wo, h) eta_i^2 |wi.h| / (eta_o wo.h + eta_i
// wi.h)^2) and of the plastics (the coat's q and the base's cosine). All to
// a relative 1e-3 (float against double).
namespace {

struct RefCheck {
    std::size_t bad_f = 0, bad_pdf = 0, positive = 0;
    double worst_f = 0, worst_pdf = 0;
    std::size_t at_f = 0, at_pdf = 0;
};

template <typename F, typename P>
RefCheck against_reference(const Material& m, const std::vector<D3>& wo, const std::vector<D3>& wi,
                           F f_ref, P pdf_ref) {
    std::vector<cl_float4> out = eval_pairs(m, wo, wi);
    RefCheck r;
    for (std::size_t i = 0; i < wo.size(); ++i) {
        for (int ch = 0; ch < 3; ++ch) {
            double want = f_ref(wo[i], wi[i], ch);
            // f below 1e-6 of its value at the peak order is float noise.
            double e = std::fabs(want) < 1e-12 && std::fabs(out[i].s[ch]) < 1e-12
                           ? 0
                           : rel_diff(out[i].s[ch], want);
            if (e > r.worst_f) r.worst_f = e, r.at_f = i;
            if (!(e <= 1e-3)) ++r.bad_f;
            if (ch == 0 && want > 0) ++r.positive;
        }
        double want = pdf_ref(wo[i], wi[i]);
        double e = want < 1e-12 && std::fabs(out[i].s[3]) < 1e-12 ? 0 : rel_diff(out[i].s[3], want);
        if (e > r.worst_pdf) r.worst_pdf = e, r.at_pdf = i;
        if (!(e <= 1e-3)) ++r.bad_pdf;
    }
    return r;
}

void expect_reference(const std::string& name, const RefCheck& r, const std::vector<D3>& wo,
                      const std::vector<D3>& wi) {
    std::printf("  %-44s f worst %.2e, pdf worst %.2e, %zu with f > 0\n", name.c_str(), r.worst_f,
                r.worst_pdf, r.positive);
    EXPECT_EQ(r.bad_f, 0u) << name << ": f differs from the definition (worst " << r.worst_f
                           << " at wo.z " << wo[r.at_f].z << ", wi.z " << wi[r.at_f].z << ")";
    EXPECT_EQ(r.bad_pdf, 0u) << name << ": pdf_w differs from the definition (worst " << r.worst_pdf
                             << " at wo.z " << wo[r.at_pdf].z << ", wi.z " << wi[r.at_pdf].z << ")";
    EXPECT_GT(r.positive, wo.size() / 4) << name;
}

} // namespace

TEST(BsdfReference, EvalAndPdfMatchTheDefinitions) {
    const double eta[3] = {kGoldEta.x, kGoldEta.y, kGoldEta.z},
                 k[3] = {kGoldK.x, kGoldK.y, kGoldK.z};
    const double kd[3] = {0.5, 0.4, 0.3}, ks = 0.9, ior = 1.5;
    for (bool b : {false, true})
        for (double a : kAlphas) {
            std::vector<D3> wo, wi;
            reflection_pairs(a, 60 + std::uint64_t(a * 100), 512, &wo, &wi);
            expect_reference(
                model_name("rough conductor", a, b),
                against_reference(
                    conductor_material({1, 1, 1}, kGoldEta, kGoldK, float(a), dist(b)), wo, wi,
                    [&](D3 o, D3 i, int ch) {
                        D3 h = ref::unit(o + i);
                        return ref::rough_conductor_f(
                            o, i, ref::fresnel_conductor(ref::dot(o, h), eta[ch], k[ch]), a, b);
                    },
                    [&](D3 o, D3 i) {
                        if (o.z <= 0 || i.z <= 0) return 0.0;
                        D3 h = ref::unit(o + i);
                        return ref::visible_pdf(o, h, a, b) / (4 * ref::dot(o, h));
                    }),
                wo, wi);

            Material pm =
                plastic_material({0.5f, 0.4f, 0.3f}, {0.9f, 0.9f, 0.9f}, 1.5f, float(a), dist(b));
            expect_reference(model_name("rough plastic", a, b),
                             against_reference(
                                 pm, wo, wi,
                                 [&](D3 o, D3 i, int ch) {
                                     return ref::plastic_f(o, i, kd[ch], ks, ior,
                                                           reference_coat(a, b), a, b, true);
                                 },
                                 [&](D3 o, D3 i) {
                                     if (o.z <= 0 || i.z <= 0) return 0.0;
                                     double f = ref::fresnel(o.z, ior), s = pm.spec_weight;
                                     double q = grid_prob(f * s / (f * s + (1 - f) * (1 - s)));
                                     D3 h = ref::unit(o + i);
                                     return q * ref::visible_pdf(o, h, a, b) /
                                                (4 * ref::dot(o, h)) +
                                            (1 - q) * i.z / kPi;
                                 }),
                             wo, wi);

            Material dm = dielectric_material(1.5f, float(a), dist(b));
            auto dielectric_pdf = [&](D3 o, D3 i) {
                bool out = o.z > 0;
                D3 so = out ? o : D3{o.x, o.y, -o.z}, si = out ? i : D3{i.x, i.y, -i.z};
                double eo = out ? 1 : ior, ei = (i.z > 0) ? 1 : ior, rel = out ? ior : 1 / ior;
                if (o.z * i.z > 0) {
                    D3 h = ref::unit(so + si);
                    double p = grid_prob(ref::fresnel(ref::dot(so, h), rel));
                    return p * ref::visible_pdf(so, h, a, b) / (4 * ref::dot(so, h));
                }
                D3 h = ref::unit(-(eo * so + ei * si));
                if (h.z < 0) h = -h;
                double oh = ref::dot(so, h), ih = ref::dot(si, h);
                if (oh <= 0 || ih >= 0) return 0.0;
                double p = grid_prob(ref::fresnel(oh, rel)), den = eo * oh + ei * ih;
                return (1 - p) * ref::visible_pdf(so, h, a, b) * ei * ei * std::fabs(ih) /
                       (den * den);
            };
            auto dielectric_f = [&](D3 o, D3 i, int) {
                return ref::rough_dielectric_f(o, i, ior, a, b);
            };
            std::vector<D3> ro, ri, to, ti;
            dielectric_reflection_pairs(a, 80 + std::uint64_t(a * 100), 512, &ro, &ri);
            expect_reference(model_name("rough dielectric reflection", a, b),
                             against_reference(dm, ro, ri, dielectric_f, dielectric_pdf), ro, ri);
            transmission_pairs(a, ior, 90 + std::uint64_t(a * 100), 512, &to, &ti);
            expect_reference(model_name("rough dielectric transmission", a, b),
                             against_reference(dm, to, ti, dielectric_f, dielectric_pdf), to, ti);
        }
    // The smooth plastic's base and its lobe's pdf (1 - q) wi.z / pi.
    std::vector<D3> wo, wi;
    reflection_pairs(0.3, 99, 512, &wo, &wi);
    Material pm = plastic_material({0.5f, 0.4f, 0.3f}, {0.9f, 0.9f, 0.9f}, 1.5f, 0.0f);
    expect_reference("plastic",
                     against_reference(
                         pm, wo, wi,
                         [&](D3 o, D3 i, int ch) {
                             return ref::plastic_f(o, i, kd[ch], ks, ior, ref::smooth_coat(ior), 0,
                                                   false, false);
                         },
                         [&](D3 o, D3 i) {
                             double f = ref::fresnel(o.z, ior), s = pm.spec_weight;
                             double q = grid_prob(f * s / (f * s + (1 - f) * (1 - s)));
                             return (1 - q) * i.z / kPi;
                         }),
                     wo, wi);
}

// ============================================================================
// 7. The conductor's complex Fresnel term, through the smooth conductor's
// sample weight ks Fc(wo.z) (ks 1): at normal incidence
// ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2) per channel for gold-like eta
// and k; at other angles the host's complex Fresnel equations; with k = 0
// the dielectric Fresnel term (host formula, including total internal
// reflection for eta 0.8); eta 0, k 1 gives 1. Relative 1e-4.
namespace {

std::vector<double> mirror_weight(Vec3 eta, Vec3 k, double cos_o) {
    std::vector<cl_float4> w =
        draw_weights(conductor_material({1, 1, 1}, eta, k, 0.0f), ref::incident(cos_o), 5, 4);
    return {w[0].s[0], w[0].s[1], w[0].s[2]};
}

} // namespace

TEST(BsdfFresnel, ConductorAtNormalIncidence) {
    std::vector<double> w = mirror_weight(kGoldEta, kGoldK, 1.0);
    for (int ch = 0; ch < 3; ++ch) {
        double e = kGoldEta[ch], k = kGoldK[ch];
        double want = ((e - 1) * (e - 1) + k * k) / ((e + 1) * (e + 1) + k * k);
        EXPECT_NEAR(w[ch], want, 1e-4 * want) << "channel " << ch;
        EXPECT_NEAR(ref::fresnel_conductor(1.0, e, k), want, 1e-12) << "the host's formula";
    }
}

TEST(BsdfFresnel, ConductorAtOtherAngles) {
    for (double co : {0.9, 0.5, 0.2, 0.05}) {
        std::vector<double> w = mirror_weight(kGoldEta, kGoldK, co);
        for (int ch = 0; ch < 3; ++ch) {
            double want = ref::fresnel_conductor(co, kGoldEta[ch], kGoldK[ch]);
            EXPECT_NEAR(w[ch], want, 1e-4 * want) << "cos " << co << " channel " << ch;
        }
    }
}

TEST(BsdfFresnel, ConductorWithoutAbsorptionIsDielectric) {
    for (float eta : {1.5f, 0.8f})
        for (double co : {1.0, 0.9, 0.7, 0.5, 0.3, 0.1}) {
            std::vector<double> w = mirror_weight({eta, eta, eta}, {0, 0, 0}, co);
            double want = ref::fresnel(co, eta);
            EXPECT_NEAR(ref::fresnel_conductor(co, eta, 0), want, 1e-12) << "the host's formulas";
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(w[ch], want, 1e-4 * want + 1e-7) << "eta " << eta << " cos " << co;
        }
}

TEST(BsdfFresnel, PerfectMirror) {
    for (double co : {1.0, 0.7, 0.3, 0.05}) {
        std::vector<double> w = mirror_weight({0, 0, 0}, {1, 1, 1}, co);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(w[ch], 1.0, 1e-5) << "cos " << co;
    }
}
