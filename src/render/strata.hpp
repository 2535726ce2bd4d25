// Stratified MLT: the film cut into square tiles (strata), each with its own
// chains, whose film numbers are the tile's unit square (cl/sampling/strata.cl),
// and its own normalization. Stratification by image tiles follows Gruson,
// West and Hachisuka, "Stratified Markov Chain Monte Carlo Light Transport"
// (2020); here in the simple form that the burn-in permits: tile s's image
// is B_s times its chains' histogram, where B_s is the mean of I over the
// tile, estimated by the burn-in's OMC samples that land in it and by its
// chains' large steps (each uniform on the tile's pixels where the target
// is above 0, StratumWeights). Each tile's brightness is
// then an estimate independent of its neighbours', and the chains move light
// only within their tile. One tile, the whole film, is plain MLT.
//
// The chains are dealt to tiles in whole work-groups, so that each group's
// row of counters (its large steps' count and luminance) belongs to one tile:
// every tile gets one group, and the rest go in proportion to the tile's
// share of b from the first round of burn-in (largest remainders).
#pragma once
#include "shared_types.h"

#include <cstdint>
#include <vector>

namespace smallmlt {

// The density, against the uniform one, of a large step's film position on
// the pixels of a tile where the target is above 0, a share `share` of the
// tile's (StratumWeights, cl/core/shared_types.h): (1 - (1 - A)^tries) / A,
// and 1 where A is 0 or 1.
double strata_large_density(double share);

// --strata auto: the tile side that the rule below picks.
constexpr std::uint32_t kStrataAuto = 0xFFFFFFFFu;
// --strata piles: auto's tiles where the burn-in piles the chains on one
// path (strata_for_piles, src/render/mlt_options.hpp), else none.
constexpr std::uint32_t kStrataPiles = 0xFFFFFFFEu;
// Work-groups of chains per tile that the rule leaves on average, so that
// most of them are dealt by brightness.
constexpr std::uint32_t kStrataGroupsPerTile = 4;

// The tiles of a film of width x height pixels, side `side` pixels (the last
// row and column may be narrower); side 0: one tile, the whole film.
struct StrataGrid {
    std::vector<FilmTile> tiles;
    std::vector<std::uint32_t> pixel_tile; // per pixel
    std::uint32_t count() const { return std::uint32_t(tiles.size()); }
    // The tile's share of the film's pixels: its part of the film's measure.
    double area(std::uint32_t tile, std::uint64_t pixels) const;
};
StrataGrid strata_grid(std::uint32_t width, std::uint32_t height, std::uint32_t side);

// How many tiles of side `side` a film has (side 0: 1).
std::uint32_t strata_count(std::uint32_t width, std::uint32_t height, std::uint32_t side);

// The side of --strata `asked` (0: none; kStrataAuto and kStrataPiles: the
// smallest side of at least 8 pixels whose tiles number at most groups /
// kStrataGroupsPerTile, or 0 if even the whole film is one), for `groups`
// work-groups of chains.
// Throws UsageError if an asked side has more tiles than groups.
std::uint32_t strata_side(std::uint32_t asked, std::uint32_t width, std::uint32_t height,
                          std::uint32_t groups);

// Work-groups per tile: one each, and the rest of `groups` in proportion to
// `weight` (largest remainders, ties to the lower tile; all weights 0: evenly).
// Needs groups >= weight.size().
std::vector<std::uint32_t> strata_groups(const std::vector<double>& weight, std::uint32_t groups);

// The tile of each of `count` work-groups, dealt in tile order as `groups`
// says (groups past their sum, if any, to the last tile).
std::vector<std::uint32_t> strata_group_tiles(const std::vector<std::uint32_t>& groups,
                                              std::uint32_t count);

} // namespace smallmlt
