// The MLT counters' rows (MLT_COUNTERS, cl/core/shared_types.h): each
// counter is joined over the work-groups' rows as the list says.
#include "render/mlt.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using namespace smallmlt;

TEST(MltStats, RowsJoinBySumOrMaximum) {
    std::vector<std::uint64_t> rows(2 * MLT_STAT_COUNT);
    for (int i = 0; i < MLT_STAT_COUNT; ++i) {
        rows[i] = 10 + i;                       // group 0
        rows[MLT_STAT_COUNT + i] = 100 + 2 * i; // group 1
    }
    rows[MLT_STAT_LONGEST] = 900; // the longest run is a maximum, not a sum
    MltStats s = mlt_join_rows(rows);
    auto sum = [&](int i) { return rows[i] + rows[MLT_STAT_COUNT + i]; };
    EXPECT_EQ(s.accepted, sum(MLT_STAT_ACCEPTED));
    EXPECT_EQ(s.large, sum(MLT_STAT_LARGE));
    EXPECT_EQ(s.nonfinite, sum(MLT_STAT_NONFINITE));
    EXPECT_EQ(s.rays, sum(MLT_STAT_RAYS));
    EXPECT_EQ(s.stuck, sum(MLT_STAT_STUCK));
    EXPECT_EQ(s.atomics, sum(MLT_STAT_ATOMICS));
    EXPECT_EQ(s.large_lum, sum(MLT_STAT_LARGE_LUM));
    EXPECT_EQ(s.longest_run, 900u);
    rows[MLT_STAT_COUNT + MLT_STAT_LONGEST] = 901;
    EXPECT_EQ(mlt_join_rows(rows).longest_run, 901u);
    // Every counter has its own word: no two of them read the same one.
    EXPECT_EQ(MLT_STAT_COUNT, MLT_COUNTS + 1);
    EXPECT_EQ(MLT_COUNTS, 7);
}

// An MLT tally goes to a Tally and back field by field, and a Tally of
// another shape (a rank with or without a split, with or without the large
// steps' layer) is refused.
TEST(MltTally, RoundTripsAndRefusesAnotherShape) {
    MltTally t = MltTally::shaped(4, 2, true);
    for (std::size_t i = 0; i < t.film.size(); ++i) {
        t.film[i] = 100 + i;
        t.large_film[i] = 200 + i;
    }
    t.mutations = {7};
    t.burn_in_lum = {8};
    t.burn_in_samples = 9;
    t.large_lum = {10};
    t.large = {11};
    t.burn_in_lum2 = 0.5;
    t.omc_spp = 12;
    for (std::size_t i = 0; i < t.omc_sums.size(); ++i) {
        t.omc_sums[i] = 0.25 * double(i);
        t.burn_in_omc[i] = 2.0 + double(i);
    }
    for (std::size_t i = 0; i < t.burn_in_landed.size(); ++i)
        t.burn_in_landed[i] = 30 + i;
    Tally flat = t.to_tally();
    MltTally back = MltTally::shaped(4, 2, true);
    back.read(flat);
    EXPECT_EQ(back.film, t.film);
    EXPECT_EQ(back.large_film, t.large_film);
    EXPECT_EQ(back.mutations, std::vector<std::uint64_t>{7});
    EXPECT_EQ(back.burn_in_lum, std::vector<std::uint64_t>{8});
    EXPECT_EQ(back.burn_in_samples, 9u);
    EXPECT_EQ(back.large_lum, std::vector<std::uint64_t>{10});
    EXPECT_EQ(back.large, std::vector<std::uint64_t>{11});
    EXPECT_EQ(back.burn_in_lum2, 0.5);
    EXPECT_EQ(back.omc_spp, 12u);
    EXPECT_EQ(back.omc_sums, t.omc_sums);
    EXPECT_EQ(back.burn_in_landed, t.burn_in_landed);
    EXPECT_EQ(back.burn_in_omc, t.burn_in_omc);
    MltTally plain = MltTally::shaped(4, 2, false);
    EXPECT_THROW(plain.read(flat), std::logic_error);
    EXPECT_THROW(back.read(plain.to_tally()), std::logic_error);
    MltTally one_layer = MltTally::shaped(4, 1, true);
    EXPECT_THROW(one_layer.read(flat), std::logic_error);
    EXPECT_THROW(back.read(one_layer.to_tally()), std::logic_error);
}
