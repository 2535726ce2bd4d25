// The cells the split's OMC part renders whole (src/render/omc_cells.hpp):
// the rule per cell, and renders where it gives the OMC part every cell (the
// furnace, against its closed form) or some of them (ajar, whose floor lit
// through the door's gap path tracing renders well). That the image stays
// unbiased where cells are mixed is RenderBlocks (test_render_blocks.cpp).
#include "base/error.hpp"
#include "render/mlt.hpp"
#include "render/omc_cells.hpp"
#include "render/omc_part_tracer.hpp"
#include "render/target_buffer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

// Parts of a 4 x 2 film whose two cells of 2 x 2 pixels get `n` samples
// per pixel, of grey luminance left[i] (left cell) and right[i] (right
// cell), and light behind smooth transmitters `behind` per sample.
BurnInParts two_cells(const std::vector<double>& left, const std::vector<double>& right,
                      double behind_left = 0, double behind_right = 0) {
    const std::uint32_t w = 4, h = 2;
    BurnInParts parts(w * h);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t p = y * w + x;
            const std::vector<double>& v = x < 2 ? left : right;
            for (double y1 : v) {
                for (int c = 0; c < 3; ++c)
                    parts.rest[3 * p + c] += y1;
                parts.rest_y2[p] += y1 * y1;
                parts.behind[p] += x < 2 ? behind_left : behind_right;
                ++parts.count[p];
            }
        }
    return parts;
}

const TargetCells kTwoCells{1u, 2u}; // two cells of 2 x 2 pixels on a 4 x 2 film

// Samples of relative variance r: n - 1 zeros and one n, whose mean is 1
// and whose unbiased sample variance is n (so r = n).
std::vector<double> relative_variance(std::uint32_t n) {
    std::vector<double> v(n, 0.0);
    v.back() = double(n);
    return v;
}

} // namespace

TEST(OmcCells, ParseNamesTheFlag) {
    EXPECT_TRUE(parse_omc_cells("--omc-cells", "on"));
    EXPECT_FALSE(parse_omc_cells("--omc-cells", "off"));
    try {
        parse_omc_cells("--omc-cells", "auto");
        FAIL() << "no error";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--omc-cells auto"), std::string::npos);
    }
}

// A cell goes to the OMC part exactly where chains_pay says no: r at most
// kChainsPayRatio and at most kChainsPayBehindShare of its light behind
// glass; a cell without light stays with the chains.
TEST(OmcCells, CellsWherePathTracingRendersTheChainsPartWell) {
    const std::uint32_t at = std::uint32_t(kChainsPayRatio); // r = the threshold
    std::vector<bool> c = smallmlt::omc_cells(
        kTwoCells, 4, 2, two_cells(relative_variance(at - 1), relative_variance(at + 1)));
    ASSERT_EQ(c.size(), 2u);
    EXPECT_TRUE(c[0]) << "r = " << at - 1 << " is below the threshold";
    EXPECT_FALSE(c[1]) << "r = " << at + 1 << " is above it";

    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({2.0, 2.0}, {0.0, 0.0}));
    EXPECT_TRUE(c[0]) << "smooth light (r = 0)";
    EXPECT_FALSE(c[1]) << "no light found: the chains'";

    // Smooth light with a share s / (s + 1) behind glass, s per sample.
    const double below = 0.5 * kChainsPayBehindShare, above = 2 * kChainsPayBehindShare;
    c = smallmlt::omc_cells(
        kTwoCells, 4, 2,
        two_cells({1.0, 1.0}, {1.0, 1.0}, below / (1 - below), above / (1 - above)));
    EXPECT_TRUE(c[0]) << "little light behind glass";
    EXPECT_FALSE(c[1]) << "light behind glass";
}

// The cells the OMC part takes share one rate of samples per pixel, so a
// cell that goes alone (r_c < R) may not go beside another: with R = 4, a
// cell of r_c = 3 goes where it is the only one with light, and stays with
// the chains beside a smooth one (two cells go only where r_c < R / 2).
TEST(OmcCells, CellsAreChosenTogether) {
    ASSERT_EQ(kChainsPayRatio, 4.0);
    std::vector<bool> c =
        smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({0.0, 0.0, 0.0}, relative_variance(3)));
    EXPECT_FALSE(c[0]) << "no light";
    EXPECT_TRUE(c[1]) << "r = 3 alone";
    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({1.0, 1.0, 1.0}, relative_variance(3)));
    EXPECT_TRUE(c[0]) << "smooth";
    EXPECT_FALSE(c[1]) << "r = 3 beside a cell that goes";
    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({1.0, 1.0, 1.0}, {0.5, 1.5}));
    EXPECT_TRUE(c[0]) << "smooth";
    EXPECT_TRUE(c[1]) << "r = 1/2 beside it";
}

// r_c is the pixels' own variance, not the spread between them: a cell of
// smooth light, bright on one side and dim on the other, is the OMC part's.
TEST(OmcCells, RelativeVarianceIsWithinPixels) {
    BurnInParts parts = two_cells({1.0, 1.0}, {1.0, 1.0});
    for (std::size_t p : {0, 4}) { // the left column of the left cell: 100 times brighter
        for (int c = 0; c < 3; ++c)
            parts.rest[3 * p + c] *= 100;
        parts.rest_y2[p] *= 100 * 100;
    }
    std::vector<bool> c = smallmlt::omc_cells(kTwoCells, 4, 2, parts);
    EXPECT_TRUE(c[0]);
    EXPECT_TRUE(c[1]);
}

// The furnace's light after the first vertex is smooth, so every cell goes
// to the OMC part: its per-pixel samples trace the whole path there, and
// the image (the burn-in's second half and the OMC part's samples; the
// chains find no light, b = 0) is the closed form of every L to the depth,
// within 0.3%. The burn-in's rounds that chose the cells (4, before the 8
// of --burn-in-iters) are not in it.
TEST(OmcCells, FurnaceIsRenderedWholeByTheOmcPart) {
    const int depth = 4;
    DeviceScene ds = prepare_scene(test::scene("furnace", 16, 16, depth));
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.burn_in_iters = 8;
    opt.seed = 3;
    opt.split = Split::Visible;
    opt.omc_cells = true;
    opt.omc_effort = 0.1;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    mlt.step(8);
    const double want = test::furnace_sum(0, depth), got = mlt.image().mean_luminance();
    const MltReport r = mlt.report();
    std::printf("furnace: %u of %u cells to the OMC part, image %.5f vs %.5f, b %.3g, %u spp + "
                "%.2f from burn-in\n",
                r.omc_cells, r.target_cells, got, want, mlt.b(), mlt.omc_cell_spp(), r.burn_in_spp);
    EXPECT_GT(mlt.omc_cell_spp(), 0u);
    EXPECT_EQ(r.omc_cells, r.target_cells);
    EXPECT_GT(r.target_cells, 1u);
    EXPECT_DOUBLE_EQ(r.omc_cell_share, 1.0);
    EXPECT_EQ(mlt.b(), 0.0);
    EXPECT_NEAR(got, want, 0.003 * want);
    EXPECT_DOUBLE_EQ(r.burn_in_spp, 4096.0 * 8 / 256);
    // The burn-in's paths in those cells: whole in their OMC part (1%: 64
    // paths a pixel), nothing left for the chains.
    const BurnInParts& parts = mlt.burn_in_parts();
    EXPECT_NEAR(parts.mean(parts.omc), want, 0.01 * want);
    EXPECT_EQ(parts.mean(parts.rest), 0.0);
}

// On ajar at 32 x 32 some cells go to the OMC part and the chains run on
// the rest: their b leaves out what the OMC part renders, so b falls, and
// the whole image's mean still agrees with the render without such cells
// (both within 3%: at these few samples, the image means' spread; the
// render test checks each block).
TEST(OmcCells, AjarSharesItsCellsAndKeepsItsLight) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 32, 32));
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.seed = 5;
    opt.split = Split::Direct;
    opt.omc_effort = 0.2;
    double mean[2], b[2];
    for (int on = 0; on < 2; ++on) {
        opt.omc_cells = on;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(32);
        const MltReport r = mlt.report();
        mean[on] = mlt.image().mean_luminance();
        b[on] = mlt.b();
        std::printf("ajar, OMC cells %s: %u of %u cells (%.1f%% of the film), b %.4g, image %.4g\n",
                    on ? "on" : "off", r.omc_cells, r.target_cells, 100 * r.omc_cell_share, b[on],
                    mean[on]);
        if (on) {
            EXPECT_GT(r.omc_cells, 0u);
            EXPECT_LT(r.omc_cells, r.target_cells);
            EXPECT_GT(mlt.stats().mutations, 0u);
            EXPECT_GT(mlt.omc_cell_rate(), 0.0) << "the cells' own samples";
            EXPECT_GT(mlt.omc_cell_spp(), 1u);
        } else {
            EXPECT_EQ(r.omc_cells, 0u);
        }
    }
    EXPECT_LT(b[1], 0.9 * b[0]) << "b still holds the light of the OMC part's cells";
    EXPECT_NEAR(mean[1], mean[0], 0.03 * mean[0]);
}

// The OMC part's passes over the film's pixels and over its cells' number
// their samples apart: a pixel's samples are the same whether or not the
// other kind's passes ran between its own, so its Sobol points stay
// consecutive. Cells: the left half of a 16 x 16 cornell, whose hand-made
// parts have smooth light there and none on the right.
TEST(OmcCells, FilmAndCellPassesNumberTheirOwnSamples) {
    const std::uint32_t w = 16, h = 16;
    DeviceScene ds = prepare_scene(test::scene("cornell", w, h));
    SceneBuffers scene(test::cl(), ds);
    BurnInParts parts(w * h);
    for (std::uint32_t p = 0; p < w * h; ++p) {
        const double y = p % w < w / 2 ? 1.0 : 0.0;
        parts.count[p] = 64;
        for (int c = 0; c < 3; ++c)
            parts.rest[3 * p + c] = 64 * y;
        parts.rest_y2[p] = 64 * y * y;
    }
    TargetBuffer target(test::cl(), kTargetMaxCells * sizeof(float));
    SingleRank one;
    target.fix(one, w, h, parts, false, true);
    ASSERT_GT(target.omc_pixels(), 0u);
    ASSERT_LT(target.omc_pixels(), std::uint64_t(w) * h);
    const OmcPart part{Split::Direct, &scene, {}, &target};
    auto render = [&](bool interleaved) {
        OmcPartTracer t(test::cl(), ds, 7, part);
        if (interleaved) {
            for (int i = 0; i < 2; ++i) {
                t.add_samples(3);
                t.add_cell_samples(3);
            }
        } else {
            t.add_samples(3);
            t.add_samples(3);
            t.add_cell_samples(3);
            t.add_cell_samples(3);
        }
        return t.tally();
    };
    const Tally a = render(true), b = render(false);
    EXPECT_EQ(a.ints, b.ints);
    std::size_t film = 0, cells = 0, differ = 0;
    for (std::uint32_t p = 0; p < w * h; ++p) {
        (target.omc_pixel(p % w, p / w) ? cells : film) += a.reals[3 * p] > 0;
        for (int c = 0; c < 3; ++c)
            differ += a.reals[3 * p + c] != b.reals[3 * p + c];
    }
    std::printf("%zu film and %zu cell pixels with light, %zu values differ\n", film, cells,
                differ);
    EXPECT_GT(film, 0u);
    EXPECT_GT(cells, 0u);
    EXPECT_EQ(differ, 0u);
}
