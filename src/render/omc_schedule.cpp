#include "render/omc_schedule.hpp"

#include <algorithm>

namespace smallmlt {

std::uint32_t omc_chunk(std::uint32_t spp, std::uint64_t pixels) {
    std::uint32_t k = 1;
    while (k < 16 && 32 * k <= spp && 2 * k * pixels <= (1u << 18))
        k *= 2;
    return k;
}

OmcSchedule::OmcSchedule(std::unique_ptr<OmcPartTracer> part, std::uint32_t threads, double effort)
    : part_(std::move(part)), threads_(threads), effort_(effort) {}

void OmcSchedule::after_step(bool chains, const std::function<SplitCosts()>& costs) {
    const std::uint64_t p = part_->pixels();
    if (!chains) {
        owed_ += double(threads_) / double(p);
    } else if (rate_ == 0 && part_->spp() == 0) {
        SplitCosts c = costs();
        // One sample per pixel measures its rays (and is kept).
        part_->add_samples(1);
        c.omc_rays = double(part_->rays()) / c.pixels;
        rate_ = omc_samples_per_step(c, effort_);
        owed_ = std::max(0.0, rate_ - 1);
    } else {
        owed_ += rate_;
    }
    for (std::uint32_t k = omc_chunk(part_->spp(), p); owed_ >= k; k = omc_chunk(part_->spp(), p)) {
        part_->add_samples(k);
        owed_ -= k;
    }
}

} // namespace smallmlt
