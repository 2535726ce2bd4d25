// The known target with bounces of test/cl/eval_target.cl, on a layout with
// two 24-bit and two 16-bit slots a bounce, depth 4: its closed-form
// marginals and per-pixel integrals (KnownTarget), for the chain tests of
// test_chain_target.cpp and test_chain_target_splat.cpp. doc/testing.md
// ("The chains against a known target") gives the derivations.
#pragma once
#include "scene/sample_layout.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace smallmlt::known_target {

constexpr const char* kProbeFile = "test/cl/probe_mlt.cl";

// Diffuse and dielectric, no light, depth 4: each bounce has BSDF_U, BSDF_V
// (24 bits), BSDF_CHOICE and RR (16 bits), 80 bits; slots straddle words.
constexpr int kDepth = 4;
inline SceneFeatures target_features() {
    SceneFeatures f;
    f.with(MAT_DIFFUSE).with(MAT_DIELECTRIC);
    f.depth = kDepth;
    return f;
}

// ---------------------------------------------------------------------------
// Exact sums over a slot's grid {i / n : i = 0 .. n - 1}.

// sum_{i = i0}^{i1 - 1} (alpha + beta i / n): exact in double for n <= 2^24.
inline double lin_sum(double i0, double i1, double n, double alpha, double beta) {
    if (i1 <= i0) return 0.0;
    double count = i1 - i0;
    return count * alpha + beta * (i0 + i1 - 1.0) * count / (2.0 * n);
}

// sum_{j = j0}^{j1 - 1} sin^2(2 pi j / n) = count / 2 - (1/2) sum cos(w j),
// w = 4 pi / n, with the Dirichlet sum
// sum_{j0}^{j1-1} cos(w j) = sin(count w / 2) / sin(w / 2) cos(w (j0 + j1 - 1) / 2).
inline double sin2_sum(double j0, double j1, double n) {
    double count = j1 - j0, w = 4.0 * M_PI / n;
    double cos_sum = std::sin(count * w / 2) / std::sin(w / 2) * std::cos(w * (j0 + j1 - 1) / 2);
    return count / 2 - cos_sum / 2;
}

// The target of test/cl/eval_target.cl on the layout of target_features(), and
// its marginals under pi(u) = F(u) / sum F on the grid (film numbers on the
// 2^-24 grid, each bounce slot on its own). All weights are "per unit
// volume": sums over grid points divided by the number of grid points.
// doc/testing.md derives each of them.
struct KnownTarget {
    static constexpr double kN24 = 16777216.0, kN16 = 65536.0;
    static constexpr double kQ[2] = {0.5, 0.75}; // continuation phase threshold, left / right

    SampleLayout layout;
    double H = 0;                      // mean of h(a)
    double E = 0;                      // mean over a bounce's numbers of all factors but p(c)
    double p_lt[2] = {}, p_ge[2] = {}; // mean of p(c) 1[phase < q] and p(c) 1[phase >= q]
    double V[kDepth][2] = {};          // weight of bounces k.. given bounce k is live
    double W[kDepth + 1][2] = {};      // weight of "exactly l live bounces", l = 1..D
    double G[2] = {};                  // weight of the film's left / right half
    double Z = 0;                      // sum over the grid of F / grid size = b

    explicit KnownTarget(const SampleLayout& l) : layout(l) {
        H = h_stripes(0, 64);
        E = H;
        for (int s = 0; s < kSlotCount; ++s) {
            if (!l.has(Slot(s)) || s == kBsdfU || s == kBsdfChoice) continue;
            double n = std::ldexp(1.0, l.bits[s]);
            E *= lin_sum(0, n, n, 0.75, 0.5) / n; // 3/4 + v/2
        }
        for (int side = 0; side < 2; ++side) {
            for (int ph = 0; ph < 4; ++ph)
                (below(ph, side) ? p_lt : p_ge)[side] += p_phase(0, 32, ph);
            V[kDepth - 1][side] = E * (p_lt[side] + p_ge[side]);
            for (int k = kDepth - 2; k >= 0; --k)
                V[k][side] = E * (p_ge[side] + p_lt[side] * V[k + 1][side]);
            for (int len = 1; len <= kDepth; ++len)
                W[len][side] = std::pow(E, len) * std::pow(p_lt[side], len - 1) *
                               (len < kDepth ? p_ge[side] : p_lt[side] + p_ge[side]);
        }
        for (int bx = 0; bx < 8; ++bx)
            G[bx >= 4] += film_column(bx, 8);
        Z = G[0] * V[0][0] + G[1] * V[0][1];
    }

    // Stripe factor s(v, n) on stripe m: 5/4 odd, 3/4 even.
    static double s_factor(int m) { return m % 2 ? 1.25 : 0.75; }
    // sum of (1 + 3x) s(x, 64) over the x grid points of stripes m0 .. m1 - 1
    // (of 64), / N24; parity -1: all stripes, 0 / 1: even / odd ones only.
    static double gx_stripes(int m0, int m1, int parity = -1) {
        double sum = 0, w = kN24 / 64;
        for (int m = m0; m < std::min(m1, 60); ++m) // 0 from 15/16 = stripe 60 on
            if (parity < 0 || m % 2 == parity)
                sum += s_factor(m) * lin_sum(m * w, (m + 1) * w, kN24, 1.0, 3.0);
        return sum / kN24;
    }
    // Weight of film cell: x bin bx of bins_x (x stripes of one parity, or
    // all), y bin by of bins_y; both counts multiples of 4 and at most 64,
    // so no cell straddles x, y = 1/4 or a stripe.
    static double film(int bx, int bins_x, int by, int bins_y, int parity = -1) {
        if ((bx + 1) * 4 <= bins_x && (by + 1) * 4 <= bins_y) return 0.0; // g = 0 there
        int per = 64 / bins_x;
        double w = kN24 / bins_y;
        double gy = (w + sin2_sum(by * w, (by + 1) * w, kN24)) / kN24;
        return gx_stripes(bx * per, (bx + 1) * per, parity) * gy;
    }
    static double film_column(int bx, int bins_x) {
        double sum = 0;
        for (int by = 0; by < 4; ++by)
            sum += film(bx, bins_x, by, 4);
        return sum;
    }
    static int side_of_column(int bx, int bins) { return 2 * bx >= bins; }
    // h summed over stripes m0 .. m1 - 1 (of 64) of the 24-bit grid, / N24;
    // parity -1: all of them, 0 or 1: the even or the odd ones only.
    static double h_stripes(int m0, int m1, int parity = -1) {
        double sum = 0, w = kN24 / 64;
        for (int m = std::max(m0, 8); m < m1; ++m) // h = 0 below 1/8 = stripe 8
            if (parity < 0 || m % 2 == parity)
                sum += (m % 2 ? 1.5 : 0.5) * lin_sum(m * w, (m + 1) * w, kN24, 0.5, 1.0);
        return sum / kN24;
    }
    // Quarter `quarter` of c's phase stripes (of 32) is the stripe
    // 4 t + quarter of 128: below q or not.
    static bool below(int quarter, int side) { return (quarter + 1) / 4.0 <= kQ[side]; }
    // p(c) = (3/4 + c/2) s(c, 128) summed over quarter `quarter` (0..3) of
    // c's phase stripes t0 .. t1 - 1 (of 32), / N16.
    static double p_phase(int t0, int t1, int quarter) {
        double sum = 0, w = kN16 / 128;
        for (int t = t0; t < t1; ++t) {
            int n = 4 * t + quarter;
            if (n < 120) // 0 from 15/16 = stripe 120 on
                sum += s_factor(n) * lin_sum(n * w, (n + 1) * w, kN16, 0.75, 0.5);
        }
        return sum / kN16;
    }
    // Weight of "c_0 in quarter `quarter` of phase stripes t0 .. t1 - 1" on
    // one side: its p times the bounce's other factors times what follows.
    double c0_weight(int t0, int t1, int quarter, int side) const {
        return p_phase(t0, t1, quarter) * E * (below(quarter, side) ? V[1][side] : 1.0);
    }
    // Pixel value of the image (bins x bins pixels): pixels * integral of F
    // over the pixel.
    double pixel(int bx, int by, int bins) const {
        return double(bins) * bins * film(bx, bins, by, bins) * V[0][side_of_column(bx, bins)];
    }
};

// For calibration runs: CT_SEED=n replaces the fixed base seed (11), and
// CT_DIAG=1 prints lag correlations and the summary (chain test) or every t
// (splat test).
inline double env_or(const char* name, double fallback) {
    const char* v = std::getenv(name);
    return v ? std::atof(v) : fallback;
}

} // namespace smallmlt::known_target
