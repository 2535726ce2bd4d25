// The MLT counters' rows (MLT_COUNTERS, cl/core/shared_types.h): each
// counter is joined over the work-groups' rows as the list says.
#include "render/mlt.hpp"

#include <gtest/gtest.h>

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
