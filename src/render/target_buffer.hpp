// The chains' target on the device (src/render/target.hpp): the weight w
// per cell and the cells, bound as the kernels' (weight, cells) pair. It
// starts as one cell of weight 1, the luminance; the two-stage target and
// the cells of the OMC part (src/render/omc_cells.hpp) fix its cells and
// weights from the burn-in's first half.
#pragma once
#include "device/ocl.hpp"
#include "render/burn_in.hpp"
#include "render/omc_cells.hpp"
#include "render/ranks.hpp"
#include "shared_types.h"

#include <cstdint>
#include <vector>

namespace smallmlt {

class TargetBuffer {
  public:
    // Room for `bytes` of weights (kTargetMaxCells floats or one).
    TargetBuffer(const ClContext& cl, std::uint64_t bytes);
    // Cells and weights from the burn-in's parts, summed over every rank so
    // that all ranks fix one target: the two-stage target's weights where
    // `two_stage` (else 1), and 0 in the cells the OMC part renders whole
    // where `omc`, for chains whose steps are `steps` (omc_cells, which
    // then writes `stay` where given; without `omc` it is left as it was).
    void fix(RankGroup& ranks, std::uint32_t width, std::uint32_t height, const BurnInParts& parts,
             bool two_stage, bool omc, const ChainSteps& steps, ChainsStay* stay = nullptr);
    // Cells `cells` of a width x height film with weights `w` (one per cell),
    // 0 where `whole` (per cell; empty: none) says the OMC part renders the
    // cell whole.
    void set(const TargetCells& cells, std::uint32_t width, std::uint32_t height,
             std::vector<float> w, const std::vector<bool>& whole);
    // The cells of weight 0 and the pixels they cover.
    std::uint32_t omc_cells() const { return omc_cells_; }
    std::uint64_t omc_pixels() const { return omc_pixels_; }
    // Whether pixel (x, y) lies in a cell of weight 0.
    bool omc_pixel(std::uint32_t x, std::uint32_t y) const;
    // The share of tile t's pixels that lie in cells of weight above 0.
    double chains_share(const FilmTile& t) const;
    const ClBuffer& weights() const { return weight_; }
    const TargetCells& cells() const { return cells_; }
    // The weights as the device holds them, one per cell (and 1 beyond).
    std::vector<float> read() const;

  private:
    const ClContext& cl_;
    ClBuffer weight_;
    TargetCells cells_;
    std::vector<bool> whole_; // per cell: weight 0 (empty: none)
    std::uint32_t omc_cells_ = 0;
    std::uint64_t omc_pixels_ = 0;
};

inline void kernel_arg(ClKernel& k, cl_uint& i, const TargetBuffer& t) {
    k.set_arg(i++, t.weights());
    k.set_arg(i++, t.cells());
}

} // namespace smallmlt
