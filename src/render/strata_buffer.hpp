// The strata on the device (src/render/strata.hpp): the tiles, each
// work-group's tile, what each tile's large steps weigh (StratumWeights) and
// the chains of a group, bound as the kernels' STRATA_ARGS
// (cl/mlt/mlt_step.cl).
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"
#include "render/strata.hpp"

#include <cstdint>
#include <vector>

namespace smallmlt {

class StrataBuffer {
  public:
    // The grid's tiles, every group in tile 0 and weights {0, 1} (expected
    // values, large steps uniform on the tile), in the plan's buffers;
    // group_chains chains to a work-group.
    StrataBuffer(const ClContext& cl, const MemoryPlan& plan, const StrataGrid& grid,
                 std::uint32_t group_chains);
    // The tiles of `grid` instead (at most as many as the plan's).
    void set_grid(const StrataGrid& grid);
    // Deals the work-groups to tiles: group g to tile tiles[g].
    void deal(const std::vector<std::uint32_t>& tiles);
    const std::vector<std::uint32_t>& group_tiles() const { return group_tile_host_; }
    std::uint32_t group_chains() const { return group_chains_; }
    // The weights per tile.
    void set_weights(const std::vector<StratumWeights>& weights);
    const ClBuffer& tiles() const { return tiles_; }
    const ClBuffer& group_tile() const { return group_tile_; }
    const ClBuffer& weights() const { return weights_; }

  private:
    const ClContext& cl_;
    ClBuffer tiles_, group_tile_, weights_;
    std::vector<std::uint32_t> group_tile_host_;
    std::uint32_t group_chains_;
};

inline void kernel_arg(ClKernel& k, cl_uint& i, const StrataBuffer& s) {
    k.set_arg(i++, s.tiles());
    k.set_arg(i++, s.group_tile());
    k.set_arg(i++, s.weights());
    k.set_arg(i++, cl_uint(s.group_chains()));
}

} // namespace smallmlt
