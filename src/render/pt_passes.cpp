#include "render/pt_passes.hpp"

#include "render/programs.hpp"

#include <algorithm>

namespace smallmlt {

std::vector<std::string> pt_program_files(PtSampler sampler) {
    ProgramSpec spec;
    spec.sample_source =
        sampler == PtSampler::Sobol ? "cl/sampling/sample_sobol.cl" : "cl/sampling/sample_omc.cl";
    return program_files(spec);
}

PtPasses::PtPasses(const ClContext& cl, const DeviceScene& ds, const SceneBuffers& scene,
                   PtSampler sampler, const std::string& defines, PtNumbering numbering,
                   std::uint64_t band_pixels, std::uint64_t stats_bytes,
                   const TargetBuffer* omc_target)
    : cl_(cl), ds_(ds), scene_(scene),
      program_(cl.build(pt_program_files(sampler), ds.layout.defines() + defines)),
      kernel_(program_.p, "pt_render"), stats_(cl, CL_MEM_READ_WRITE, stats_bytes),
      numbering_(numbering), band_pixels_(band_pixels), omc_target_(omc_target) {
    stats_.fill_zero(cl_);
}

void PtPasses::add_samples(std::uint32_t n,
                           const std::function<const ClBuffer&(std::uint64_t)>& band,
                           const std::function<void(std::uint64_t, std::uint64_t)>& after,
                           bool cells_only) {
    // A device that ends loops after a count per work-item
    // (DeviceInfo::loop_iteration_limit) gets one sample per launch: a path
    // stays well within the count, a pixel's many samples would not. The
    // film is the same, bit for bit: a pixel adds its samples in the same
    // order (the OMC part's host sums, added per launch, round otherwise).
    const std::uint32_t per_launch = cl_.device().loop_iteration_limit ? 1u : n;
    for (std::uint32_t done = 0; done < n; done += per_launch)
        launch(std::min(per_launch, n - done), band, after, cells_only);
}

void PtPasses::launch(std::uint32_t n, const std::function<const ClBuffer&(std::uint64_t)>& band,
                      const std::function<void(std::uint64_t, std::uint64_t)>& after,
                      bool cells_only) {
    cl_ulong seed = numbering_.seed;
    std::uint32_t& taken = cells_only ? cell_spp_ : spp_;
    cl_uint first_sample = taken, count = n;
    for (std::uint64_t first = 0, b = 0; first < pixels(); first += band_pixels_, ++b) {
        std::uint64_t size = std::min(band_pixels_, pixels() - first);
        auto set = [&](const auto&... omc_target) {
            kernel_.set_args(scene_, seed, first_sample, count, cl_uint(numbering_.offset),
                             cl_uint(numbering_.stride), numbering_.late, cl_uint(first),
                             cl_uint(size), band(b), stats_, omc_target...);
        };
        if (omc_target_)
            set(*omc_target_, cl_uint(cells_only));
        else
            set();
        kernel_.enqueue(cl_, size);
        after(first, size);
    }
    cl_.finish("kernel pt_render over " + std::to_string(pixels()) + " pixels");
    taken += n;
}

std::uint64_t PtPasses::stat(int which) const {
    std::vector<cl_ulong> rows(stats_.bytes() / sizeof(cl_ulong));
    stats_.read(cl_, rows.data());
    std::uint64_t sum = 0;
    for (std::size_t r = 0; r + PT_STAT_COUNT <= rows.size(); r += PT_STAT_COUNT)
        sum += rows[r + which];
    return sum;
}

std::uint64_t PtPasses::nonfinite() const {
    return stat(PT_STAT_NONFINITE);
}

std::uint64_t PtPasses::rays() const {
    return stat(PT_STAT_RAYS);
}

} // namespace smallmlt
