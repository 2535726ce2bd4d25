// The splatted image of the MLT sampler against the known target with
// bounces (test/known_target.hpp) follows its per-pixel integral.
// doc/testing.md ("The chains against a known target") gives the derivations.
#include "known_target.hpp"
#include "render/mlt.hpp"
#include "stats.hpp"
#include "target_cells.h"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace smallmlt;
using namespace smallmlt::known_target;

// ---------------------------------------------------------------------------
// The splatted image, b * splats * pixels / mutations, against the target's
// per-pixel integral, pixels * sum_{pixel} g / N24^2 * V_0(side), on a 4 x 4
// film. R independent renders (own seeds: own b, burn-in and steps) give R
// values of each quantity below; with their mean m and standard deviation s,
// t = (m - truth) / (s / sqrt R) is t-distributed with R - 1 degrees of
// freedom for an unbiased render (each value is a sum of many splats: close
// to normal). Quantities: the 15 lit pixels of image(); the image mean (a
// bias shared by all pixels: the splat weights); and the 15 lit pixels of
// image() / b, against truth / b_true (where the chains went, without b's own
// noise, which is common to all pixels of one render and dominates them).
// 31 two-sided tests at 1e-3 / 31 each (Bonferroni: 1e-3 for the test; 2 L
// + 1 for L lit pixels). The
// pixel where the target is zero must get exactly nothing.
//
// With holes, the cells of 2 x 2 pixels that `holes` marks (bit c: cell c,
// two cells a row) have weight 0, as the OMC part's cells have: the chains'
// image there is exactly 0, elsewhere the per-pixel integral, and b the
// target's mean over the film with the holes left out. The large steps then
// draw their film numbers on the rest (StratumWeights), at a density b's
// sum and, with `kelemen`, Kelemen's weights must both take into account.
struct SplatCase {
    std::uint32_t proposals, threads, steps, replicas, holes;
    bool kelemen;
};

class ChainTargetSplat : public ::testing::TestWithParam<SplatCase> {};

TEST_P(ChainTargetSplat, ImageMatchesThePerPixelIntegral) {
    const SplatCase sc = GetParam();
    const int bins = 4, pixels = bins * bins, values = 2 * pixels + 1;
    const DeviceScene ds = test::layout_only_scene(target_features(), bins, bins);
    const KnownTarget tg(ds.layout);
    const std::uint32_t replicas = sc.replicas;
    // Value i < pixels: pixel i of image(); i = pixels: the image mean;
    // pixels + 1 + j: pixel j of image() / b.
    std::vector<double> sum(values, 0.0), sum2(values, 0.0), truth(values, 0.0);
    const TargetCells cells{1u, 2u}; // 2 x 2 pixels a cell
    std::vector<bool> zero_cells(4);
    for (std::uint32_t c = 0; c < 4; ++c)
        zero_cells[c] = (sc.holes >> c) & 1u;
    for (int i = 0; i < pixels; ++i) {
        const std::uint32_t x = std::uint32_t(i % bins), y = std::uint32_t(i / bins);
        truth[i] = zero_cells[target_cell(&cells, x, y)] ? 0.0 : tg.pixel(int(x), int(y), bins);
        truth[pixels] += truth[i] / pixels;
    }
    const double b_true = truth[pixels]; // the mean of I over the film
    for (int i = 0; i < pixels; ++i)
        truth[pixels + 1 + i] = truth[i] / b_true;
    if (!sc.holes) {
        EXPECT_NEAR(b_true, tg.Z, 1e-12 * tg.Z);
    }
    auto t0 = std::chrono::steady_clock::now();
    double acceptance = 0, b_error = 0;
    for (std::uint32_t r = 0; r < replicas; ++r) {
        MltOptions opt = test::plain_mlt();
        MltTestHooks hooks;
        opt.proposals = sc.proposals;
        opt.threads = sc.threads;
        opt.large_step = sc.kelemen ? 0.3f : 0.05f;
        opt.kelemen = sc.kelemen;
        opt.seed = std::uint64_t(env_or("CT_SEED", 11)) * 7919 + 100 * sc.proposals + r;
        opt.burn_in_iters = 32;
        hooks.evaluator = "test/cl/eval_target.cl";
        if (sc.holes) {
            hooks.cells = cells;
            hooks.zero_cells = zero_cells;
        }
        MltRenderer mlt(test::cl(), ds, opt, hooks);
        mlt.prepare();
        mlt.step(sc.steps);
        MltStats ms = mlt.stats();
        acceptance += double(ms.accepted) / double(ms.mutations) / replicas;
        b_error += mlt.b_rel_error() / replicas;
        Image img = mlt.image();
        std::vector<double> v(values, 0.0);
        for (int i = 0; i < pixels; ++i) {
            v[i] = img.rgb[3 * i];
            v[pixels] += v[i] / pixels;
            v[pixels + 1 + i] = v[i] / mlt.b();
        }
        for (int i = 0; i < values; ++i) {
            sum[i] += v[i];
            sum2[i] += v[i] * v[i];
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    int lit = 0;
    for (int i = 0; i < pixels; ++i)
        lit += truth[i] > 0;
    const int tests = 2 * lit + 1;
    const double alpha = 1e-3 / tests, nu = replicas - 1.0;
    const double t_limit = test::student_two_sided_critical(alpha, nu);
    std::printf(
        "K %u, holes %x%s: %u replicas, %.1f s, acceptance %.1f%%, b +-%.2f%% a render; |t| "
        "limit %.2f\n",
        sc.proposals, sc.holes, sc.kelemen ? ", Kelemen's weights" : "", replicas, seconds,
        100 * acceptance, 100 * b_error, t_limit);
    const bool diag = env_or("CT_DIAG", 0) > 0;
    double worst[3] = {0, 0, 0};
    int worst_at[3] = {-1, -1, -1};
    for (int i = 0; i < values; ++i) {
        const int group = i < pixels ? 0 : i == pixels ? 1 : 2;
        const std::string what = group == 0   ? "pixel " + std::to_string(i)
                                 : group == 1 ? std::string("image mean")
                                              : "pixel / b " + std::to_string(i - pixels - 1);
        double mean = sum[i] / replicas;
        if (truth[i] == 0) {
            EXPECT_EQ(sum[i], 0.0) << what << ": splats where the target is zero";
            continue;
        }
        double var = (sum2[i] - replicas * mean * mean) / (replicas - 1);
        double se = std::sqrt(std::max(var, 0.0) / replicas);
        ASSERT_GT(se, 0.0) << what;
        double t = (mean - truth[i]) / se;
        if (std::fabs(t) > std::fabs(worst[group])) {
            worst[group] = t;
            worst_at[group] = group == 2 ? i - pixels - 1 : i;
        }
        if (diag) std::printf("  t %s %.3f\n", what.c_str(), t);
        if (group == 1)
            std::printf("  image mean %.5f, truth %.5f (%+.2f%%, se %.2f%%), t %.2f\n", mean,
                        truth[i], 100 * (mean / truth[i] - 1), 100 * se / truth[i], t);
        EXPECT_LT(std::fabs(t), t_limit)
            << what << ": mean " << mean << ", truth " << truth[i] << ", t " << t;
    }
    std::printf("  worst t: pixels %.2f (at %d), pixels / b %.2f (at %d)\n", worst[0], worst_at[0],
                worst[2], worst_at[2]);
}

INSTANTIATE_TEST_SUITE_P(Proposals, ChainTargetSplat,
                         ::testing::Values(SplatCase{1, 2048, 150, 16, 0u, false},
                                           SplatCase{4, 2048, 150, 16, 0u, false},
                                           SplatCase{1, 2048, 150, 16, 0b1110u, false},
                                           SplatCase{1, 2048, 150, 16, 0b1110u, true}));
