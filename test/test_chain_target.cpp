// The MLT sampler against a known target with bounces (test/known_target.hpp):
// the chains' states follow the target's closed-form marginals, live and dead
// bounces included. The splatted image: test_chain_target_splat.cpp.
// doc/testing.md ("The chains against a known target") gives the derivations.
#include "known_target.hpp"
#include "render/mlt.hpp"
#include "scene/sample_layout.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace smallmlt;
using namespace smallmlt::known_target;

namespace {

// ---------------------------------------------------------------------------
// Hotelling's T^2 over chains. Chain c contributes the vector n_c of its
// counts per cell over S snapshots. Chains are independent and identically
// distributed (own streams; their starts are independent up to the burn-in
// picks, see below), so however correlated a chain's snapshots are, the mean
// of n_c over C chains is asymptotically normal with covariance Sigma / C,
// and with Sigma estimated from the chains,
//   T^2 = C (mean - S p)^T Sigma^-1 (mean - S p),  (C - q) T^2 / (q (C - 1)) ~ F(q, C - q)
// for q used cells. Cells of zero probability are left out (they must stay
// empty: checked apart), and so is the last used cell (the counts of a chain
// sum to S, so Sigma is singular on all cells).
struct CellStat {
    std::string name;
    int cells = 0;
    std::vector<double> p;             // target probability of each cell
    std::vector<std::uint16_t> counts; // chains x cells
};

struct Verdict {
    double t2 = 0, f = 0, p_value = 1, limit = 0;
    int q = 0;
    std::uint64_t in_zero_cells = 0;
};

Verdict hotelling(const CellStat& st, std::uint32_t chains, std::uint32_t snapshots, double alpha) {
    Verdict v;
    std::vector<int> used;
    for (int j = 0; j < st.cells; ++j)
        if (st.p[j] > 0)
            used.push_back(j);
        else
            for (std::uint32_t c = 0; c < chains; ++c)
                v.in_zero_cells += st.counts[std::size_t(c) * st.cells + j];
    used.pop_back();
    const int q = int(used.size());
    const double n = chains;
    std::vector<double> mean(q, 0.0), cov(std::size_t(q) * q, 0.0), x(q);
    for (std::uint32_t c = 0; c < chains; ++c)
        for (int a = 0; a < q; ++a)
            mean[a] += st.counts[std::size_t(c) * st.cells + used[a]] / n;
    for (std::uint32_t c = 0; c < chains; ++c) {
        for (int a = 0; a < q; ++a)
            x[a] = st.counts[std::size_t(c) * st.cells + used[a]] - mean[a];
        for (int a = 0; a < q; ++a)
            for (int b = 0; b <= a; ++b)
                cov[std::size_t(a) * q + b] += x[a] * x[b] / (n - 1);
    }
    // Cholesky: cov = L L^T, then T^2 = n |L^-1 d|^2.
    std::vector<double> d(q);
    for (int a = 0; a < q; ++a)
        d[a] = mean[a] - snapshots * st.p[used[a]];
    bool ok = true;
    for (int a = 0; a < q && ok; ++a) {
        for (int b = 0; b <= a; ++b) {
            double s = cov[std::size_t(a) * q + b];
            for (int k = 0; k < b; ++k)
                s -= cov[std::size_t(a) * q + k] * cov[std::size_t(b) * q + k];
            if (a == b) {
                if (!(s > 1e-12 * (mean[a] + 1e-300))) ok = false; // a cell that never varies
                cov[std::size_t(a) * q + a] = std::sqrt(std::max(s, 1e-300));
            } else {
                cov[std::size_t(a) * q + b] = s / cov[std::size_t(b) * q + b];
            }
        }
    }
    double t2 = 0;
    if (ok) {
        for (int a = 0; a < q; ++a) {
            double s = d[a];
            for (int k = 0; k < a; ++k)
                s -= cov[std::size_t(a) * q + k] * x[k];
            x[a] = s / cov[std::size_t(a) * q + a];
            t2 += x[a] * x[a];
        }
        t2 *= n;
    } else {
        t2 = INFINITY;
    }
    v.q = q;
    v.t2 = t2;
    v.f = t2 * (n - q) / (q * (n - 1));
    v.p_value = std::isfinite(v.f) ? test::f_upper_tail(v.f, q, n - q) : 0.0;
    double f_limit = test::f_critical(alpha, q, n - q);
    v.limit = f_limit * q * (n - 1) / (n - q);
    return v;
}

} // namespace

// ---------------------------------------------------------------------------
// The closed forms against brute-force sums over every grid point, with the
// per-number functions written as test/cl/eval_target.cl computes them (float).

float host_stripes(float v, float n, float odd, float even) {
    return (std::uint32_t(v * n) & 1u) ? odd : even;
}

float host_h(float a) { // SLOT_BSDF_U
    return a < 0.125f ? 0.0f : (0.5f + a) * host_stripes(a, 64.0f, 1.5f, 0.5f);
}

float host_p(float c) { // the continuation slot's factor
    return c < 0.9375f ? (0.75f + 0.5f * c) * host_stripes(c, 128.0f, 1.25f, 0.75f) : 0.0f;
}

float host_sx(float x) { // the film's stripes
    return x < 0.9375f ? host_stripes(x, 64.0f, 1.25f, 0.75f) : 0.0f;
}

bool host_go_on(float c, float q) { // and its phase
    return c * 32.0f - std::floor(c * 32.0f) < q;
}

TEST(ChainTargetMath, ClosedFormsEqualGridSums) {
    const KnownTarget tg(make_layout(target_features()));
    // h over the 24-bit grid, per (16 bins x parity) cell of a_0.
    std::vector<double> h_cells(32, 0.0);
    for (std::uint32_t i = 0; i < (1u << 24); ++i)
        h_cells[(i >> 20) * 2 + ((i >> 18) & 1u)] += host_h(float(i) / 16777216.0f);
    for (int j = 0; j < 32; ++j)
        EXPECT_NEAR(h_cells[j] / KnownTarget::kN24,
                    KnownTarget::h_stripes(4 * (j / 2), 4 * (j / 2) + 4, j % 2), 1e-12)
            << "a_0 cell " << j;
    // p(c) and the continuation over the 16-bit grid, per side and quarter.
    for (int side = 0; side < 2; ++side) {
        double lt = 0, ge = 0, quarter[4] = {};
        for (std::uint32_t j = 0; j < (1u << 16); ++j) {
            float c = float(j) / 65536.0f;
            double p = host_p(c);
            (host_go_on(c, float(KnownTarget::kQ[side])) ? lt : ge) += p / KnownTarget::kN16;
            quarter[(j >> 9) & 3u] += p / KnownTarget::kN16;
        }
        EXPECT_NEAR(lt, tg.p_lt[side], 1e-12) << "side " << side;
        EXPECT_NEAR(ge, tg.p_ge[side], 1e-12) << "side " << side;
        for (int ph = 0; ph < 4; ++ph)
            EXPECT_NEAR(quarter[ph], KnownTarget::p_phase(0, 32, ph), 1e-12) << "quarter " << ph;
    }
    // g s(x, 64) over the film grid, per axis (a product off the zero corner),
    // x per (bin of 4, stripe parity), y per bin of 8.
    std::vector<double> gx(8, 0.0), gy(8, 0.0);
    for (std::uint32_t i = 0; i < (1u << 24); ++i) {
        double u = i / KnownTarget::kN24, s = std::sin(2 * M_PI * u);
        gx[(i >> 22) * 2 + ((i >> 18) & 1u)] += (1 + 3 * u) * host_sx(float(u)) / KnownTarget::kN24;
        gy[i >> 21] += (1 + s * s) / KnownTarget::kN24;
    }
    for (int bx = 0; bx < 4; ++bx)
        for (int by = 0; by < 8; ++by)
            for (int par = 0; par < 2; ++par)
                EXPECT_NEAR(KnownTarget::film(bx, 4, by, 8, par),
                            bx < 1 && by < 2 ? 0.0 : gx[bx * 2 + par] * gy[by], 1e-12)
                    << "film cell " << bx << ", " << by << ", parity " << par;
    // The lengths' weights add up to the whole: sum_l W_l = V_0 per side.
    for (int side = 0; side < 2; ++side) {
        double w = 0;
        for (int len = 1; len <= kDepth; ++len)
            w += tg.W[len][side];
        EXPECT_NEAR(w, tg.V[0][side], 1e-14) << "side " << side;
    }
    std::printf("H %.6f, E %.6f, P(go on) left %.6f right %.6f, V_0 %.6f %.6f, b = %.6f\n", tg.H,
                tg.E, tg.p_lt[0] / (tg.p_lt[0] + tg.p_ge[0]),
                tg.p_lt[1] / (tg.p_lt[1] + tg.p_ge[1]), tg.V[0][0], tg.V[0][1], tg.Z);
}

// The evaluator reports as live exactly the bounces whose numbers it read:
// for fixed keys (small steps on even chains, large on odd ones, from chain
// starts with every live count), the lazily evaluated proposal, the same
// proposal materialized number by number and replayed, and the chain's state
// after committing it (replayed with its live count, so any number it did not
// store would be drawn afresh) give the same F and the same live count, bit
// for bit (probe_lazy_eager).
TEST(ChainTargetLazy, CommitStoresExactlyTheNumbersRead) {
    const DeviceScene ds = test::layout_only_scene(target_features(), 8, 8);
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 4096;
    opt.seed = 3;
    hooks.evaluator = "test/cl/eval_target.cl";
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    mlt.prepare();
    mlt.step(20); // chains of every length, with stale numbers behind them
    std::vector<cl_float4> f = test::lazy_eager_committed(mlt, ds, opt.threads);
    int lengths[kDepth + 1] = {}, lit = 0;
    for (std::uint32_t c = 0; c < opt.threads; ++c) {
        const cl_float4 &lazy = f[3 * c], &eager_f = f[3 * c + 1], &stored = f[3 * c + 2];
        EXPECT_EQ(std::memcmp(lazy.s, eager_f.s, 16), 0) << "chain " << c;
        EXPECT_EQ(std::memcmp(lazy.s, stored.s, 16), 0) << "chain " << c;
        cl_uint len;
        std::memcpy(&len, &lazy.s[3], 4);
        ASSERT_TRUE(len >= 1 && len <= cl_uint(kDepth)) << "chain " << c;
        ++lengths[len];
        lit += lazy.s[0] > 0;
    }
    for (int len = 1; len <= kDepth; ++len)
        EXPECT_GT(lengths[len], int(opt.threads) / 50)
            << "too few proposals with " << len << " bounces";
    EXPECT_GT(lit, int(opt.threads) / 4);
}

// ---------------------------------------------------------------------------
// Chain states. C chains (K proposals each, threads = C K) start at OMC
// burn-in picks, run `burn` steps, then S snapshots `every` steps apart read
// the packed states (probe_chain_numbers: film numbers, a_0 = BSDF_U and
// c_0 = BSDF_CHOICE of bounce 0, a_1 = BSDF_U of bounce 1, and the live bounces
// L from the ChainValue). Six statistics, each a Hotelling T^2 over chains
// against the closed-form marginal; significance 1e-3 for the test, 1e-3 / 6
// per statistic (Bonferroni), with fixed seeds.
//
// Sizes: a chain's states decorrelate in about 75 steps whatever K (lag-10
// correlation 0.88 for x, a_0 and c_0, 0.15 for L: split transitions move
// to one of the K proposals, large ones no more often than at K = 1), so
// every K runs a similar number of steps; K = 8 and 16 with fewer chains
// (each step costs K proposals). The starts are burn-in picks, close to the
// target already; two chains that start on the same pick (drawn with
// replacement: a few percent of them) have decorrelated after the 150 burn
// steps. The Hotelling statistic needs no thinning: the covariance of a
// chain's counts comes from the chains themselves.
struct ChainCase {
    std::uint32_t proposals, chains, burn, every, snapshots;
};

class ChainTarget : public ::testing::TestWithParam<ChainCase> {};

TEST_P(ChainTarget, StatesFollowTheClosedFormMarginals) {
    const ChainCase cc = GetParam();
    const DeviceScene ds = test::layout_only_scene(target_features(), 8, 8);
    const SampleLayout& l = ds.layout;
    const KnownTarget tg(l);
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.proposals = cc.proposals;
    opt.threads = cc.chains * cc.proposals;
    opt.large_step = 0.05f;
    opt.seed = std::uint64_t(env_or("CT_SEED", 11)) + 1000 * cc.proposals;
    opt.burn_in_iters = 32;
    hooks.evaluator = "test/cl/eval_target.cl";
    hooks.extra_files = {kProbeFile};
    const std::uint32_t snapshots = cc.snapshots, burn = cc.burn, every = cc.every;

    auto t0 = std::chrono::steady_clock::now();
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    mlt.prepare();
    const std::uint32_t chains = mlt.chains();

    // Numbers to read: film 0, 1; bounce 0's BSDF_U and BSDF_CHOICE; bounce 1's BSDF_U.
    auto dim = [&](int bounce, Slot s) {
        return cl_uint(kCameraDims + bounce * l.bounce_dims + l.index[s]);
    };
    std::vector<cl_uint> dims = {0, 1, dim(0, kBsdfU), dim(0, kBsdfChoice), dim(1, kBsdfU)};
    const cl_uint n = cl_uint(dims.size());
    ClBuffer dims_buf(test::cl(), CL_MEM_READ_ONLY, dims.size() * 4, dims.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, std::size_t(chains) * (n + 1) * 4);
    ClKernel probe(MltInspect::program(mlt), "probe_chain_numbers");
    std::vector<cl_uint> row(std::size_t(chains) * (n + 1));

    // The statistics and their cells (doc/testing.md gives the formulas).
    std::vector<CellStat> st(6);
    st[0].name = "film: 4 x-bins x stripe parity x 8 y-bins";
    st[0].cells = 64;
    for (int j = 0; j < 64; ++j) {
        int par = j % 2, bx = (j / 2) % 4, by = j / 8;
        st[0].p.push_back(KnownTarget::film(bx, 4, by, 8, par) * tg.V[0][bx >= 2] / tg.Z);
    }
    st[1].name = "a_0 (24-bit): 16 bins x stripe parity";
    st[1].cells = 32;
    for (int j = 0; j < 32; ++j)
        st[1].p.push_back(KnownTarget::h_stripes(4 * (j / 2), 4 * (j / 2) + 4, j % 2) / tg.H);
    st[2].name = "c_0 (16-bit): 8 bins x phase quarter";
    st[2].cells = 32;
    for (int j = 0; j < 32; ++j) {
        int t0 = 4 * (j / 4), ph = j % 4;
        st[2].p.push_back((tg.G[0] * tg.c0_weight(t0, t0 + 4, ph, 0) +
                           tg.G[1] * tg.c0_weight(t0, t0 + 4, ph, 1)) /
                          tg.Z);
    }
    st[3].name = "live bounces L";
    st[3].cells = kDepth;
    for (int len = 1; len <= kDepth; ++len)
        st[3].p.push_back((tg.G[0] * tg.W[len][0] + tg.G[1] * tg.W[len][1]) / tg.Z);
    st[4].name = "film column x c_0 phase quarter";
    st[4].cells = 32;
    for (int j = 0; j < 32; ++j) {
        int bx = j % 8, ph = j / 8, side = KnownTarget::side_of_column(bx, 8);
        st[4].p.push_back(KnownTarget::film_column(bx, 8) * tg.c0_weight(0, 32, ph, side) / tg.Z);
    }
    st[5].name = "L x a_1 (24-bit): 8 bins x parity";
    st[5].cells = 1 + (kDepth - 1) * 16;
    st[5].p.push_back((tg.G[0] * tg.W[1][0] + tg.G[1] * tg.W[1][1]) / tg.Z);
    for (int len = 2; len <= kDepth; ++len)
        for (int j = 0; j < 16; ++j)
            st[5].p.push_back((tg.G[0] * tg.W[len][0] + tg.G[1] * tg.W[len][1]) / tg.Z *
                              KnownTarget::h_stripes(8 * (j / 2), 8 * (j / 2) + 8, j % 2) / tg.H);
    for (auto& s : st) {
        double sum = 0;
        for (double p : s.p)
            sum += p;
        ASSERT_NEAR(sum, 1.0, 1e-12) << s.name;
        s.counts.assign(std::size_t(chains) * s.cells, 0);
    }

    mlt.step(burn);
    std::uint64_t at_zero = 0;
    std::vector<cl_uint> prev;
    const bool diag = env_or("CT_DIAG", 0) > 0;
    // Lag correlations of (x, a_0, c_0, L) between consecutive snapshots.
    double lag[4][5] = {}; // sums: a, b, a^2, b^2, ab
    for (std::uint32_t snap = 0; snap < snapshots; ++snap) {
        if (snap) mlt.step(every);
        probe.set_args(MltInspect::state(mlt), MltInspect::values(mlt), cl_uint(chains), dims_buf,
                       n, out);
        probe.run(test::cl(), chains);
        out.read(test::cl(), row.data());
        if (diag && snap) {
            const int col[4] = {0, 2, 3, 5};
            for (std::uint32_t c = 0; c < chains; ++c)
                for (int v = 0; v < 4; ++v) {
                    double a = prev[std::size_t(c) * (n + 1) + col[v]],
                           b = row[std::size_t(c) * (n + 1) + col[v]];
                    lag[v][0] += a;
                    lag[v][1] += b;
                    lag[v][2] += a * a;
                    lag[v][3] += b * b;
                    lag[v][4] += a * b;
                }
        }
        if (diag) prev = row;
        for (std::uint32_t c = 0; c < chains; ++c) {
            const cl_uint* r = &row[std::size_t(c) * (n + 1)];
            cl_uint x = r[0], y = r[1], a0 = r[2], c0 = r[3], a1 = r[4], len = r[5];
            ASSERT_TRUE(len >= 1 && len <= cl_uint(kDepth)) << "chain " << c << " L " << len;
            // Where F = 0: the film's corner and band, a < 1/8, c >= 15/16.
            at_zero += (x < (1u << 22) && y < (1u << 22)) || x >= (15u << 20) || a0 < (1u << 21) ||
                       c0 >= (15u << 12) || (len >= 2 && a1 < (1u << 21));
            std::size_t at;
            at = std::size_t(c) * st[0].cells + ((y >> 21) * 4 + (x >> 22)) * 2 + ((x >> 18) & 1u);
            ++st[0].counts[at];
            cl_uint ma0 = a0 >> 18, ma1 = a1 >> 18, tc0 = c0 >> 11, qc0 = (c0 >> 9) & 3u;
            ++st[1].counts[std::size_t(c) * st[1].cells + (ma0 >> 2) * 2 + (ma0 & 1u)];
            ++st[2].counts[std::size_t(c) * st[2].cells + (tc0 >> 2) * 4 + qc0];
            ++st[3].counts[std::size_t(c) * st[3].cells + len - 1];
            ++st[4].counts[std::size_t(c) * st[4].cells + qc0 * 8 + (x >> 21)];
            at = len == 1 ? 0 : 1 + (len - 2) * 16 + (ma1 >> 3) * 2 + (ma1 & 1u);
            ++st[5].counts[std::size_t(c) * st[5].cells + at];
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    MltStats ms = mlt.stats();
    std::printf("K %u: %u chains, %u + %u x %u steps, %.1f s, acceptance %.1f%%\n", cc.proposals,
                chains, burn, snapshots - 1, every, seconds,
                100.0 * double(ms.accepted) / double(ms.mutations));

    if (diag) {
        double m = double(chains) * (snapshots - 1);
        const char* nm[4] = {"x", "a_0", "c_0", "L"};
        for (int v = 0; v < 4; ++v) {
            double ma = lag[v][0] / m, mb = lag[v][1] / m;
            double r = (lag[v][4] / m - ma * mb) /
                       std::sqrt((lag[v][2] / m - ma * ma) * (lag[v][3] / m - mb * mb));
            std::printf("  lag-%u correlation of %s: %.3f\n", every, nm[v], r);
        }
        std::printf("  %s\n", mlt.summary(0).c_str());
    }
    EXPECT_EQ(at_zero, 0u) << "chain states where the target is zero";
    const double alpha = 1e-3 / st.size();
    for (const auto& s : st) {
        Verdict v = hotelling(s, chains, snapshots, alpha);
        std::printf("  %-36s T2 %9.1f (q %2d, limit %6.1f)  p %.3g\n", s.name.c_str(), v.t2, v.q,
                    v.limit, v.p_value);
        EXPECT_EQ(v.in_zero_cells, 0u) << s.name << ": states where the target is zero";
        EXPECT_GT(v.p_value, alpha) << s.name << ": T2 " << v.t2 << " over " << v.limit;
    }
}

INSTANTIATE_TEST_SUITE_P(Proposals, ChainTarget,
                         ::testing::Values(ChainCase{1, 4096, 150, 10, 70},
                                           ChainCase{2, 2048, 150, 10, 60},
                                           ChainCase{4, 2048, 150, 10, 50},
                                           ChainCase{8, 1024, 150, 10, 60},
                                           ChainCase{16, 1024, 150, 10, 50}));
