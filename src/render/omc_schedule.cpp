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
    const std::uint64_t p = part_->pixels(), pc = part_->cell_pixels();
    if (!chains) {
        owed_ += double(threads_) / double(p);
        owed_cells_ += pc > 0 ? double(threads_) / double(p) : 0.0;
    } else if (!measured_) {
        measured_ = true;
        SplitCosts c = costs();
        // One sample per pixel, on the film and in the cells, measures
        // their rays (and is kept).
        part_->add_samples(1);
        const double film = double(part_->rays());
        c.omc_rays = p > pc ? film / double(p - pc) : 0;
        if (pc > 0) {
            part_->add_cell_samples(1);
            c.cell_rays = (double(part_->rays()) - film) / double(pc);
        }
        c.cell_pixels = double(pc);
        rate_ = omc_samples_per_step(c, effort_);
        owed_ = std::max(0.0, rate_.film - 1);
        owed_cells_ = pc > 0 ? std::max(0.0, rate_.cells - 1) : 0.0;
    } else {
        owed_ += rate_.film;
        owed_cells_ += rate_.cells;
    }
    for (std::uint32_t k = omc_chunk(part_->spp(), p); owed_ >= k; k = omc_chunk(part_->spp(), p)) {
        part_->add_samples(k);
        owed_ -= k;
    }
    for (std::uint32_t k = omc_chunk(part_->cell_spp(), pc); owed_cells_ >= k;
         k = omc_chunk(part_->cell_spp(), pc)) {
        part_->add_cell_samples(k);
        owed_cells_ -= k;
    }
}

} // namespace smallmlt
