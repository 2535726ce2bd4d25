// Size and field offsets of every shared struct as the host compiler lays
// them out, in the order of SHARED_LAYOUT (cl/core/shared_types.h).
#pragma once
#include "shared_types.h"

#include <vector>

namespace smallmlt {

std::vector<std::uint32_t> host_layout();

} // namespace smallmlt
