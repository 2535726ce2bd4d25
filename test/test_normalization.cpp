// The MLT image's scale: b, the mean luminance of the film that the OMC
// samples of burn-in estimate, and the identity that ties the image to it.
// With the render tests' check of b against PT's mean on real scenes
// (test_render_blocks.cpp), these are the only tests where a mean is the
// quantity checked; where the chains put light is checked image against
// image and state against a known target (test_chain_target.cpp).
#include "image/image_metrics.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

double furnace_mean(int depth) {
    double expected = 0;
    for (int i = 0; i <= depth; ++i)
        expected += std::pow(0.5, i);
    return expected;
}

} // namespace

// In the furnace every path carries about the same radiance, the sum of
// 0.5^i over the bounces, so b is known in closed form and its standard
// error is tiny (the renderer reports it: about 0.05% at depth 2 and 0.2% at
// depth 4 here). b must lie within 4 of its standard errors plus 0.2% (the
// float rounding of 2^18 paths) of the analytic mean: a b off by 1% or
// estimated from the wrong samples fails it.
TEST(BEstimate, FurnaceBIsTheAnalyticMean) {
    for (int depth : {2, 4}) {
        DeviceScene ds = prepare_scene(test::scene("furnace", 16, 16, depth));
        MltOptions opt = test::plain_mlt();
        opt.threads = 8192;
        opt.burn_in_iters = 32;
        opt.seed = 5;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.sample_starts();
        double want = furnace_mean(depth);
        double tol = 4 * mlt.b_rel_error() + 0.002;
        std::printf("furnace depth %d: b %.6f (+-%.3f%%), analytic %.6f\n", depth, mlt.b(),
                    100 * mlt.b_rel_error(), want);
        EXPECT_LT(mlt.b_rel_error(), 0.0025) << "b noisier than this test was designed for";
        EXPECT_NEAR(mlt.b(), want, tol * want) << "depth " << depth;
    }
}

// Every step's splats add up to the step's work-items in luminance (a
// proposal splats a F(y)/I(y), the chain's state (K - sum a) F(x)/I(x)), so
// the image's mean luminance is b exactly, up to the rounding of the splats
// (test::film_mean_tolerance, here about 1e-4). A wrong stay or proposal
// weight (0.9 of it) breaks
// the sum. Checked at K = 1 and K = 4. Only with burn-in: a chain started
// without it may sit on a black path, where F(x)/I(x) is undefined and its
// stay weight splats nothing (the startup bias of doc/stability.md).
TEST(BEstimate, ImageMeanIsBByConstruction) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 24, 24));
    for (std::uint32_t k : {1u, 4u}) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 2048;
        opt.proposals = k;
        opt.burn_in_iters = 4;
        opt.large_step = 0.1f;
        opt.seed = 3 + k;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(16);
        double mean = mlt.image().mean_luminance();
        EXPECT_NEAR(mean, mlt.b(), test::film_mean_tolerance(mlt) * mlt.b()) << "K " << k;
    }
}

// Every large step is an OMC sample of I and joins b, so b keeps converging
// after burn-in: in the furnace at depth 4, 256 chains with 4 burn-in rounds
// (1,024 samples) then 400 steps at large-step probability 0.5 (about
// 51,000 more). The reported error must fall as 1/sqrt(samples) (by more
// than 5x) and b must stay within 4 of its errors plus 0.2% of the analytic
// mean. Leaving the large steps out, or counting them twice, fails it.
TEST(BEstimate, LargeStepsKeepBConverging) {
    DeviceScene ds = prepare_scene(test::scene("furnace", 16, 16, 4));
    MltOptions opt = test::plain_mlt();
    opt.threads = 256;
    opt.burn_in_iters = 4;
    opt.large_step = 0.5f;
    opt.seed = 12;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    double err0 = mlt.b_rel_error();
    mlt.step(400);
    double want = furnace_mean(4), err = mlt.b_rel_error();
    MltStats s = mlt.stats();
    std::printf("furnace depth 4: b %.6f (+-%.3f%%, after burn-in +-%.3f%%), %llu large steps, "
                "analytic %.6f\n",
                mlt.b(), 100 * err, 100 * err0, static_cast<unsigned long long>(s.large), want);
    EXPECT_GT(s.large, 45000u);
    EXPECT_LT(err, err0 / 5);
    EXPECT_NEAR(mlt.b(), want, (4 * err + 0.002) * want);
    EXPECT_NEAR(mlt.image().mean_luminance(), mlt.b(), test::film_mean_tolerance(mlt) * mlt.b());
}
