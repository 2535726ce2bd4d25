// Where the burn-in's samples lie on the film (cl/sampling/burnin_film.cl,
// src/render/burn_in.hpp): every pixel gets its share of them, give or take
// one, at Sobol sample numbers below the OMC part's first; the device puts
// each where the host expects; a pixel's samples are its Sobol sequence's
// (a (0,4,2)-net in every aligned block of 16); and a render's burn-in lands
// where expected, with its OMC part going on after it.
#include "base/rng.hpp"
#include "burnin_order.h"
#include "render/burn_in.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace smallmlt;

namespace {

// Samples per pixel of the burn-in's first `samples` samples.
std::vector<std::uint64_t> counts(const BurnInFilm& f, std::uint32_t pixels,
                                  std::uint64_t samples) {
    std::vector<std::uint64_t> n(pixels, 0);
    for (std::uint64_t g = 0; g < samples; ++g)
        ++n.at(burn_in_film_sample(f, pixels, g).first);
    return n;
}

// The known target's options with three burn-in rounds of `threads`
// samples and `split`.
MltOptions three_rounds(std::uint32_t threads, Split split) {
    MltOptions opt = test::plain_mlt();
    opt.threads = threads;
    opt.burn_in_iters = 3;
    opt.split = split;
    opt.omc_cells = false; // every round's paths stay in the parts
    return opt;
}

} // namespace

// Shares differ by at most one sample, each pixel's Sobol numbers are
// 0, 1, 2, ... without a gap or a repeat up to where burn_in_omc_start has
// the OMC part go on, and fewer samples than pixels still spread over the
// whole image (each quarter of the rows gets a quarter).
TEST(BurnInFilm, EveryPixelGetsItsShare) {
    struct Case {
        std::uint32_t width, height, per_round, rounds;
    };
    for (Case c : {Case{8, 6, 37, 40}, Case{128, 128, 256, 32}, Case{128, 128, 16384, 4},
                   Case{1, 1, 5, 3}, Case{4, 3, 1000, 2}, Case{100, 60, 600, 3}}) {
        const std::uint32_t pixels = c.width * c.height;
        const std::uint64_t samples = std::uint64_t(c.per_round) * c.rounds;
        for (std::uint64_t seed : {1, 2, 3}) {
            BurnInFilm f = burn_in_film(seed, derive_seed(seed, 9), pixels, c.per_round);
            std::vector<std::uint64_t> n = counts(f, pixels, samples);
            auto [lo, hi] = std::minmax_element(n.begin(), n.end());
            EXPECT_LE(*hi - *lo, 1u) << c.width << "x" << c.height << " seed " << seed;
            const SequenceStart start = burn_in_omc_start(f, pixels, samples);
            std::vector<std::vector<bool>> used(pixels);
            for (std::uint32_t p = 0; p < pixels; ++p)
                used[p].assign(start.at(pixels, p), false);
            for (std::uint64_t g = 0; g < samples; ++g) {
                auto [p, k] = burn_in_film_sample(f, pixels, g);
                ASSERT_LT(k, used[p].size()) << "sample " << g << ", pixel " << p;
                ASSERT_FALSE(used[p][k]) << "pixel " << p << " number " << k << " twice";
                used[p][k] = true;
            }
            for (std::uint32_t p = 0; p < pixels; ++p)
                ASSERT_EQ(std::count(used[p].begin(), used[p].end(), false), 0)
                    << "pixel " << p << ": a number before the OMC part's is unused";
        }
    }
    // 2,048 samples over 16,384 pixels: each quarter of the rows gets
    // 512 +- 64.
    BurnInFilm f = burn_in_film(5, 6, 128 * 128, 256);
    std::uint64_t quarter[4] = {};
    for (std::uint64_t g = 0; g < 2048; ++g)
        ++quarter[burn_in_film_sample(f, 128 * 128, g).first / 128 / 32];
    for (std::uint64_t q : quarter)
        EXPECT_NEAR(double(q), 512.0, 64.0);
}

// The device places every sample in the pixel the host expects (13 x 7
// pixels, whose film grid does not divide evenly), and in an 8 x 4 image
// (grid cells of 2^21 film steps) the 16 samples of each pixel with Sobol
// numbers 16..31 form a (0,4,2)-net over the pixel: for a = 0..4, each box
// of 2^-a by 2^(a-4) of the pixel holds one.
TEST(BurnInFilm, DeviceSamplesArePixelsSobolPoints) {
    for (auto [w, h] : {std::pair{13u, 7u}, std::pair{8u, 4u}}) {
        DeviceScene ds = prepare_scene(test::scene("cornell", int(w), int(h)));
        MltOptions opt = test::plain_mlt();
        MltTestHooks hooks;
        opt.threads = 64;
        hooks.extra_files = {"test/cl/probe_mlt.cl"};
        MltRenderer mlt(test::cl(), ds, opt, hooks);
        const std::uint32_t pixels = w * h, n = 40 * pixels;
        BurnInFilm f = burn_in_film(21, 22, pixels, 37);
        ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, std::size_t(n) * 3 * sizeof(cl_uint));
        ClKernel k(MltInspect::program(mlt), "probe_burnin_film");
        k.set_args(f, ds.frame, cl_ulong(0), cl_uint(n), out);
        k.run(test::cl(), n);
        std::vector<cl_uint> v(std::size_t(n) * 3);
        out.read(test::cl(), v.data());
        std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> block(pixels);
        for (std::uint32_t g = 0; g < n; ++g) {
            auto [p, index] = burn_in_film_sample(f, pixels, g);
            ASSERT_EQ(v[3 * g + 2], p) << w << "x" << h << " sample " << g;
            if (index >= 16 && index < 32) block[p].push_back({v[3 * g], v[3 * g + 1]});
        }
        if (w != 8) continue;
        for (std::uint32_t p = 0; p < pixels; ++p) {
            ASSERT_EQ(block[p].size(), 16u) << "pixel " << p;
            for (int a = 0; a <= 4; ++a) {
                std::vector<int> box(16, 0);
                for (auto [x, y] : block[p]) {
                    std::uint32_t bx = (x >> 21 == p % w) ? (x >> (21 - a)) & ((1u << a) - 1) : 99;
                    std::uint32_t by =
                        (y >> 22 == p / w) ? (y >> (22 - (4 - a))) & ((1u << (4 - a)) - 1) : 99;
                    ASSERT_LT(bx, 99u) << "pixel " << p << ": x outside it";
                    ASSERT_LT(by, 99u) << "pixel " << p << ": y outside it";
                    ++box[(by << a) | bx];
                }
                for (int b = 0; b < 16; ++b)
                    EXPECT_EQ(box[b], 1) << "pixel " << p << ", a = " << a << ", box " << b;
            }
        }
    }
}

// A render's burn-in (3 rounds of 256 samples over 13 x 7 pixels) lands
// where burn_in_film_sample puts it, round by round, and the split's OMC part
// goes on with each pixel's sequence at the number after the burn-in's last.
TEST(BurnInFilm, RenderBurnInLandsWhereExpected) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 13, 7));
    MltRenderer mlt(test::cl(), ds, three_rounds(256, Split::Visible));
    mlt.prepare();
    const std::uint32_t pixels = 13 * 7;
    const std::uint64_t samples = 3 * 256;
    const std::vector<std::uint64_t> n = counts(mlt.burn_in_film(), pixels, samples);
    EXPECT_EQ(mlt.burn_in_parts().count, n);
    const PtNumbering* omc = mlt.omc_numbering();
    ASSERT_NE(omc, nullptr);
    EXPECT_EQ(omc->stride, 1u);
    for (std::uint32_t p = 0; p < pixels; ++p)
        EXPECT_EQ(omc->offset + burnin_order_late(&omc->late, pixels, p), n[p]) << "pixel " << p;
}

// The burn-in's samples are the path tracer's: with every light left to
// per-pixel samples (Split::All), an MLT render of cornell (16 x 12 pixels,
// 3 rounds of 80 samples: some pixels get one more than others) is, pixel by
// pixel, the Sobol path tracer's image of its OMC part's seed at the
// pixel's own count of samples, up to float rounding and the film numbers'
// grid (the burn-in's is the film's, the path tracer's the pixel's).
// Random numbers past the film position differ by a sample's noise. So is
// that of --split auto where no chain runs (cornell's r is below the
// threshold), whose burn-in ran a round more to choose the OMC part's cells
// and keeps its paths (MltBurnIn::settle_cell_rounds).
TEST(BurnInFilm, BurnInSamplesAreThePathTracers) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 16, 12));
    for (Split split : {Split::All, Split::Auto}) {
        MltOptions opt = three_rounds(80, split);
        opt.seed = 5;
        opt.omc_cells = split == Split::Auto;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        ASSERT_EQ(mlt.split(), Split::All) << "asked " << split_name(split);
        if (split == Split::Auto) {
            ASSERT_GT(mlt.report().omc_cells, 0u) << "no cell was chosen";
        }
        mlt.step(8);
        const std::uint32_t pixels = 16 * 12, spp = mlt.omc_spp();
        ASSERT_GT(spp, 0u);
        const Image img = mlt.part_image(MltRenderer::Part::Omc);
        const PtNumbering* omc = mlt.omc_numbering();
        ASSERT_NE(omc, nullptr);
        const std::uint32_t rounds = burn_in_rounds(opt), q = rounds * 80 / pixels;
        const Image pt[2] = {test::render_pt(ds, omc->seed, q + spp),
                             test::render_pt(ds, omc->seed, q + spp + 1)};
        int late = 0, off = 0;
        double worst = 0;
        for (std::uint32_t p = 0; p < pixels; ++p) {
            const std::uint32_t l = burnin_order_late(&omc->late, pixels, p);
            late += int(l);
            for (int c = 0; c < 3; ++c) {
                const double want = pt[l].rgb[3 * p + c], got = img.rgb[3 * p + c];
                const double rel = std::abs(got - want) / std::max(want, 1e-3);
                worst = std::max(worst, rel);
                off += rel > 1e-4;
            }
        }
        std::printf("asked %s, %u burn-in rounds: %d of %u pixels late, %d of %u values off by "
                    "more than 1e-4, worst %.3g\n",
                    split_name(split), rounds, late, pixels, off, 3 * pixels, worst);
        EXPECT_EQ(rounds, split == Split::Auto ? 4u : 3u);
        EXPECT_GT(late, 0);
        EXPECT_LT(late, int(pixels));
        EXPECT_EQ(off, 0);
    }
}
