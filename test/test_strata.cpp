// The strata of stratified MLT on the host (src/render/strata.hpp): the
// tiles cover the film once, the rule's side, and the dealing of work-groups
// by brightness. On the device: test_mlt.cpp (MltStrata, MltSplat) and the
// render tests (test_render_blocks.cpp).
#include "base/error.hpp"
#include "render/strata.hpp"

#include <gtest/gtest.h>

#include <numeric>

using namespace smallmlt;

// Ragged edges (20 x 13 in tiles of 8: 3 x 2 tiles, the last column 4 wide
// and the last row 5 high): every pixel in exactly one tile, the one
// pixel_tile names; the areas sum to 1; the whole film is one tile whose
// position is the film's numbers unchanged.
TEST(Strata, TilesCoverEveryPixelOnce) {
    StrataGrid g = strata_grid(20, 13, 8);
    ASSERT_EQ(g.count(), 6u);
    EXPECT_EQ(strata_count(20, 13, 8), 6u);
    std::vector<int> hits(20 * 13, 0);
    double area = 0;
    for (std::uint32_t t = 0; t < g.count(); ++t) {
        const FilmTile& f = g.tiles[t];
        area += g.area(t, 20 * 13);
        EXPECT_FLOAT_EQ(f.ox, float(f.x0) / 20);
        EXPECT_FLOAT_EQ(f.sy, float(f.h) / 13);
        for (std::uint32_t y = f.y0; y < f.y0 + f.h; ++y)
            for (std::uint32_t x = f.x0; x < f.x0 + f.w; ++x) {
                ++hits[y * 20 + x];
                EXPECT_EQ(g.pixel_tile[y * 20 + x], t) << x << ", " << y;
            }
    }
    EXPECT_EQ(g.tiles[2].w, 4u);
    EXPECT_EQ(g.tiles[5].h, 5u);
    for (int h : hits)
        EXPECT_EQ(h, 1);
    EXPECT_DOUBLE_EQ(area, 1.0);
    StrataGrid whole = strata_grid(20, 13, 0);
    ASSERT_EQ(whole.count(), 1u);
    const FilmTile& w = whole.tiles[0];
    EXPECT_EQ(w.w, 20u);
    EXPECT_EQ(w.h, 13u);
    EXPECT_EQ(w.ox, 0.0f);
    EXPECT_EQ(w.oy, 0.0f);
    EXPECT_EQ(w.sx, 1.0f);
    EXPECT_EQ(w.sy, 1.0f);
}

// auto: the smallest side of 8 pixels or more with at most a tile per 4
// work-groups; an asked side with more tiles than groups is refused.
TEST(Strata, TheRulesSideLeavesFourGroupsATile) {
    EXPECT_EQ(strata_side(kStrataAuto, 128, 128, 256), 16u); // 64 tiles of 16
    EXPECT_EQ(strata_side(kStrataAuto, 512, 512, 256), 64u); // 64 tiles of 64
    EXPECT_EQ(strata_side(kStrataAuto, 160, 90, 256), 16u);  // 10 x 6 tiles; 15: 11 x 6 = 66
    EXPECT_EQ(strata_side(kStrataAuto, 128, 128, 4), 0u);    // one group a tile at most: none
    EXPECT_EQ(strata_side(8, 128, 128, 256), 8u);
    EXPECT_THROW(strata_side(8, 128, 128, 255), UsageError);
}

// Every tile gets a group, the rest go by weight with the largest
// remainders; all weights 0 deals evenly.
TEST(Strata, GroupsAreDealtByBrightness) {
    EXPECT_EQ(strata_groups({0, 1, 3}, 10), (std::vector<std::uint32_t>{1, 3, 6}));
    EXPECT_EQ(strata_groups({1, 1, 1, 1}, 6), (std::vector<std::uint32_t>{2, 2, 1, 1}));
    EXPECT_EQ(strata_groups({0, 0}, 6), (std::vector<std::uint32_t>{3, 3}));
    EXPECT_EQ(strata_groups({5, 7}, 2), (std::vector<std::uint32_t>{1, 1}));
    std::vector<std::uint32_t> g = strata_groups({0.3, 2.9, 0.0, 11.1, 5.7}, 64);
    EXPECT_EQ(std::accumulate(g.begin(), g.end(), 0u), 64u);
    EXPECT_EQ(strata_group_tiles({2, 1, 3}, 7), (std::vector<std::uint32_t>{0, 0, 1, 2, 2, 2, 2}));
}
