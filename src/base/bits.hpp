// Integer helpers.
#pragma once
#include <cstdint>

namespace smallmlt {

inline bool is_power_of_two(std::uint64_t v) {
    return v != 0 && (v & (v - 1)) == 0;
}

// The exponent of a power of two v: v = 2^log2_of(v).
inline std::uint32_t log2_of(std::uint64_t v) {
    std::uint32_t e = 0;
    while (v > 1) {
        v >>= 1;
        ++e;
    }
    return e;
}

} // namespace smallmlt
