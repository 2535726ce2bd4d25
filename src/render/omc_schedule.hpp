// The split's OMC part beside the chains (src/render/split.hpp): its
// per-pixel samples, an OmcPartTracer, run after each MLT
// step at the rate that the split's rule gives, once the first step has
// measured a mutation's rays.
#pragma once
#include "render/omc_part_tracer.hpp"
#include "render/split.hpp"

#include <cstdint>
#include <functional>
#include <memory>

namespace smallmlt {

// The OMC part's samples per pixel in its next call, after `spp` of them on
// a film of `pixels`: a power of two, at most 16, at most spp / 16 and at
// most 2^18 paths (1 if even one sample per pixel is more), so that a call's
// fixed cost (a launch, and reading its band back) is spread over several
// samples, a call stays short, and what a render leaves owed at its end
// stays below a 16th of the samples.
std::uint32_t omc_chunk(std::uint32_t spp, std::uint64_t pixels);

class OmcSchedule {
  public:
    // `threads`: the chains' work-items; `effort`: --omc-effort.
    OmcSchedule(std::unique_ptr<OmcPartTracer> part, std::uint32_t threads, double effort);

    // After one MLT step. With chains, the part is owed the rule's rates of
    // samples per pixel (chosen at the first step from `costs`, with the
    // rays of one sample per pixel, and one more in the cells, that it
    // measures); without (Split::All,
    // or no light in the MLT part), a step's time: one path per thread.
    // Whole chunks run as soon as they are owed, so the samples, and the
    // image, do not depend on how steps are grouped into passes.
    void after_step(bool chains, const std::function<SplitCosts()>& costs);

    // Samples per pixel per MLT step, on the film and more in the cells the
    // OMC part renders whole (0 before the first step with chains).
    const OmcRates& rate() const { return rate_; }
    const OmcPartTracer& part() const { return *part_; }

  private:
    std::unique_ptr<OmcPartTracer> part_;
    std::uint32_t threads_;
    double effort_, owed_ = 0, owed_cells_ = 0;
    OmcRates rate_;
    bool measured_ = false;
};

} // namespace smallmlt
