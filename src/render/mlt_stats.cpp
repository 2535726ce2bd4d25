#include "render/mlt_stats.hpp"

#include <algorithm>

namespace smallmlt {

MltStats mlt_join_rows(const std::vector<std::uint64_t>& rows) {
    MltStats s;
    for (std::size_t r = 0; r + MLT_STAT_COUNT <= rows.size(); r += MLT_STAT_COUNT) {
#define SMALLMLT_JOIN_SUM(a, b) ((a) + (b))
#define SMALLMLT_JOIN_MAX(a, b) std::max((a), (b))
#define SMALLMLT_JOIN_ROW(NAME, member, JOIN)                                                      \
    s.member = SMALLMLT_JOIN_##JOIN(s.member, rows[r + MLT_STAT_##NAME]);
        MLT_COUNTERS(SMALLMLT_JOIN_ROW)
#undef SMALLMLT_JOIN_ROW
#undef SMALLMLT_JOIN_MAX
#undef SMALLMLT_JOIN_SUM
        s.large_lum += rows[r + MLT_STAT_LARGE_LUM];
    }
    return s;
}

} // namespace smallmlt
