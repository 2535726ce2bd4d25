// The chains' target on the device (src/render/target.hpp): the weight w
// per cell and the cells, bound as the kernels' (weight, cells) pair. It
// starts as one cell of weight 1, the luminance; the two-stage target fixes
// its cells and weights from the burn-in's first half.
#pragma once
#include "device/ocl.hpp"
#include "render/ranks.hpp"
#include "shared_types.h"

#include <cstdint>
#include <vector>

namespace smallmlt {

class TargetBuffer {
  public:
    // Room for `bytes` of weights (kTargetMaxCells floats or one).
    TargetBuffer(const ClContext& cl, std::uint64_t bytes);
    // Cells and weights from the per-pixel RGB sums of the burn-in's MLT
    // parts (BurnInParts::rest) and the samples they hold, summed over every
    // rank, so that all ranks fix one target.
    void fix(RankGroup& ranks, std::uint32_t width, std::uint32_t height,
             const std::vector<double>& rgb_sums, std::uint64_t samples);
    const ClBuffer& weights() const { return weight_; }
    const TargetCells& cells() const { return cells_; }
    // The weights as the device holds them, one per cell (and 1 beyond).
    std::vector<float> read() const;

  private:
    const ClContext& cl_;
    ClBuffer weight_;
    TargetCells cells_;
};

inline void kernel_arg(ClKernel& k, cl_uint& i, const TargetBuffer& t) {
    k.set_arg(i++, t.weights());
    k.set_arg(i++, t.cells());
}

} // namespace smallmlt
