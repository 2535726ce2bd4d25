// Stratified per-pixel samples of the OMC part of a split (cl/path/path.cl),
// on the scene buffers of the MLT render it belongs to: path tracing's pass
// code (src/render/pt_passes.hpp) with its film on the host. The device
// holds one scratch band of omc_scratch_pixels, rendered band by band and
// added into the host's sums, so the split adds little to the device's
// memory (src/device/memory_plan.hpp).
#pragma once
#include "render/burn_in.hpp"
#include "render/integrator.hpp"
#include "render/pt_passes.hpp"
#include "render/split.hpp"

#include <cstdint>
#include <vector>

namespace smallmlt {

struct OmcPart {
    Split split = Split::Direct;
    const SceneBuffers* scene = nullptr;
    // Each pixel's first Sobol sample number: those before it are the
    // burn-in's (cl/sampling/burnin_film.cl).
    SequenceStart start;
};

class OmcPartTracer {
  public:
    // Renders only the OMC part of part.split, with Sobol samples.
    OmcPartTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                  const OmcPart& part);

    // Adds n samples per pixel into the host's sums.
    void add_samples(std::uint32_t n);
    std::uint32_t spp() const { return passes_.spp(); }
    const PtNumbering& numbering() const { return passes_.numbering(); }
    std::uint64_t rays() const { return passes_.rays(); }
    std::uint64_t pixels() const { return passes_.pixels(); }
    // The samples per pixel (ints[0]) and the sums of R, G, B per pixel
    // (reals), as PathTracer::tally.
    Tally tally() const;

  private:
    const ClContext& cl_;
    PtPasses passes_;
    ClBuffer scratch_;         // one band of the film on the device
    std::vector<double> sums_; // the film: sums of R, G, B per pixel
};

} // namespace smallmlt
