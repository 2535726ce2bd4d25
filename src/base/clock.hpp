// Wall-clock time of the host, for render time and throughput figures.
#pragma once
#include <chrono>

namespace smallmlt {

using Clock = std::chrono::steady_clock;

// Seconds from t0 to now.
inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

} // namespace smallmlt
