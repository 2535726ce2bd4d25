// The MLT film of 32-bit words (cl/mlt/film.cl, src/render/mlt_film.hpp): its
// overflow bound, taken to its worst case; stochastic rounding, unbiased
// where a channel is far below one unit; the same image as the 64-bit
// reference film within rounding; and bands, which change nothing.
#include "base/error.hpp"
#include "device/memory_plan.hpp"
#include "render/mlt.hpp"
#include "render/mlt_film.hpp"
#include "render/path_tracer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

// The furnace (depth 4, whose program other tests build too) with emission
// `ke` on every face: every path's F is a multiple of ke (the walls are
// grey), so every splat has ke's colour.
DeviceScene coloured_furnace(int film, float r, float g, float b) {
    DeviceScene ds = prepare_scene(test::scene("furnace", film, film, 4));
    for (Material& m : ds.materials) {
        m.ke[0] = r;
        m.ke[1] = g;
        m.ke[2] = b;
    }
    return ds;
}

// Per channel, the sum over the image.
std::array<double, 3> channel_sums(const Image& img) {
    std::array<double, 3> s{};
    for (std::size_t i = 0; i < img.rgb.size(); ++i)
        s[i % 3] += img.rgb[i];
    return s;
}

} // namespace

// The plan keeps every pass under 2^32 by the bound, with the most fraction
// bits the bound allows (one more would break it), and at least 8 of them up
// to 2^20 threads; with Kelemen's weights, as many in each of two layers (a
// mutation adds at most 1 to each).
TEST(FilmPlan, EveryPassStaysBelowTwoTo32) {
    for (std::uint32_t t : {64u, 1000u, 4096u, 65536u, 1u << 20, 3u << 20}) {
        MltFilmPlan p = plan_mlt_film(4096, t, kNoAllocLimit, false);
        std::uint32_t f = p.shape.frac_bits, s = p.steps_per_drain;
        EXPECT_LE(film_pass_bound(t, s, f), 4294967295.0) << t << " threads";
        if (f < kFilmMaxFracBits) {
            EXPECT_GT(film_pass_bound(t, s, f + 1), 4294967295.0) << t << " threads";
        }
        if (t <= (1u << 20)) {
            EXPECT_GE(f, 8u) << t << " threads";
        }
        EXPECT_GE(std::uint64_t(t) * s, std::min<std::uint64_t>(kFilmPassMutations, t));
        EXPECT_EQ(p.shape.scale, std::ldexp(1.0f, int(f)));
        MltFilmPlan k = plan_mlt_film(4096, t, kNoAllocLimit, false, kFilmPassMutations, 2);
        EXPECT_EQ(k.shape.frac_bits, f) << t << " threads";
        EXPECT_EQ(k.shape.layers, 2u);
        EXPECT_EQ(p.shape.layers, 1u);
    }
    MltFilmPlan ref = plan_mlt_film(4096, 4096, kNoAllocLimit, true);
    EXPECT_EQ(ref.steps_per_drain, 0u);
    EXPECT_EQ(ref.shape.frac_bits, std::uint32_t(FILM64_FRAC_BITS));
}

// The worst case of the bound: a 1x1 film, so every splat of a pass lands
// on one pixel, and pure blue light, so each splat adds its weight / 0.0722
// to that pixel's blue word, the most any channel can take. 4,096 threads
// with passes of 2^16 mutations drain every 16 steps with 12 fraction bits
// (the plan's rule, at a shorter pass than the default): a pass fills the
// word to 2^16 x 2^12 / 0.0722 = 3.72e9 of its 4.29e9. The peak must come
// within 0.5% of that (the test reaches the bound), and the image must
// still be exact: blue = b / 0.0722 (every splat's luminance is its weight,
// and the weights of a step sum to the threads), red and green 0. One more
// fraction bit would wrap every pass and miss by half. Each pass ends with
// nothing owed, which the bound assumes.
TEST(FilmOverflow, EverySplatOnOnePixelIsExact) {
    DeviceScene ds = coloured_furnace(1, 0, 0, 1);
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.film_pass_mutations = 1u << 16;
    opt.burn_in_iters = 2;
    opt.seed = 21;
    MltRenderer mlt(test::cl(), ds, opt);
    ASSERT_EQ(mlt.film().plan().steps_per_drain, 16u);
    ASSERT_EQ(mlt.film().plan().shape.frac_bits, 12u);
    mlt.prepare();
    mlt.step(32); // two passes: each ends with every gathered weight splatted
    std::vector<ChainValue> values(4096);
    MltInspect::values(mlt).read(test::cl(), values.data());
    for (const ChainValue& v : values)
        ASSERT_EQ(v.stay, 0u) << "a pass ended with a weight still owed";
    mlt.step(10);
    double want_peak = 4096.0 * 16 * 4096 / 0.0722;
    double peak = double(mlt.film().peak_word());
    Image img = mlt.image();
    std::printf("peak word %.6g (bound's worst case %.6g, 2^32 = 4.295e9); blue %.8g, b / "
                "0.0722 = %.8g\n",
                peak, want_peak, double(img.rgb[2]), mlt.b() / 0.0722);
    EXPECT_NEAR(peak, want_peak, 0.005 * want_peak);
    EXPECT_EQ(img.rgb[0], 0.0f);
    EXPECT_EQ(img.rgb[1], 0.0f);
    EXPECT_NEAR(img.rgb[2], mlt.b() / 0.0722, 1e-4 * mlt.b() / 0.0722);
}

// Rounding must not bias dim channels. Light of colour (3e-5, 0, 1) makes
// every splat's red about 0.1 of a word's unit (2^-8): rounded to nearest
// or down, red would vanish. Rounded at random with the probability of its
// fraction, the image's red / blue is 3e-5 (every splat's ratio) up to the
// noise of rounding: with about 4 x 10^5 splats of p = 0.1, a relative
// standard deviation of 3 / sqrt(4 x 10^5) = 0.5%; the test allows 3%
// (6 sigma).
TEST(FilmRounding, DimChannelsAreNotBiased) {
    const float red = 3e-5f;
    DeviceScene ds = coloured_furnace(8, red, 0, 1);
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.burn_in_iters = 2;
    opt.seed = 22;
    MltRenderer mlt(test::cl(), ds, opt);
    ASSERT_EQ(mlt.film().plan().shape.frac_bits, 8u);
    mlt.prepare();
    mlt.step(60);
    std::array<double, 3> s = channel_sums(mlt.image());
    double ratio = s[0] / s[2] / red;
    std::printf("red / blue = %.5f of the light's\n", ratio);
    EXPECT_NEAR(ratio, 1.0, 0.03);
    EXPECT_EQ(s[1], 0.0);
}

// Same seed, same chains (cornell, as MltStaySplat, whose 64-bit program it
// shares): the 32-bit film and the 64-bit reference give
// images that differ only by rounding. The 32-bit film rounds each added
// word at random, an error in (-1, 1) units of 2^-F with mean 0 and
// variance at most 1/4 (the reference's 2^-24 is negligible beside it).
// With N added words (the steps' atomics, plus at most one per channel and
// chain for each flush and read), the sum of squared differences is within
// twice its bound N / 4; and per channel the image's sum of differences,
// whose variance the channel's sum of squares estimates (the pixels' errors
// are independent), is within 4 of its standard deviations (a bias of 1/32
// unit in the 3% of adds that carry large stay weights fails it).
TEST(FilmAtomics, ThirtyTwoBitFilmEqualsSixtyFourWithinRounding) {
    SKIP_WITHOUT_INT64_ATOMICS();
    DeviceScene ds = prepare_scene(test::scene("cornell", 32, 32));
    Image img[2];
    MltStats st[2];
    double unit = 0, b = 0;
    std::uint32_t drains = 0;
    for (int wide = 0; wide < 2; ++wide) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 2048;
        opt.film_pass_mutations = 8192; // drains every 4 steps
        opt.seed = 31;
        opt.burn_in_iters = 4;
        opt.film_atomics64 = wide;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(40);
        img[wide] = mlt.image();
        st[wide] = mlt.stats();
        if (!wide) {
            const MltFilmPlan& p = mlt.film().plan();
            drains = 40 / p.steps_per_drain;
            b = mlt.b();
            unit = b * 1024.0 / double(st[0].mutations) / double(p.shape.scale);
        }
    }
    ASSERT_EQ(st[0].accepted, st[1].accepted) << "the chains took other paths";
    ASSERT_EQ(st[0].rays, st[1].rays);
    double n = double(st[0].atomics) + 3.0 * 2048 * (drains + 1);
    double sum[3] = {}, sq[3] = {};
    for (std::size_t i = 0; i < img[0].rgb.size(); ++i) {
        double d = (double(img[0].rgb[i]) - double(img[1].rgb[i])) / unit;
        sum[i % 3] += d;
        sq[i % 3] += d * d;
    }
    std::printf("N = %.0f added words; sums of differences %.1f %.1f %.1f units (sd %.1f %.1f "
                "%.1f); squares %.0f (bound %.0f)\n",
                n, sum[0], sum[1], sum[2], std::sqrt(sq[0]), std::sqrt(sq[1]), std::sqrt(sq[2]),
                sq[0] + sq[1] + sq[2], n / 2);
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(std::fabs(sum[c]), 4 * std::sqrt(sq[c])) << "channel " << c;
    EXPECT_LT(sq[0] + sq[1] + sq[2], n / 2);
    EXPECT_GT(sq[0], 0.0) << "the films rounded alike: is the 32-bit film in use?";
}

// A film split into bands renders the image of one buffer, bit for bit: by
// MLT (40x40 = 1,600 pixels in 4 bands of 448) and by PT. A fifth band is
// refused by MLT, which binds at most four.
TEST(FilmBands, BandsChangeNothing) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 40, 40));
    const std::uint64_t banded = 448 * 12; // 448 pixels of 12 bytes
    EXPECT_EQ(plan_pt(ds, banded).film_bands(), 4u);
    EXPECT_EQ(plan_mlt(ds, ChainShape{1024, 1, false, false}, banded).film_bands(), 4u);
    std::vector<float> mlt[2], pt[2];
    for (int split = 0; split < 2; ++split) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 1024;
        opt.film_pass_mutations = 4096;
        opt.burn_in_iters = 2;
        opt.seed = 41;
        opt.max_alloc_bytes = split ? banded : 0;
        MltRenderer m(test::cl(), ds, opt);
        EXPECT_EQ(m.film().plan().shape.bands, split ? 4u : 1u);
        m.prepare();
        m.step(10);
        mlt[split] = m.image().rgb;
        PathTracer p(test::cl(), ds, 41, PtSampler::Sobol, split ? banded : 0);
        p.add_samples(4);
        pt[split] = p.image().rgb;
    }
    EXPECT_EQ(mlt[0], mlt[1]);
    EXPECT_EQ(pt[0], pt[1]);
    MltOptions five = test::plain_mlt();
    five.threads = 1024;
    five.max_alloc_bytes = 320 * 12;
    try {
        MltRenderer m(test::cl(), ds, five);
        ADD_FAILURE() << "a film of 5 bands was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("5 bands"), std::string::npos) << e.what();
    }
}

// The targets of the film's memory: cornell-water at 512x512, depth 24,
// fits 16 MiB (largest allocation 4 MiB), and a 3840x2160 film fits
// 256 MiB by PT and by MLT, in bands of at most 64 MiB. (test/cli_test.sh
// renders them.)
TEST(FilmBands, SmallDevicesHoldLargeFilms) {
    const DeviceInfo& dev = test::cl().device();
    DeviceScene water = prepare_scene(test::scene("cornell-water", 512, 512, 24));
    DeviceBudget mib16 = device_budget(dev, std::uint64_t(16) << 20);
    ThreadChoice c = choose_threads(water, ChainShape{}, dev, mib16);
    EXPECT_GE(c.threads, kMinThreads);
    EXPECT_TRUE(plan_fits(plan_pt(water, mib16.max_alloc_bytes), mib16));
    DeviceScene uhd = prepare_scene(test::scene("cornell", 3840, 2160));
    DeviceBudget mib256 = device_budget(dev, std::uint64_t(256) << 20);
    MemoryPlan pt = plan_pt(uhd, mib256.max_alloc_bytes);
    EXPECT_TRUE(plan_fits(pt, mib256));
    EXPECT_EQ(pt.film_bands(), 2u);
    ThreadChoice m = choose_threads(uhd, ChainShape{}, dev, mib256);
    EXPECT_EQ(m.plan.film_bands(), 2u);
    EXPECT_LE(m.plan.largest(), mib256.max_alloc_bytes);
}
