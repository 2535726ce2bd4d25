// Path-tracer renders against analytic and statistical expectations:
// the furnace, determinism, and 1/spp convergence of pixel variance.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace smallmlt;

// Every face has Kd 0.5 and Ke 1 and the box is closed, so the radiance of
// every path prefix is known: L = sum_{i=0..depth} 0.5^i.
class Furnace : public ::testing::TestWithParam<int> {};

TEST_P(Furnace, MeanRadianceMatchesAnalyticWithinHalfPercent) {
    int depth = GetParam();
    DeviceScene ds = prepare_scene(test::scene("furnace", 64, 64, depth));
    Image img = test::render_pt(ds, 11, 64);
    double expected = 0;
    for (int i = 0; i <= depth; ++i)
        expected += std::pow(0.5, i);
    double mean = img.mean_luminance();
    EXPECT_NEAR(mean, expected, 0.005 * expected) << "depth " << depth;
}

INSTANTIATE_TEST_SUITE_P(Depths, Furnace, ::testing::Values(1, 4, 24));

TEST(Render, SameSeedSameImageWhateverThePassSplit) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 32, 32));
    Image a = test::render_pt(ds, 5, 8);
    Image b = test::render_pt(ds, 5, 8);
    EXPECT_EQ(a.rgb, b.rgb);
    PathTracer split(test::cl(), ds, 5);
    split.add_samples(3);
    split.add_samples(5);
    EXPECT_EQ(split.image().rgb, a.rgb);
    Image other = test::render_pt(ds, 6, 8);
    EXPECT_NE(other.rgb, a.rgb);
}

// A pixel's samples asked for at once or one by one: the same image, bit for
// bit. In one launch, 64 samples of ajar take a work-item past the 65,535
// loop iterations after which Mesa's llvmpipe ends every loop (its BVH
// traversals stop short and the image loses half its light), so there the
// path tracer must launch sample by sample (DeviceInfo::loop_iteration_limit).
TEST(Render, ManySamplesAtOnceEqualOneByOne) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 32, 32));
    Image at_once = test::render_pt(ds, 5, 64);
    PathTracer one_by_one(test::cl(), ds, 5);
    for (int k = 0; k < 64; ++k)
        one_by_one.add_samples(1);
    EXPECT_EQ(at_once.rgb, one_by_one.image().rgb);
}

// Two independent renders A, B at n spp: E[(A - B)^2] / 2 is the per-pixel
// variance. Returns its log-log slope over n = 2..32, averaged over the whole
// film and over its lower half (the directly seen light's edge pixels, a few
// dozen at this size, dominate the whole film's sum).
std::array<double, 2> variance_slopes(PtSampler sampler) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 96, 96));
    std::array<std::vector<double>, 2> log_var;
    std::vector<double> log_n;
    for (std::uint32_t n : {2u, 8u, 32u}) {
        Image a = test::render_pt(ds, 100 + n, n, sampler);
        Image b = test::render_pt(ds, 200 + n, n, sampler);
        for (int half = 0; half < 2; ++half) {
            double sum = 0;
            std::size_t first = half ? std::size_t(a.width) * (a.height / 2) : 0;
            std::size_t pixels = std::size_t(a.width) * a.height - first;
            for (std::size_t p = first; p < first + pixels; ++p) {
                double d = a.luminance(p) - b.luminance(p);
                sum += 0.5 * d * d;
            }
            log_var[half].push_back(std::log(sum / double(pixels)));
        }
        log_n.push_back(std::log(double(n)));
    }
    std::array<double, 2> slope{};
    for (int half = 0; half < 2; ++half) {
        const std::vector<double>& y = log_var[half];
        double mx = (log_n[0] + log_n[1] + log_n[2]) / 3, my = (y[0] + y[1] + y[2]) / 3;
        double sxy = 0, sxx = 0;
        for (int i = 0; i < 3; ++i) {
            sxy += (log_n[i] - mx) * (y[i] - my);
            sxx += (log_n[i] - mx) * (log_n[i] - mx);
        }
        slope[half] = sxy / sxx;
    }
    return slope;
}

// Independent random numbers: the Monte Carlo rate, slope -1 within 10%,
// measured on the lower half (the whole film's estimate rests on a handful
// of edge pixels).
TEST(Render, PixelVarianceFallsAsOneOverSppWithRandomNumbers) {
    std::array<double, 2> slope = variance_slopes(PtSampler::Random);
    std::printf("random sampler: variance slope %.3f (lower half %.3f)\n", slope[0], slope[1]);
    EXPECT_NEAR(slope[1], -1.0, 0.1);
}

// Sobol points: faster than 1/n over the whole film at low spp, where the
// stratified film positions resolve the light's edges (about -1.1 on the
// lower half alone, where indirect light dominates).
TEST(Render, PixelVarianceFallsFasterThanOneOverSppWithSobolPoints) {
    std::array<double, 2> slope = variance_slopes(PtSampler::Sobol);
    std::printf("Sobol sampler: variance slope %.3f (lower half %.3f)\n", slope[0], slope[1]);
    EXPECT_LT(slope[0], -1.25);
}
