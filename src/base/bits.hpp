// Integer helpers.
#pragma once
#include <cstdint>

namespace smallmlt {

inline bool is_power_of_two(std::uint64_t v) {
    return v != 0 && (v & (v - 1)) == 0;
}

} // namespace smallmlt
