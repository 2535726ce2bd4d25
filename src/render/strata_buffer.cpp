#include "render/strata_buffer.hpp"

#include <stdexcept>

namespace smallmlt {

StrataBuffer::StrataBuffer(const ClContext& cl, const MemoryPlan& plan, const StrataGrid& grid,
                           std::uint32_t group_chains)
    : cl_(cl), tiles_(cl, CL_MEM_READ_ONLY, plan.bytes(Buffer::StrataTiles)),
      group_tile_(cl, CL_MEM_READ_ONLY, plan.bytes(Buffer::GroupTiles)),
      weights_(cl, CL_MEM_READ_ONLY, plan.bytes(Buffer::StrataWeights)),
      group_tile_host_(group_tile_.bytes() / sizeof(std::uint32_t), 0),
      group_chains_(group_chains) {
    set_grid(grid);
    group_tile_.fill_zero(cl);
    set_weights({});
}

void StrataBuffer::set_grid(const StrataGrid& grid) {
    std::vector<FilmTile> tiles(tiles_.bytes() / sizeof(FilmTile));
    if (grid.tiles.size() > tiles.size())
        throw std::logic_error("strata: more tiles than the memory plan's");
    std::copy(grid.tiles.begin(), grid.tiles.end(), tiles.begin());
    tiles_.write(cl_, tiles.data());
}

void StrataBuffer::deal(const std::vector<std::uint32_t>& tiles) {
    group_tile_host_ = tiles;
    group_tile_host_.resize(group_tile_.bytes() / sizeof(std::uint32_t), 0);
    group_tile_.write(cl_, group_tile_host_.data());
}

void StrataBuffer::set_weights(const std::vector<StratumWeights>& weights) {
    std::vector<StratumWeights> all(weights_.bytes() / sizeof(StratumWeights),
                                    StratumWeights{0.0f, 1.0f});
    std::copy(weights.begin(), weights.begin() + std::min(all.size(), weights.size()), all.begin());
    weights_.write(cl_, all.data());
}

} // namespace smallmlt
