// The pass code of ordinary Monte Carlo on the device, shared by its two
// roles: the standalone path tracer (src/render/path_tracer.hpp) and the
// split's OMC part (src/render/omc_part_tracer.hpp). It owns the pt_render
// kernel (cl/kernels/pt.cl), its per-work-group counters and the numbering
// of samples; the roles own the film.
#pragma once
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "render/target_buffer.hpp"
#include "scene/device_scene.hpp"
#include "shared_types.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace smallmlt {

// Where the path tracer's numbers come from: Owen-scrambled Sobol points
// (cl/sampling/sample_sobol.cl) or the independent stream of each sample's key
// (cl/sampling/sample_omc.cl, what burn-in and MLT's large steps use).
enum class PtSampler { Sobol, Random };
constexpr PtSampler kDefaultPtSampler = PtSampler::Sobol; // the command line's too

// Kernel files of the path-tracing program, in build order.
std::vector<std::string> pt_program_files(PtSampler sampler);

// Sample k of a pixel is number offset + k * stride of its sequence, plus
// one for the pixels of `late`: rank r of R renders offset r, stride R
// (src/render/ranks.hpp); the OMC part starts after the burn-in's samples
// (src/render/burn_in.hpp, burn_in_omc_start).
struct PtNumbering {
    std::uint64_t seed = 0;
    std::uint32_t offset = 0, stride = 1;
    LatePixels late{};
};

class PtPasses {
  public:
    // `defines` after the scene layout's; the film in bands of band_pixels;
    // stats_bytes from the memory plan. The OMC part (PT_OMC_PART) takes
    // the chains' target, whose cells of weight 0 it renders whole.
    PtPasses(const ClContext& cl, const DeviceScene& ds, const SceneBuffers& scene,
             PtSampler sampler, const std::string& defines, PtNumbering numbering,
             std::uint64_t band_pixels, std::uint64_t stats_bytes,
             const TargetBuffer* omc_target = nullptr);

    // Adds n samples per pixel (numbered spp() .. spp() + n - 1), band by
    // band: band b's pixels go to band(b); after(first, size) runs once its
    // launch is queued (the OMC part reads its scratch band there). With
    // `cells_only`, only the pixels of the OMC part's cells take them,
    // numbered cell_spp() on: each pixel's numbers stay consecutive, so its
    // Sobol points keep their stratification.
    void add_samples(std::uint32_t n, const std::function<const ClBuffer&(std::uint64_t)>& band,
                     const std::function<void(std::uint64_t, std::uint64_t)>& after,
                     bool cells_only = false);

    std::uint32_t spp() const { return spp_; }
    std::uint32_t cell_spp() const { return cell_spp_; }
    const PtNumbering& numbering() const { return numbering_; }
    std::uint64_t pixels() const { return std::uint64_t(ds_.frame.width) * ds_.frame.height; }
    std::uint64_t band_pixels() const { return band_pixels_; }
    std::uint64_t rays() const;
    // Samples dropped because their radiance was NaN or infinite.
    std::uint64_t nonfinite() const;

  private:
    const ClContext& cl_;
    const DeviceScene& ds_;
    const SceneBuffers& scene_;
    ClProgram program_;
    ClKernel kernel_;
    ClBuffer stats_; // PT_STAT_COUNT per work-group
    PtNumbering numbering_;
    std::uint64_t band_pixels_;
    const TargetBuffer* omc_target_;
    std::uint32_t spp_ = 0, cell_spp_ = 0;
    void launch(std::uint32_t n, const std::function<const ClBuffer&(std::uint64_t)>& band,
                const std::function<void(std::uint64_t, std::uint64_t)>& after, bool cells_only);
    std::uint64_t stat(int which) const; // sum of the rows of stats
};

} // namespace smallmlt
