// Ordinary Monte Carlo (path tracing) on the device: owns the scene buffers,
// the per-pixel accumulators and the pt_render kernel (cl/kernels/pt.cl).
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "image/image.hpp"
#include "render/integrator.hpp"
#include "render/split.hpp"
#include "scene/device_scene.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace smallmlt {

// Where the path tracer's numbers come from: Owen-scrambled Sobol points
// (cl/sampling/sample_sobol.cl) or the independent stream of each sample's key
// (cl/sampling/sample_omc.cl, what burn-in and MLT's large steps use).
enum class PtSampler { Sobol, Random };
constexpr PtSampler kDefaultPtSampler = PtSampler::Sobol; // the command line's too

// Kernel files of the path-tracing program, in build order.
std::vector<std::string> pt_program_files(PtSampler sampler);

// Stratified per-pixel samples of the OMC part of a split (cl/path/path.cl), on
// the scene buffers of the MLT render it belongs to. Its film is on the host:
// the device holds one scratch band of omc_scratch_pixels, rendered band by
// band and added into the host's sums, so the split adds little to the
// device's memory (src/device/memory_plan.hpp).
struct OmcPart {
    Split split = Split::Direct;
    const SceneBuffers* scene = nullptr;
    // Each pixel's first Sobol sample number: those before it are the
    // burn-in's (cl/sampling/burnin_film.cl).
    std::uint32_t first_sample = 0;
};

class PathTracer : public Integrator {
  public:
    // The film's bands fit max_alloc_bytes (0: the device's largest
    // allocation). Sample k of a pixel is number offset + k * stride of its
    // sequence: rank r of R renders offset r, stride R (src/render/ranks.hpp).
    PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
               PtSampler sampler = kDefaultPtSampler, std::uint64_t max_alloc_bytes = 0,
               std::uint32_t sample_offset = 0, std::uint32_t sample_stride = 1);
    // Renders only the OMC part of part.split (Sobol samples).
    PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed, const OmcPart& part);

    void advance(std::uint32_t units) override { add_samples(units); }
    std::uint64_t units_for_spp(std::uint32_t spp, int rank, int ranks) const override;
    double spp_done() const override { return spp_; }
    std::string summary(double seconds) const override;

    // Adds n samples per pixel (numbered spp() .. spp() + n - 1).
    void add_samples(std::uint32_t n);
    std::uint32_t spp() const { return spp_; }
    std::uint32_t first_sample() const { return sample_offset_; }
    std::uint64_t rays() const;
    // Samples dropped because their radiance was NaN or infinite.
    std::uint64_t nonfinite() const;
    std::vector<std::string> notes() const override;
    std::uint64_t pixels() const { return std::uint64_t(ds_.frame.width) * ds_.frame.height; }

    // The sums of R, G, B per pixel (reals) and the samples per pixel (ints[0]).
    Tally tally() const override;
    Image image_from(const Tally& summed) const override; // mean radiance per pixel

  private:
    const ClContext& cl_;
    const DeviceScene& ds_;
    std::uint64_t seed_;
    std::uint32_t spp_ = 0;
    MemoryPlan plan_; // sizes of the buffers below (src/device/memory_plan.cpp)
    ClProgram program_;
    ClKernel kernel_;
    std::optional<SceneBuffers> own_scene_; // unless the OMC part shares its render's
    const SceneBuffers& scene_;
    std::vector<ClBuffer> bands_; // the film: sums of R, G, B per pixel
    ClBuffer stats_;              // PT_STAT_COUNT per work-group
    std::uint64_t band_pixels_;
    std::uint32_t sample_offset_, sample_stride_;
    std::vector<double> host_; // the OMC part's film (else empty: the film is bands_)
    // One kernel launch of n samples per pixel.
    void launch(std::uint32_t n);
    // Sums of the rows of stats.
    std::uint64_t stat(int which) const;
};

} // namespace smallmlt
