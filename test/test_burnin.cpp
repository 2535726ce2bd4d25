// Burn-in by OMC: chains start on the paths their picks found and where the
// light is, which removes most of the startup bias, and the burn-in's
// per-pixel variance is the pixels' sample variance.
// The picks themselves: test_start_picks.cpp.
#include "image/image_metrics.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

using namespace smallmlt;

// Every chain starts on the path its pick found lit: mlt_init regenerates,
// from the pick's round and index, the sample the draw chose (1000 chains
// over 7 rounds), in the pixel that burn_in_film_sample names for round x
// threads + index.
TEST(BurnIn, ChainsStartOnThePathsTheirPicksFound) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 32, 32));
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 1000;
    opt.burn_in_iters = 7;
    hooks.extra_files = {"test/cl/probe_mlt.cl"};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    mlt.prepare();
    std::vector<ChainValue> v(opt.threads);
    MltInspect::values(mlt).read(test::cl(), v.data());
    int dark = 0;
    for (const ChainValue& c : v)
        dark += !(c.rgb[0] + c.rgb[1] + c.rgb[2] > 0);
    EXPECT_EQ(dark, 0) << "chains started on unlit paths";
    std::vector<cl_uint2> picks(opt.threads);
    MltInspect::picks(mlt).read(test::cl(), picks.data());
    std::vector<cl_uint> pixel = test::chain_pixels(mlt, ds.frame);
    std::set<cl_uint> rounds;
    for (std::uint32_t c = 0; c < opt.threads; ++c) {
        std::uint64_t g = std::uint64_t(picks[c].s[0]) * opt.threads + picks[c].s[1];
        ASSERT_EQ(pixel[c], burn_in_film_sample(mlt.burn_in_film(), 32 * 32, g).first)
            << "chain " << c << ", pick (" << picks[c].s[0] << ", " << picks[c].s[1] << ")";
        rounds.insert(picks[c].s[0]);
    }
    EXPECT_EQ(rounds.size(), 7u) << "the picks come from every round";
}

// The paper's Figure 1 in a test: early in a render (2 of a normal render's
// 64 steps), the error against a path-traced reference with OMC burn-in (at
// the default large-step probability) is at least 3 times lower than without
// burn-in at large-step 0.5, same seed and chains.
TEST(BurnIn, RemovesMostOfTheStartupBias) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 32, 32));
    Image ref = test::render_pt(ds, 31, 2048);
    double err[2];
    for (int burn = 0; burn < 2; ++burn) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 4096;
        opt.seed = 3;
        opt.burn_in = burn == 1;
        opt.large_step = burn ? 0.1f : 0.5f;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(2);
        err[burn] = image_mse(mlt.image(), ref);
    }
    std::printf("MSE after 2 steps: without burn-in %.4g, with %.4g (ratio %.1f)\n", err[0], err[1],
                err[0] / err[1]);
    EXPECT_GT(err[0], 3 * err[1]);
}

namespace {

// One burn-in path as mlt_luminance writes it: grey OMC part o and MLT part
// m (RGB all equal, so the luminance is the value) landing at `pixel`.
void add_path(std::vector<float>& out, std::uint32_t pixel, float o, float m) {
    float bits;
    std::memcpy(&bits, &pixel, sizeof bits);
    out.insert(out.end(), {o, o, o, bits, m, m, m, 1.0f});
}

} // namespace

// V of split.hpp from the burn-in: P times the mean sample variance of the
// pixels with two paths or more. Pixel 0: OMC parts 1, 3 (variance 2);
// pixel 1: 5, 5, 8 (variance 3); pixel 2: one path (left out); pixel 3:
// none. V = 4 x (2 + 3) / 2 = 10. The MLT parts are all 2: V = 0. With no
// pixel of two paths: the second moment, P x mean f^2. The means per path:
// 122 / 6 and 2.
TEST(BurnInParts, VarianceIsThePixelsSampleVariance) {
    BurnInParts parts(4);
    std::vector<float> round;
    add_path(round, 0, 1, 2);
    add_path(round, 1, 5, 2);
    add_path(round, 0, 3, 2);
    add_path(round, 2, 100, 2);
    add_path(round, 1, 5, 2);
    add_path(round, 1, 8, 2);
    parts.add(round);
    EXPECT_EQ(parts.count, (std::vector<std::uint64_t>{2, 3, 1, 0}));
    EXPECT_NEAR(parts.variance(parts.omc, parts.omc_y2), 10.0, 1e-9);
    EXPECT_NEAR(parts.variance(parts.rest, parts.rest_y2), 0.0, 1e-9);
    EXPECT_NEAR(parts.mean(parts.omc), 122.0 / 6, 1e-9);
    EXPECT_NEAR(parts.mean(parts.rest), 2.0, 1e-9);
    BurnInParts sparse(4);
    round.clear();
    add_path(round, 0, 1, 0);
    add_path(round, 3, 3, 0);
    sparse.add(round);
    EXPECT_NEAR(sparse.variance(sparse.omc, sparse.omc_y2), 4.0 * (1 + 9) / 2, 1e-9);
}
