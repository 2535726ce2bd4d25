// The two-stage target's cells and weights (src/render/target.hpp); that it
// leaves the image unbiased is MltSplat.TwoStageImageMatchesTheTarget.
#include "base/error.hpp"
#include "render/target.hpp"

#include <gtest/gtest.h>

using namespace smallmlt;

TEST(Target, NamesParseAndBadOnesNameTheFlag) {
    EXPECT_EQ(parse_target("--target", "luminance"), Target::Luminance);
    EXPECT_EQ(parse_target("--target", "two-stage"), Target::TwoStage);
    EXPECT_STREQ(target_name(Target::TwoStage), "two-stage");
    try {
        parse_target("--target", "kelemen");
        FAIL() << "no error";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--target: 'kelemen'"), std::string::npos);
    }
}

// The smallest square cells that leave kTargetSamplesPerCell samples each.
TEST(Target, CellsFollowTheSamples) {
    TargetCells c = target_cells(128, 128, 262144); // 256 cells at most
    EXPECT_EQ(c.shift, 3u);
    EXPECT_EQ(c.columns, 16u);
    EXPECT_EQ(target_cell_count(c, 128), 256u);
    c = target_cells(100, 60, 262144); // 8 x 8 cells: 13 x 8
    EXPECT_EQ(c.shift, 3u);
    EXPECT_EQ(target_cell_count(c, 60), 104u);
    c = target_cells(512, 512, 1000); // fewer samples than a cell needs
    EXPECT_EQ(target_cell_count(c, 512), 1u);
    EXPECT_EQ(target_cell_count(target_one_cell(), 4096), 1u);
    c = target_cells(4096, 4096, std::uint64_t(1) << 40);
    EXPECT_LE(target_cell_count(c, 4096), kTargetMaxCells);
}

// w = c_max / max(c, floor): 1 at the brightest cell, c_max / c elsewhere,
// the floor (kTargetFloor of the mean) where there is no light; all 1
// without any light.
TEST(Target, WeightsEvenOutTheCells) {
    const std::uint32_t w = 4, h = 2;
    TargetCells cells{1u, 2u}; // two cells of 2 x 2 pixels
    std::vector<double> sums(3 * w * h, 0.0);
    for (std::uint32_t y = 0; y < h; ++y) {
        for (int ch = 0; ch < 3; ++ch) {
            sums[3 * (y * w + 0) + ch] = 4.0; // left cell: luminance 4 per pixel
            sums[3 * (y * w + 1) + ch] = 4.0;
            sums[3 * (y * w + 2) + ch] = 1.0; // right cell: 1
            sums[3 * (y * w + 3) + ch] = 1.0;
        }
    }
    std::vector<float> wt = target_weights(cells, w, h, sums);
    ASSERT_EQ(wt.size(), 2u);
    EXPECT_FLOAT_EQ(wt[0], 1.0f);
    EXPECT_FLOAT_EQ(wt[1], 4.0f);
    for (std::uint32_t y = 0; y < h; ++y)
        for (int ch = 0; ch < 3; ++ch)
            sums[3 * (y * w + 2) + ch] = sums[3 * (y * w + 3) + ch] = 0.0;
    wt = target_weights(cells, w, h, sums); // mean 2: floor 0.2
    EXPECT_FLOAT_EQ(wt[1], float(4.0 / (kTargetFloor * 2.0)));
    std::fill(sums.begin(), sums.end(), 0.0);
    wt = target_weights(cells, w, h, sums);
    EXPECT_FLOAT_EQ(wt[0], 1.0f);
    EXPECT_FLOAT_EQ(wt[1], 1.0f);
}
