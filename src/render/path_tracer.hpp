// Ordinary Monte Carlo (path tracing) on the device, the standalone method:
// its own scene buffers and film bands, and path tracing's pass code
// (src/render/pt_passes.hpp), which the split's OMC part shares
// (src/render/omc_part_tracer.hpp).
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "image/image.hpp"
#include "render/integrator.hpp"
#include "render/pt_passes.hpp"
#include "scene/device_scene.hpp"

#include <cstdint>
#include <vector>

namespace smallmlt {

class PathTracer : public Integrator {
  public:
    // The film's bands fit max_alloc_bytes (0: the device's largest
    // allocation). Sample k of a pixel is number offset + k * stride of its
    // sequence: rank r of R renders offset r, stride R (src/render/ranks.hpp).
    PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
               PtSampler sampler = kDefaultPtSampler, std::uint64_t max_alloc_bytes = 0,
               std::uint32_t sample_offset = 0, std::uint32_t sample_stride = 1);
    void advance(std::uint32_t units) override { add_samples(units); }
    std::uint64_t units_for_spp(std::uint32_t spp, int rank, int ranks) const override;
    double spp_done() const override { return passes_.spp(); }
    std::string summary(double seconds) const override;

    // Adds n samples per pixel (numbered spp() .. spp() + n - 1).
    void add_samples(std::uint32_t n);
    std::uint32_t spp() const { return passes_.spp(); }
    std::uint64_t rays() const { return passes_.rays(); }
    // Samples dropped because their radiance was NaN or infinite.
    std::uint64_t nonfinite() const { return passes_.nonfinite(); }
    std::vector<std::string> notes() const override;
    std::uint64_t pixels() const { return passes_.pixels(); }

    // The sums of R, G, B per pixel (reals) and the samples per pixel (ints[0]).
    Tally tally() const override;
    Image image_from(const Tally& summed) const override; // mean radiance per pixel

  private:
    const ClContext& cl_;
    const DeviceScene& ds_;
    MemoryPlan plan_; // sizes of the buffers below (src/device/memory_plan.cpp)
    SceneBuffers scene_;
    PtPasses passes_;
    std::vector<ClBuffer> bands_; // the film: sums of R, G, B per pixel
};

} // namespace smallmlt
