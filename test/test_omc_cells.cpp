// The cells the split's OMC part renders whole (src/render/omc_cells.hpp):
// the rule per cell and the chains' correlation on bright pixels, and renders where it gives the
// OMC part every cell (the furnace, against its closed form) or some of them (ajar, whose floor lit
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
#include <numeric>

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

// The chains' default probability of a large step, which omc_cells weighs
// a bright pixel's correlation by, and a small step's reach of one pixel;
// without large steps the rule takes the chains to move freely everywhere.
const ChainSteps kLargeStep{large_step_of(MltOptions{}), 1}, kFree{0.0, 1};

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
        kTwoCells, 4, 2, two_cells(relative_variance(at - 1), relative_variance(at + 1)),
        kLargeStep);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_TRUE(c[0]) << "r = " << at - 1 << " is below the threshold";
    EXPECT_FALSE(c[1]) << "r = " << at + 1 << " is above it";

    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({2.0, 2.0}, {0.0, 0.0}), kLargeStep);
    EXPECT_TRUE(c[0]) << "smooth light (r = 0)";
    EXPECT_FALSE(c[1]) << "no light found: the chains'";
    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({2.0, 2.0}, {}), kLargeStep);
    EXPECT_TRUE(c[0]) << "smooth light beside a cell without samples";
    EXPECT_FALSE(c[1]) << "no samples: the chains'";

    // Smooth light with a share s / (s + 1) behind glass, s per sample.
    const double below = 0.5 * kChainsPayBehindShare, above = 2 * kChainsPayBehindShare;
    c = smallmlt::omc_cells(
        kTwoCells, 4, 2,
        two_cells({1.0, 1.0}, {1.0, 1.0}, below / (1 - below), above / (1 - above)), kLargeStep);
    EXPECT_TRUE(c[0]) << "little light behind glass";
    EXPECT_FALSE(c[1]) << "light behind glass";
}

// The cells the OMC part takes share one rate of samples per pixel, so a
// cell that goes alone (r_c < R) may not go beside another: with R = 4, a
// cell of r_c = 3 goes where it is the only one with light, and stays with
// the chains beside a smooth one (two cells go only where r_c < R / 2).
TEST(OmcCells, CellsAreChosenTogether) {
    ASSERT_EQ(kChainsPayRatio, 4.0);
    std::vector<bool> c = smallmlt::omc_cells(
        kTwoCells, 4, 2, two_cells({0.0, 0.0, 0.0}, relative_variance(3)), kLargeStep);
    EXPECT_FALSE(c[0]) << "no light";
    EXPECT_TRUE(c[1]) << "r = 3 alone";
    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({1.0, 1.0, 1.0}, relative_variance(3)),
                            kLargeStep);
    EXPECT_TRUE(c[0]) << "smooth";
    EXPECT_FALSE(c[1]) << "r = 3 beside a cell that goes";
    c = smallmlt::omc_cells(kTwoCells, 4, 2, two_cells({1.0, 1.0, 1.0}, {0.5, 1.5}), kLargeStep);
    EXPECT_TRUE(c[0]) << "smooth";
    EXPECT_TRUE(c[1]) << "r = 1/2 beside it";
}

// A chain stays on a state far brighter than b until a large step is
// accepted: correlation tau at most, I / (tau p b A) above, for an area of
// A pixels of such light.
TEST(OmcCells, ChainCorrelationGrowsWithBrightness) {
    const double b = 2, p = 0.25, tau = kChainCorrelation;
    EXPECT_DOUBLE_EQ(chain_correlation(b, b, 1, p), 1.0);
    EXPECT_DOUBLE_EQ(chain_correlation(tau * p * b, b, 1, p), 1.0);
    EXPECT_DOUBLE_EQ(chain_correlation(10 * tau * p * b, b, 1, p), 10.0);
    EXPECT_DOUBLE_EQ(chain_correlation(10 * tau * p * b, b, 4, p), 2.5) << "an area of 4 pixels";
    EXPECT_DOUBLE_EQ(chain_correlation(10 * tau * p * b, b, 20, p), 1.0) << "of 20";
    EXPECT_DOUBLE_EQ(chain_correlation(100 * b, b, 1, 0.0), 1.0) << "no large steps";
    EXPECT_DOUBLE_EQ(chain_correlation(100 * b, 0.0, 1, p), 1.0) << "no light";
}

// The area of a pixel's light within reach: 1 + (W - 1) min(1, n / m), n
// the mean of the W - 1 others in reach.
TEST(OmcCells, LightAreaCountsPixelsAsBrightWithinReach) {
    const std::uint32_t w = 5, h = 5;
    std::vector<double> m(w * h, 1.0);
    std::vector<double> a = light_areas(m, w, h, 1);
    EXPECT_DOUBLE_EQ(a[2 * w + 2], 9.0) << "inside";
    EXPECT_DOUBLE_EQ(a[2], 6.0) << "on an edge";
    EXPECT_DOUBLE_EQ(a[0], 4.0) << "in a corner";
    m[2 * w + 2] = 100; // the centre 100 times brighter
    m[0] = 0;
    a = light_areas(m, w, h, 1);
    EXPECT_DOUBLE_EQ(a[2 * w + 2], 1.08) << "alone: 1 + 8 (8 / 8) / 100";
    EXPECT_DOUBLE_EQ(a[2 * w + 1], 9.0) << "beside it";
    EXPECT_DOUBLE_EQ(a[0], 1.0) << "no light";
    a = light_areas(m, w, h, 2);
    EXPECT_DOUBLE_EQ(a[2 * w + 2], 1.23) << "reach 2: 1 + 24 (23 / 24) / 100";
}

// Parts of a w x 2 film of cells of 2 x 2 pixels (TargetCells{1, w / 2})
// whose pixels hold noisy light (r = 16: the chains pay there) but the
// first `bright` of row 0, 1,000 times brighter at r = 4.
BurnInParts bright_pixel_film(std::uint32_t w, std::uint32_t bright = 2) {
    BurnInParts parts(2 * w);
    for (std::uint32_t p = 0; p < 2 * w; ++p)
        for (double y : relative_variance(p < bright ? 4 : 16)) {
            const double l = p < bright ? 1000 * y : y;
            for (int c = 0; c < 3; ++c)
                parts.rest[3 * p + c] += l;
            parts.rest_y2[p] += l * l;
            ++parts.count[p];
        }
    return parts;
}

// That the rule gives no cell of bright_pixel_film(w, bright) to the OMC
// part, with the chains' large steps.
void expect_no_cell_goes(std::uint32_t w, std::uint32_t bright) {
    const std::vector<bool> c =
        smallmlt::omc_cells({1u, w / 2}, w, 2, bright_pixel_film(w, bright), kLargeStep);
    ASSERT_EQ(c.size(), w / 2);
    for (std::uint32_t i = 0; i < c.size(); ++i)
        EXPECT_FALSE(c[i]) << "cell " << i;
}

// On a 32 x 2 film (the small steps' reach a pixel, so each bright pixel's
// area is 2.0), were the chains to move freely on the bright pixels, their
// cell would stay theirs (r_c = 8); but they would stay there until a
// large step is accepted, about I / (p b) = 370 steps (b = 9), and the
// cell goes to the OMC part, alone.
TEST(OmcCells, CellsWhereChainsWouldStayOnABrightPixel) {
    const std::uint32_t w = 64;
    const BurnInParts parts = bright_pixel_film(w);
    std::vector<bool> c = smallmlt::omc_cells({1u, w / 2}, w, 2, parts, kFree);
    ASSERT_EQ(c.size(), w / 2);
    for (std::uint32_t i = 0; i < c.size(); ++i)
        EXPECT_FALSE(c[i]) << "cell " << i << ", the chains moving freely";
    c = smallmlt::omc_cells({1u, w / 2}, w, 2, parts, kLargeStep);
    EXPECT_TRUE(c[0]) << "the bright pixels' cell";
    for (std::uint32_t i = 1; i < c.size(); ++i)
        EXPECT_FALSE(c[i]) << "cell " << i;
}

// A bright pixel with no other within kLoneReach counts as light the chains
// move freely on (without_lone_pixels): no cell goes, as where they move
// freely everywhere.
TEST(OmcCells, ALoneBrightPixelIsNotAnAreaTheChainsStayOn) {
    expect_no_cell_goes(16, 1);
}

// A pixel's excess stays where another within kLoneReach (2) has some.
TEST(OmcCells, LonePixelsLoseTheirExcess) {
    ASSERT_EQ(kLoneReach, 2u);
    const std::uint32_t w = 8, h = 4;
    std::vector<double> e(w * h, 0.0);
    e[1 * w + 1] = 5; // (1, 1) and (3, 2): 2 apart
    e[2 * w + 3] = 3;
    e[0 * w + 7] = 4; // (7, 0): 4 from (3, 2)
    e[3 * w + 6] = 2; // (6, 3): 3 from (3, 2)
    const std::vector<double> kept = without_lone_pixels(e, w, h);
    EXPECT_DOUBLE_EQ(kept[1 * w + 1], 5.0);
    EXPECT_DOUBLE_EQ(kept[2 * w + 3], 3.0);
    EXPECT_DOUBLE_EQ(kept[0 * w + 7], 0.0) << "alone in a corner";
    EXPECT_DOUBLE_EQ(kept[3 * w + 6], 0.0) << "3 from the nearest";
    for (std::size_t p = 0; p < e.size(); ++p)
        EXPECT_TRUE(e[p] != 0 || kept[p] == 0) << "pixel " << p << " gained an excess";
}

// A pixel's neighbours' mean is their light over their samples, without
// its own: on a 3 x 3 film whose pixel i holds i + 1 samples of luminance
// 2 i, the centre's is (sum of 2 i (i + 1), i != 4) / (sum of i + 1,
// i != 4) = 440 / 40; the corner (0, 0)'s, of pixels 1, 3 and 4, is
// (4 + 24 + 40) / (2 + 4 + 5). Without samples around it, a pixel's is 0.
TEST(OmcCells, NeighbourMeansLeaveThePixelOut) {
    ASSERT_EQ(kNeighbourReach, 1u);
    BurnInParts parts(9);
    for (std::size_t i = 0; i < 9; ++i) {
        for (int c = 0; c < 3; ++c)
            parts.rest[3 * i + c] = 2.0 * double(i) * double(i + 1);
        parts.count[i] = i + 1;
    }
    std::vector<double> m = neighbour_means(parts, 3, 3);
    EXPECT_NEAR(m[4], 440.0 / 40.0, 1e-12);
    EXPECT_NEAR(m[0], 68.0 / 11.0, 1e-12);
    BurnInParts lone(9);
    for (int c = 0; c < 3; ++c)
        lone.rest[3 * 4 + c] = 5;
    lone.count[4] = 1;
    m = neighbour_means(lone, 3, 3);
    EXPECT_EQ(m[4], 0.0) << "no other pixel holds a sample";
    EXPECT_NEAR(m[0], 5.0, 1e-12);
}

// Parts of a 64 x 64 film of two samples per pixel of luminance 1, but for
// a 6 x 6 patch of mean luminance 10,000: in every pixel (`even`), or, as a
// burn-in of few samples finds it, in the white squares of a checkerboard at
// twice that, the black ones dark.
BurnInParts bright_patch(bool even) {
    const std::uint32_t w = 64;
    BurnInParts parts(w * w);
    for (std::uint32_t y = 0; y < w; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t p = std::size_t(y) * w + x;
            const bool patch = x >= 28 && x < 34 && y >= 28 && y < 34;
            const double l = !patch ? 1.0 : even ? 1e4 : (x + y) % 2 ? 0.0 : 2e4;
            for (int c = 0; c < 3; ++c)
                parts.rest[3 * p + c] = 2 * l;
            parts.rest_y2[p] = 2 * l * l;
            parts.count[p] = 2;
        }
    return parts;
}

// The chains' stay by each pixel's samples reads a patch whose light fell
// on half its pixels, at twice their mean, as more than three times the
// stay of the patch evenly lit; by the neighbours' samples it reads both
// within 15%: only the patch's rim differs, where a pixel's neighbours lie
// partly outside the patch and, in the checkerboard, a white one's are not
// half white. Both are positive.
TEST(OmcCells, StayByNeighboursReadsUnevenLightAsEven) {
    const TargetCells cells{3u, 8u}; // 8 x 8 pixels each
    ChainsStay even, uneven;
    smallmlt::omc_cells(cells, 64, 64, bright_patch(true), kLargeStep, &even);
    smallmlt::omc_cells(cells, 64, 64, bright_patch(false), kLargeStep, &uneven);
    std::printf("stay by own samples %.4g even, %.4g uneven; by neighbours' %.4g, %.4g\n", even.own,
                uneven.own, even.neighbours, uneven.neighbours);
    EXPECT_GT(even.own, 0.0);
    EXPECT_GT(even.neighbours, 0.0);
    EXPECT_GT(uneven.own, 3 * even.own);
    EXPECT_NEAR(uneven.neighbours / even.neighbours, 1.0, 0.15);
}

// The bright pixels' error with the chains does not fall as their light
// does. On a 32 x 2 film (b = 13) with three bright pixels, two in the
// first cell and one in the second, giving the first cell to the OMC part
// leaves the third pixel's excess whole, and both cells stay with the
// chains; taken to fall with the chains' light, that excess would shrink
// as the first cell's light left, and the first cell would go.
TEST(OmcCells, BrightPixelsErrorStaysWhenTheChainsLightFalls) {
    expect_no_cell_goes(32, 3);
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
    std::vector<bool> c = smallmlt::omc_cells(kTwoCells, 4, 2, parts, kLargeStep);
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

// Ajar at 32 x 32 with the direct split and 4,096 threads: at seed 5 two
// of its 64 cells go to the OMC part (omc_cells on, the default).
namespace {
MltOptions ajar_with_cells() {
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.seed = 5;
    opt.split = Split::Direct;
    opt.omc_effort = 0.2;
    return opt;
}
} // namespace

// A restart's rounds are burn-in rounds: their paths in the OMC part's cells
// are whole paths and join the cells' per-pixel samples, as the first
// burn-in's do; elsewhere the OMC part keeps only its own. Ajar at 32 x 32
// with and without --restart 4, the same seed: the same cells and the same
// first burn-in, and with restarts each cell pixel's count grows by the
// restarts' samples that landed there (each pixel gets its share of a
// round, give or take one) and every other pixel's stays; the image's mean
// stays within 3%.
TEST(OmcCells, RestartsRoundsRenderTheCellsToo) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 32, 32));
    MltOptions opt = ajar_with_cells();
    std::vector<std::uint64_t> landed[2];
    std::vector<bool> cell;
    std::uint64_t restart_samples = 0;
    double mean[2];
    for (int on = 0; on < 2; ++on) {
        opt.restart = on ? 4 : 0;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(8);
        const MltTally t = mlt.mlt_tally();
        landed[on] = t.burn_in_landed;
        mean[on] = mlt.image().mean_luminance();
        if (on) {
            restart_samples = t.restart_samples;
            EXPECT_EQ(mlt.report().restarts, 2u);
            for (std::uint32_t p = 0; p < 32 * 32; ++p)
                cell.push_back(MltInspect::target(mlt).omc_pixel(p % 32, p / 32));
        }
    }
    std::uint64_t in_cells = 0, cell_pixels = 0, elsewhere = 0;
    for (std::uint32_t p = 0; p < 32 * 32; ++p) {
        const std::uint64_t grew = landed[1][p] - landed[0][p];
        (cell[p] ? in_cells : elsewhere) += grew;
        cell_pixels += cell[p];
    }
    const double share = double(restart_samples) * double(cell_pixels) / (32 * 32);
    std::printf("ajar, restarts every 4 steps: %llu of their samples, %llu in %llu cell pixels "
                "(their share %.0f), %llu elsewhere; image %.4g against %.4g\n",
                (unsigned long long)restart_samples, (unsigned long long)in_cells,
                (unsigned long long)cell_pixels, share, (unsigned long long)elsewhere, mean[1],
                mean[0]);
    ASSERT_GT(cell_pixels, 0u) << "no cell went";
    ASSERT_GT(restart_samples, 0u);
    EXPECT_EQ(elsewhere, 0u);
    EXPECT_NEAR(double(in_cells), share, double(cell_pixels) * (restart_samples / 4096));
    EXPECT_NEAR(mean[1], mean[0], 0.03 * mean[0]);
}

// On ajar at 32 x 32 some cells go to the OMC part and the chains run on
// the rest: their b leaves out what the OMC part renders, so b falls, and
// the whole image's mean still agrees with the render without such cells
// (both within 3%: at these few samples, the image means' spread; the
// render test checks each block).
TEST(OmcCells, AjarSharesItsCellsAndKeepsItsLight) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 32, 32));
    MltOptions opt = ajar_with_cells();
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
    target.fix(one, w, h, parts, false, true, kLargeStep);
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
