// The pass loop of `smallmlt render`: advances a method in passes of about a
// quarter second until the sample count or the time is reached, measures the
// error against a reference when the convergence log is due and there is an
// image (that time is not render time), draws progress, and stops after the current pass when
// interrupted (src/base/interrupt.hpp).
#pragma once
#include "render/convergence_log.hpp"
#include "render/integrator.hpp"
#include "render/progress.hpp"
#include "render/ranks.hpp"

#include <cstdint>
#include <optional>

namespace smallmlt {

constexpr double kPassSeconds = 0.25; // target duration of one pass

struct LoopLimits {
    std::optional<std::uint32_t> spp; // samples or mutations per pixel
    std::optional<double> time_s;     // or render seconds
    double pass_s = kPassSeconds;
};

struct LoopResult {
    double render_s = 0; // prepare and passes, without measuring
    bool interrupted = false;
    std::uint32_t passes = 0; // the same on every rank
};

// `log` may be null. With several ranks, every rank runs its share in
// lockstep passes: a signal on any rank stops all after the current pass,
// --time stops all when rank 0's time is up and each rank has rendered at
// least one pass, --spp when every rank's share is done (a rank done early
// waits).
LoopResult render_loop(Integrator& method, const LoopLimits& limits, ConvergenceLog* log,
                       Progress& progress, RankGroup& ranks);

} // namespace smallmlt
