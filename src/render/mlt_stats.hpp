// The counters of an MLT render on the host: MLT_COUNTERS
// (cl/core/shared_types.h), joined over the work-groups' rows.
#pragma once
#include "shared_types.h"

#include <cstdint>
#include <vector>

namespace smallmlt {

// The counters, and the mutations the steps made.
struct MltStats {
    std::uint64_t mutations = 0;
#define SMALLMLT_STAT_MEMBER(NAME, member, JOIN) std::uint64_t member = 0;
    MLT_COUNTERS(SMALLMLT_STAT_MEMBER)
#undef SMALLMLT_STAT_MEMBER
    std::uint64_t large_lum = 0; // sum of the large steps' I(y), MLT_B_FRAC_BITS fixed point
};

// The counters of rows of MLT_STAT_COUNT words, each joined as
// MLT_COUNTERS says (a sum or a maximum).
MltStats mlt_join_rows(const std::vector<std::uint64_t>& rows);

} // namespace smallmlt
