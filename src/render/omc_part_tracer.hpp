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
    // The chains' target: its cells of weight 0 are rendered whole
    // (src/render/omc_cells.hpp).
    const TargetBuffer* target = nullptr;
};

class OmcPartTracer {
  public:
    // Renders only the OMC part of part.split, with Sobol samples.
    OmcPartTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                  const OmcPart& part);

    // Adds n samples to each pixel but those of the cells it renders whole
    // (src/render/omc_cells.hpp), into the host's sums.
    void add_samples(std::uint32_t n) { add(n, false); }
    // Adds n samples to each pixel of those cells.
    void add_cell_samples(std::uint32_t n) { add(n, true); }
    // Samples per pixel: of the film but the cells; of the cells.
    std::uint32_t spp() const { return spp_; }
    std::uint32_t cell_spp() const { return cell_spp_; }
    // The pixels of the cells it renders whole.
    std::uint64_t cell_pixels() const;
    const PtNumbering& numbering() const { return passes_.numbering(); }
    std::uint64_t rays() const { return passes_.rays(); }
    std::uint64_t pixels() const { return passes_.pixels(); }
    // The samples per pixel (ints[0]), those of the cells' pixels (ints[1]),
    // and the sums of R, G, B per pixel (reals).
    Tally tally() const;

  private:
    void add(std::uint32_t n, bool cells_only);

    const ClContext& cl_;
    const TargetBuffer* target_;
    PtPasses passes_;
    std::uint32_t spp_ = 0, cell_spp_ = 0;
    ClBuffer scratch_;         // one band of the film on the device
    std::vector<double> sums_; // the film: sums of R, G, B per pixel
};

} // namespace smallmlt
