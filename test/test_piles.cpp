// --restart auto and --strata piles: when the chains restart, and where the
// burn-in piles them on one path, the strata that keep such a pile to one
// tile (doc/design.md, "Restarts" and "Strata").
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace smallmlt;

// --restart auto: every 8 steps where the chains are at least the film's
// pixels and a restart's samples are large steps' (Kelemen's weights with
// burn-in), else never; a number is kept, and auto is the default. Then in
// renders: the known target at 16x16 (256 pixels) with 1,024 chains
// restarts every 8 steps, splats its restarts' samples and takes
// kDefaultLargeStepRestart's large steps; at 64x64 (4,096 pixels) it never
// restarts and takes kDefaultLargeStepKelemen's. The share of large steps
// among 40,960 mutations is within 0.01 of its probability: 6.6 standard
// deviations of a binomial at 0.1, 4.4 at 0.3 (two-sided 1e-5).
TEST(MltRestart, AutoRestartsWhereTheChainsAreAtLeastThePixels) {
    EXPECT_EQ(MltOptions().restart, kRestartAuto) << "the default";
    MltOptions opt;
    opt.restart = kRestartAuto;
    EXPECT_EQ(restart_steps(opt, 16384, 16384), kRestartAutoSteps);
    EXPECT_EQ(restart_steps(opt, 16383, 16384), 0u);
    MltOptions expected = opt;
    expected.kelemen = false;
    EXPECT_EQ(restart_steps(expected, 16384, 1024), 0u);
    MltOptions no_burn_in = opt;
    no_burn_in.burn_in = false;
    EXPECT_EQ(restart_steps(no_burn_in, 16384, 1024), 0u);
    MltOptions given = opt;
    given.restart = 32;
    EXPECT_EQ(restart_steps(given, 1, 1024), 32u);
    given.restart = 0;
    EXPECT_EQ(restart_steps(given, 16384, 1024), 0u);
    for (std::uint32_t side : {16u, 64u}) {
        DeviceScene ds = test::layout_only_scene({}, side, side);
        MltOptions o;
        o.restart = kRestartAuto;
        o.split = Split::None;
        o.threads = 1024;
        o.burn_in_iters = 4;
        MltTestHooks hooks;
        hooks.evaluator = "test/cl/eval_target.cl";
        MltRenderer mlt(test::cl(), ds, o, hooks);
        mlt.prepare();
        mlt.step(40);
        const MltReport r = mlt.report();
        EXPECT_EQ(r.restart_every, side == 16 ? kRestartAutoSteps : 0u) << side;
        EXPECT_EQ(r.restarts, side == 16 ? 40u / kRestartAutoSteps : 0u) << side;
        EXPECT_EQ(r.restart_samples, side == 16) << side;
        const double large = double(r.stats.large) / double(r.stats.mutations);
        EXPECT_NEAR(large, side == 16 ? kDefaultLargeStepRestart : kDefaultLargeStepKelemen, 0.01)
            << side;
    }
}

// --restart auto where the chains are fewer than the pixels: restarts
// every 16 steps after a burn-in whose brightest path took more than
// kPileShare of the chains, or whose cells found the chains' error where
// they would stay above kPileStay times their error were they free by each
// pixel's samples, or above kPileStayNeighbours by its neighbours'; else
// never. A number given is kept. Renders with a quarter as many chains as
// pixels:
// - tiny-caustic at 64x64, 64 burn-in rounds: at seed 4 the burn-in finds
//   a path from the ceiling through the ball to the spark (b +-21%) and
//   starts a pile of chains on it; at seed 3 it finds none, and its
//   brightest path takes about one chain. The caustic lies behind glass,
//   so no cell and no stay.
// - veach-mis at 128x128, 32 rounds: the lamps' images on the plates,
//   where chains would stay, though no path takes 1% of them. The burn-in
//   then chooses the OMC part's cells for chains that restart (3 cells;
//   for those that do not, 1), so the render is bit for bit the one of
//   --restart 16 given.
// - cornell-glass at 64x64, 64 rounds: neither.
// The summary gives the stay where the cells measured it, and only there.
TEST(MltRestart, AutoRestartsWhereChainsPileUp) {
    MltOptions opt;
    EXPECT_EQ(restart_pile_steps(opt, 2 * kPileShare, {}), kRestartPileSteps);
    EXPECT_EQ(restart_pile_steps(opt, 0, {2 * kPileStay, 0}), kRestartPileSteps);
    EXPECT_EQ(restart_pile_steps(opt, 0, {0, 2 * kPileStayNeighbours}), kRestartPileSteps);
    EXPECT_EQ(restart_pile_steps(opt, kPileShare, {kPileStay, kPileStayNeighbours}), 0u);
    MltOptions given = opt;
    given.restart = 0;
    EXPECT_EQ(restart_pile_steps(given, 1.0, {1e9, 1e9}), 0u);
    MltOptions no_burn_in = opt;
    no_burn_in.burn_in = false;
    EXPECT_EQ(restart_pile_steps(no_burn_in, 1.0, {1e9, 1e9}), 0u);
    struct Case {
        const char* scene;
        std::uint32_t side, rounds;
        std::uint64_t seed;
        bool pile, stay;
    };
    for (const Case& c :
         {Case{"tiny-caustic", 64, 64, 3, false, false},
          Case{"tiny-caustic", 64, 64, 4, true, false}, Case{"veach-mis", 128, 32, 2, false, true},
          Case{"cornell-glass", 64, 64, 4, false, false}}) {
        DeviceScene ds = prepare_scene(test::scene(c.scene, c.side, c.side));
        MltOptions o;
        o.threads = c.side * c.side / 4;
        o.burn_in_iters = c.rounds;
        o.seed = c.seed;
        MltRenderer mlt(test::cl(), ds, o);
        mlt.prepare();
        mlt.step(32);
        const MltReport r = mlt.report();
        const double share = mlt.largest_start_share();
        ASSERT_TRUE(mlt.chains_stay()) << c.scene << " " << c.seed;
        const ChainsStay stay = *mlt.chains_stay();
        std::printf("%s %ux%u, seed %llu: the brightest path took %.3g%% of the chains (%.1f), "
                    "stay %.3g (own) %.3g (neighbours'), b +-%.2f%%; restarts every %u steps; "
                    "%u cells to the OMC part\n",
                    c.scene, c.side, c.side, (unsigned long long)c.seed, 100 * share,
                    share * o.threads, stay.own, stay.neighbours, 100 * r.b_rel_error,
                    r.restart_every, r.omc_cells);
        if (c.pile)
            EXPECT_GT(share, 4 * kPileShare) << c.scene << " " << c.seed;
        else
            EXPECT_LT(share, kPileShare) << c.scene << " " << c.seed;
        if (c.stay) {
            EXPECT_GT(stay.own, 2 * kPileStay) << c.scene << " " << c.seed;
            EXPECT_GT(stay.neighbours, 2 * kPileStayNeighbours) << c.scene << " " << c.seed;
        } else {
            EXPECT_LT(stay.own, kPileStay / 4) << c.scene << " " << c.seed;
            EXPECT_LT(stay.neighbours, kPileStayNeighbours / 4) << c.scene << " " << c.seed;
        }
        // The summary says the stays the rule read.
        char said[96];
        std::snprintf(said, sizeof said, "; the chains' stay %.3g by each pixel's samples, %.3g by",
                      stay.own, stay.neighbours);
        ASSERT_TRUE(r.chains_stay) << c.scene << " " << c.seed;
        EXPECT_EQ(r.chains_stay->own, stay.own) << c.scene << " " << c.seed;
        EXPECT_EQ(r.chains_stay->neighbours, stay.neighbours) << c.scene << " " << c.seed;
        EXPECT_NE(mlt_summary(r).find(said), std::string::npos) << mlt_summary(r);
        const bool restarts = c.pile || c.stay;
        EXPECT_EQ(r.restart_every, restarts ? kRestartPileSteps : 0u) << c.scene << " " << c.seed;
        EXPECT_EQ(r.restarts, restarts ? 32u / kRestartPileSteps : 0u) << c.scene << " " << c.seed;
        if (!c.stay) continue;
        MltOptions given = o;
        given.restart = kRestartPileSteps;
        MltRenderer restarting(test::cl(), ds, given);
        restarting.prepare();
        restarting.step(32);
        EXPECT_EQ(r.omc_cells, restarting.report().omc_cells) << c.scene << " " << c.seed;
        EXPECT_TRUE(mlt.image().rgb == restarting.image().rgb) << c.scene << " " << c.seed;
    }
    // Without the OMC part's cells the stay is not measured, and the
    // summary does not give it.
    DeviceScene ds = prepare_scene(test::scene("cornell-glass", 32, 32));
    MltOptions cells_off;
    cells_off.threads = 256;
    cells_off.burn_in_iters = 4;
    cells_off.omc_cells = false;
    MltRenderer mlt(test::cl(), ds, cells_off);
    mlt.prepare();
    mlt.step(1);
    EXPECT_FALSE(mlt.chains_stay());
    EXPECT_FALSE(mlt.report().chains_stay);
    EXPECT_EQ(mlt_summary(mlt.report()).find("the chains' stay"), std::string::npos)
        << mlt_summary(mlt.report());
}

// --strata piles, the default: auto's tiles where the burn-in piled the
// chains on one path (strata_for_piles), else none, decided after the
// burn-in's rounds. tiny-caustic at 64x64 with 4,096 chains (16 tiles of
// 16 pixels for auto), 16 burn-in rounds: at seed 4 the brightest path
// takes 45% of the chains, at seed 3 0.12%. Either way the render
// after 24 steps is bit for bit the one of the strata the rule chose,
// given: --strata auto at seed 4 and none at seed 3, so b's sums, the draw
// of starts and the tiles on the device all follow the choice.
TEST(MltStrata, PilesKeepTheTilesWhereChainsPileUp) {
    MltOptions opt;
    EXPECT_EQ(opt.strata, kStrataPiles) << "the default";
    EXPECT_TRUE(strata_for_piles(opt, 2 * kPileShare));
    EXPECT_FALSE(strata_for_piles(opt, kPileShare));
    MltOptions given = opt;
    given.strata = kStrataAuto;
    EXPECT_FALSE(strata_for_piles(given, 1.0));
    DeviceScene ds = prepare_scene(test::scene("tiny-caustic", 64, 64));
    for (std::uint64_t seed : {3u, 4u}) {
        const bool pile = seed == 4;
        MltOptions o;
        o.threads = 4096;
        o.burn_in_iters = 16;
        o.seed = seed;
        MltRenderer mlt(test::cl(), ds, o);
        mlt.prepare();
        mlt.step(24);
        const double share = mlt.largest_start_share();
        std::printf("tiny-caustic 64x64, seed %llu: the brightest path took %.3g%% of the "
                    "chains; %u tiles\n",
                    (unsigned long long)seed, 100 * share, mlt.strata_grid().count());
        if (pile)
            EXPECT_GT(share, 4 * kPileShare);
        else
            EXPECT_LT(share, kPileShare);
        EXPECT_EQ(mlt.strata_grid().count(), pile ? 16u : 1u) << "seed " << seed;
        EXPECT_EQ(mlt.report().strata, pile ? 16u : 1u) << "seed " << seed;
        EXPECT_NE(mlt.report().split, Split::All) << "the chains run";
        const std::vector<std::uint32_t>& dealt = mlt.group_tiles();
        EXPECT_EQ(*std::max_element(dealt.begin(), dealt.end()), pile ? 15u : 0u)
            << "seed " << seed << ": the work-groups dealt to the tiles kept";
        MltOptions chosen = o;
        chosen.strata = pile ? kStrataAuto : 0;
        MltRenderer same(test::cl(), ds, chosen);
        same.prepare();
        same.step(24);
        EXPECT_EQ(mlt.b(), same.b()) << "seed " << seed;
        EXPECT_TRUE(mlt.image().rgb == same.image().rgb) << "seed " << seed;
    }
}
