// The chains' starts (StartPicks, src/render/start_picks.hpp): pooled over
// rounds, each burn-in sample drawn in proportion to its luminance, and every
// aligned square of the film given its share of the chains within one;
// confined to each chain's tile with strata. Host code only.
#include "render/start_picks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

using namespace smallmlt;

namespace {

constexpr std::uint32_t kSide = 64, kPixels = kSide * kSide;

// A film of kSide x kSide pixels and `rounds` burn-in rounds of `n` samples
// (luminances from `make(round, index)`), and where each sample lies.
struct Pool {
    BurnInFilm film;
    StrataGrid grid;
    std::vector<std::vector<float>> lum;
    std::vector<std::vector<std::uint32_t>> pixel; // per round and index
    double total = 0;
    template <class F> Pool(std::uint32_t rounds, std::uint32_t n, std::uint32_t side, F make) {
        film = burn_in_film(11, 17, kPixels, n);
        grid = strata_grid(kSide, kSide, side);
        for (std::uint32_t r = 0; r < rounds; ++r) {
            lum.emplace_back(n);
            pixel.emplace_back(n);
            for (std::uint32_t i = 0; i < n; ++i) {
                lum[r][i] = make(r, i);
                pixel[r][i] = burn_in_film_sample(film, kPixels, std::uint64_t(r) * n + i).first;
                if (lum[r][i] > 0 && std::isfinite(lum[r][i])) total += lum[r][i];
            }
        }
    }
    StartPicks picks() const {
        StartPicks p(film, kSide, kSide, grid);
        for (std::uint32_t r = 0; r < lum.size(); ++r)
            p.add_round(r, lum[r]);
        return p;
    }
};

// Luminances over five decades with zeros, a non-finite one and a few
// bright samples, the light of a caustic among dim paths.
float mixed(std::uint32_t r, std::uint32_t i) {
    std::mt19937 rng(r * 7919u + i);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    if (i % 97 == 5) return 0.0f;
    if (i == 1234 && r == 2) return INFINITY;
    if (i % 499 == 7) return 50.0f * u(rng);
    return std::pow(10.0f, -4.0f * u(rng));
}

std::uint32_t morton_x(std::uint32_t p) {
    return p % kSide;
}
std::uint32_t morton_y(std::uint32_t p) {
    return p / kSide;
}

} // namespace

// The order is a permutation of the pixels, tile by tile, and within a
// tile every aligned 2 x 2 and 4 x 4 square of pixels is a run of it.
TEST(StartPicks, OrderIsTilesThenMortonWithin) {
    StrataGrid grid = strata_grid(kSide, kSide, 16);
    std::vector<std::uint32_t> order = start_pick_order(kSide, kSide, grid);
    ASSERT_EQ(order.size(), kPixels);
    std::vector<int> seen(kPixels, 0);
    for (std::size_t j = 0; j < order.size(); ++j) {
        ++seen[order[j]];
        if (j > 0) {
            EXPECT_LE(grid.pixel_tile[order[j - 1]], grid.pixel_tile[order[j]]) << j;
        }
    }
    for (int s : seen)
        ASSERT_EQ(s, 1);
    for (std::uint32_t q : {4u, 16u})
        for (std::size_t j = 0; j < order.size(); j += q) {
            std::uint32_t side = q == 4 ? 2 : 4, x0 = morton_x(order[j]) / side * side,
                          y0 = morton_y(order[j]) / side * side;
            for (std::size_t k = j; k < j + q; ++k) {
                EXPECT_EQ(morton_x(order[k]) / side * side, x0) << k;
                EXPECT_EQ(morton_y(order[k]) / side * side, y0) << k;
            }
        }
}

// The property the draw exists for: at every seed, every aligned square of
// 1 to 64 pixels on a side gets k L_square / L chains within one (L: the
// luminance of its samples), where independent draws scatter by the square
// root of that. 4 rounds of 4096 samples of `mixed`, 3,000 chains, 8 seeds.
TEST(StartPicks, EveryAlignedSquareGetsItsShareWithinOne) {
    Pool pool(4, kPixels, 0, mixed);
    StartPicks picks = pool.picks();
    const std::uint32_t chains = 3000;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        std::vector<cl_uint2> got = picks.draw({}, 0xFFFFFFFFu, chains, seed);
        for (std::uint32_t side = 1; side <= kSide; side *= 2) {
            const std::uint32_t n = kSide / side;
            std::vector<double> expect(n * n, 0.0), count(n * n, 0.0);
            for (std::uint32_t r = 0; r < pool.lum.size(); ++r)
                for (std::uint32_t i = 0; i < kPixels; ++i) {
                    float y = pool.lum[r][i];
                    std::uint32_t p = pool.pixel[r][i];
                    if (y > 0 && std::isfinite(y))
                        expect[morton_y(p) / side * n + morton_x(p) / side] +=
                            chains * double(y) / pool.total;
                }
            for (const cl_uint2& g : got) {
                std::uint32_t p = pool.pixel.at(g.s[0]).at(g.s[1]);
                count[morton_y(p) / side * n + morton_x(p) / side] += 1;
            }
            for (std::uint32_t b = 0; b < n * n; ++b)
                ASSERT_LT(std::fabs(count[b] - expect[b]), 1.0 + 1e-6)
                    << "seed " << seed << ", square " << b << " of side " << side;
        }
    }
}

// Over the uniform number U, each sample is drawn exactly in proportion to
// its luminance, pooled over rounds whose sums differ by 10^4 (one dark, one
// a single bright sample): the mean count of every lit sample over 2,000
// seeds against k y / L. A count is floor or ceil of k y / L, so its mean
// over S seeds has a standard deviation of at most 0.5 / sqrt(S); the bound
// is 4.9 of those, significance 1e-6 per sample and below 0.002 over the
// samples (Bonferroni). Unlit and non-finite samples are never drawn.
TEST(StartPicks, EachSampleIsDrawnInProportionToItsLuminance) {
    const std::uint32_t n = 1000, chains = 300, seeds = 2000;
    Pool pool(5, n, 0, [](std::uint32_t r, std::uint32_t i) -> float {
        if (r == 1) return 0.0f;
        if (r == 3) return i == 777 ? 50.0f : 0.0f;
        if (r == 4) return i % 10 == 0 ? 0.01f : 0.0f;
        return mixed(r, i);
    });
    StartPicks picks = pool.picks();
    std::map<std::pair<std::uint32_t, std::uint32_t>, double> count;
    for (std::uint64_t seed = 0; seed < seeds; ++seed)
        for (const cl_uint2& g : picks.draw({}, 0xFFFFFFFFu, chains, 1000 + seed)) {
            float y = pool.lum.at(g.s[0]).at(g.s[1]);
            ASSERT_TRUE(y > 0 && std::isfinite(y)) << "round " << g.s[0] << " sample " << g.s[1];
            count[{g.s[0], g.s[1]}] += 1;
        }
    const double bound = 4.9 * 0.5 / std::sqrt(double(seeds));
    double worst = 0;
    for (std::uint32_t r = 0; r < pool.lum.size(); ++r)
        for (std::uint32_t i = 0; i < n; ++i) {
            float y = pool.lum[r][i];
            if (!(y > 0 && std::isfinite(y))) continue;
            double z = count[{r, i}] / seeds - chains * double(y) / pool.total;
            worst = std::max(worst, std::fabs(z) / bound);
            EXPECT_LT(std::fabs(z), bound) << "round " << r << " sample " << i << " (" << y << ")";
        }
    std::printf("largest deviation: %.3f of the bound\n", worst);
}

// Where no sample found light, the draw is uniform over them: 2 dark
// rounds of 500, 1,000 chains: each sample drawn once.
TEST(StartPicks, DarkRoundsDrawEverySampleAlike) {
    Pool pool(2, 500, 0, [](std::uint32_t, std::uint32_t) { return 0.0f; });
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (const cl_uint2& g : pool.picks().draw({}, 0xFFFFFFFFu, 1000, 5))
        ++count[{g.s[0], g.s[1]}];
    EXPECT_EQ(count.size(), 1000u);
    for (const auto& c : count)
        EXPECT_EQ(c.second, 1);
}

// With strata (tiles of 16 pixels, 16 tiles), the chains of a work-group
// draw from their tile's samples alone, and each tile's chains follow its
// luminance: every aligned 4 x 4 square within a tile gets its share of
// the tile's chains within one. Groups of 64 chains, dealt unevenly.
TEST(StartPicks, ChainsDrawFromTheirTileAlone) {
    Pool pool(3, kPixels, 16, mixed);
    StartPicks picks = pool.picks();
    std::vector<std::uint32_t> group_tile;
    for (std::uint32_t t = 0; t < 16; ++t)
        for (std::uint32_t g = 0; g < 1 + t % 3; ++g)
            group_tile.push_back(t);
    const std::uint32_t group_chains = 64, chains = std::uint32_t(group_tile.size()) * 64;
    std::vector<cl_uint2> got = picks.draw(group_tile, group_chains, chains, 3);
    std::vector<double> tile_lum(16, 0.0), square_lum(kPixels / 16, 0.0), count(kPixels / 16, 0.0),
        tile_chains(16, 0.0);
    auto square = [](std::uint32_t p) { return morton_y(p) / 4 * (kSide / 4) + morton_x(p) / 4; };
    for (std::uint32_t r = 0; r < pool.lum.size(); ++r)
        for (std::uint32_t i = 0; i < kPixels; ++i) {
            float y = pool.lum[r][i];
            if (!(y > 0 && std::isfinite(y))) continue;
            tile_lum[pool.grid.pixel_tile[pool.pixel[r][i]]] += y;
            square_lum[square(pool.pixel[r][i])] += y;
        }
    for (std::uint32_t c = 0; c < chains; ++c) {
        std::uint32_t p = pool.pixel.at(got[c].s[0]).at(got[c].s[1]);
        ASSERT_EQ(pool.grid.pixel_tile[p], group_tile[c / group_chains]) << "chain " << c;
        count[square(p)] += 1;
    }
    for (std::uint32_t g : group_tile)
        tile_chains[g] += group_chains;
    for (std::uint32_t s = 0; s < kPixels / 16; ++s) {
        std::uint32_t p = (s / (kSide / 4)) * 4 * kSide + (s % (kSide / 4)) * 4;
        std::uint32_t t = pool.grid.pixel_tile[p];
        double expect = tile_chains[t] * square_lum[s] / tile_lum[t];
        EXPECT_LT(std::fabs(count[s] - expect), 1.0 + 1e-6) << "square " << s << ", tile " << t;
    }
}

// A tile that no sample reached draws from the whole film (mlt_init then
// moves the start to the tile's edge); one whose samples are dark draws
// them uniformly. One round of 8 samples on 16 tiles.
TEST(StartPicks, TilesWithoutSamplesOrLight) {
    Pool pool(1, 8, 16, [](std::uint32_t, std::uint32_t i) { return i < 4 ? 1.0f : 0.0f; });
    std::vector<std::uint32_t> group_tile(16);
    for (std::uint32_t t = 0; t < 16; ++t)
        group_tile[t] = t;
    std::vector<cl_uint2> got = pool.picks().draw(group_tile, 4, 64, 9);
    for (std::uint32_t c = 0; c < 64; ++c) {
        std::uint32_t t = c / 4, i = got[c].s[1];
        bool tile_has = false, tile_lit = false;
        for (std::uint32_t j = 0; j < 8; ++j)
            if (pool.grid.pixel_tile[pool.pixel[0][j]] == t) {
                tile_has = true;
                tile_lit = tile_lit || j < 4;
            }
        ASSERT_LT(i, 8u);
        if (tile_has) {
            EXPECT_EQ(pool.grid.pixel_tile[pool.pixel[0][i]], t) << "chain " << c;
        }
        if (tile_lit) {
            EXPECT_LT(i, 4u) << "chain " << c << " drew a dark sample in a lit tile";
        }
        if (!tile_has) {
            EXPECT_LT(i, 4u) << "chain " << c << " of an empty tile drew a dark sample";
        }
    }
}

// Same seed, same picks; another seed moves them.
TEST(StartPicks, SeedDecides) {
    Pool pool(2, kPixels, 0, mixed);
    StartPicks picks = pool.picks();
    auto a = picks.draw({}, 0xFFFFFFFFu, 500, 1), b = picks.draw({}, 0xFFFFFFFFu, 500, 1),
         c = picks.draw({}, 0xFFFFFFFFu, 500, 2);
    int same = 0, differ = 0;
    for (std::size_t j = 0; j < a.size(); ++j) {
        same += a[j].s[0] == b[j].s[0] && a[j].s[1] == b[j].s[1];
        differ += a[j].s[0] != c[j].s[0] || a[j].s[1] != c[j].s[1];
    }
    EXPECT_EQ(same, 500);
    EXPECT_GT(differ, 250);
}
