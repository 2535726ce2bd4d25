// Host-side checks of the shared struct layouts (SHARED_LAYOUT of
// cl/core/shared_types.h); a probe kernel (test/cl/probe.cl) reports the
// device's view in the same order, and test/test_layout.cpp compares the two.
#include "scene/shared_layout.hpp"

#include "scene/scene.hpp"

#include <cstddef>

namespace smallmlt {

#define SMALLMLT_CHECK_SIZE(T, size) static_assert(sizeof(T) == size, #T);
#define SMALLMLT_CHECK_OFFSET(T, field, off)                                                       \
    static_assert(offsetof(T, field) == off, #T "." #field);
SHARED_LAYOUT(SMALLMLT_CHECK_SIZE, SMALLMLT_CHECK_OFFSET)
#undef SMALLMLT_CHECK_OFFSET
#undef SMALLMLT_CHECK_SIZE
static_assert(kMaxDepth <= CHAIN_BOUNCES_MASK, "ChainValue.meta holds the live bounces");

std::vector<std::uint32_t> host_layout() {
    std::vector<std::uint32_t> v;
#define SMALLMLT_SIZE(T, size) v.push_back(sizeof(T));
#define SMALLMLT_OFFSET(T, field, off) v.push_back(offsetof(T, field));
    SHARED_LAYOUT(SMALLMLT_SIZE, SMALLMLT_OFFSET)
#undef SMALLMLT_OFFSET
#undef SMALLMLT_SIZE
    return v;
}

} // namespace smallmlt
