#include "render/omc_part_tracer.hpp"

#include "device/memory_plan.hpp"

namespace smallmlt {

OmcPartTracer::OmcPartTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                             const OmcPart& part)
    : cl_(cl), target_(part.target),
      passes_(cl, ds, *part.scene, PtSampler::Sobol,
              split_defines(part.split) + "#define PT_OMC_PART 1\n",
              {seed, part.start.first, 1, part.start.late},
              omc_scratch_pixels(std::uint64_t(ds.frame.width) * ds.frame.height),
              plan_pt(ds, cl.device().max_alloc_bytes).bytes(Buffer::Stats), part.target),
      scratch_(cl, CL_MEM_READ_WRITE, passes_.band_pixels() * kPtFilmPixelBytes),
      sums_(3 * passes_.pixels(), 0.0) {}

std::uint64_t OmcPartTracer::cell_pixels() const {
    return target_ ? target_->omc_pixels() : 0;
}

void OmcPartTracer::add(std::uint32_t n, bool cells_only) {
    (cells_only ? cell_spp_ : spp_) += n;
    std::vector<float> band(3 * passes_.band_pixels());
    passes_.add_samples(
        n,
        [&](std::uint64_t) -> const ClBuffer& {
            scratch_.fill_zero(cl_);
            return scratch_;
        },
        [&](std::uint64_t first, std::uint64_t size) {
            scratch_.read(cl_, band.data());
            for (std::size_t i = 0; i < 3 * size; ++i)
                sums_[3 * first + i] += band[i];
        },
        cells_only);
}

Tally OmcPartTracer::tally() const {
    Tally t;
    t.ints = {spp_, cell_spp_};
    t.reals = sums_;
    return t;
}

} // namespace smallmlt
