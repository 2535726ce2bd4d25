// The chains' starts: burn-in samples drawn in proportion to their
// luminance by systematic resampling (Kitagawa 1996; Douc, Cappe and
// Moulines 2005) along the film. The samples are laid out tile by tile
// (src/render/strata.hpp; one tile without strata) and within a tile pixel
// by pixel in Morton order; the chains of a tile share one uniform number
// U and chain q of k takes the sample at (q + U) / k of the tile's
// cumulative weight. Each sample is then drawn, over U, exactly in
// proportion to its weight, as independent draws would be, but every run
// of samples along that order (every aligned square of 2^j x 2^j pixels
// among them) gets its expected number of chains within one. Independent
// draws scatter that number by its square root, and chains that have not
// yet mixed across the film keep the scatter as blotches in the image.
//
// The weights are the luminances in 64-bit fixed point under one exponent
// for all rounds, so the sums are exact and a sample keeps its share
// however small it is. The host keeps each round's luminances (4 bytes a
// sample) until the draw; which pixel a sample lies in follows from its
// number (src/render/burn_in.hpp, burn_in_film_sample).
#pragma once
#include "device/ocl.hpp"
#include "render/burn_in.hpp"
#include "render/strata.hpp"

#include <cstdint>
#include <vector>

namespace smallmlt {

// The pixels of a width x height film in the order of the draw: by tile of
// `grid`, then by Morton code (x and y interleaved) within the tile.
std::vector<std::uint32_t> start_pick_order(std::uint32_t width, std::uint32_t height,
                                            const StrataGrid& grid);

class StartPicks {
  public:
    // For burn-in rounds placed on a width x height film by `film`, tiles
    // `grid`.
    StartPicks(const BurnInFilm& film, std::uint32_t width, std::uint32_t height,
               const StrataGrid& grid);
    // Lays the samples out by the tiles of `grid` instead (the same film).
    void set_grid(const StrataGrid& grid);
    // Adds round `round`'s luminances, one per sample index (at most
    // film.per_round of them), rounds in increasing order.
    void add_round(std::uint32_t round, const std::vector<float>& lum);
    // The start (round, index) of each of `chains` chains: the chains of
    // work-group g (group_chains each) lie in tile group_tile[g], chains past
    // the groups in the last group's tile. Within a tile, the draw above with
    // U from the streams of `seed`; a tile whose samples found no light
    // draws them uniformly, and a tile without samples draws from the whole
    // film (mlt_init moves such a start to the tile's edge).
    std::vector<cl_uint2> draw(const std::vector<std::uint32_t>& group_tile,
                               std::uint32_t group_chains, std::uint32_t chains,
                               std::uint64_t seed) const;
    // The brightest sample's share of the luminance, and so of the chains
    // drawn over the whole film (0 without light).
    double largest_share() const { return total_ > 0 ? largest_ / total_ : 0.0; }

  private:
    struct Sample {
        std::uint32_t round, index;
        std::uint64_t weight;
    };
    // Calls f(round, index, weight) for each sample of `pixel`, in round
    // order; weight 1 where `uniform`.
    template <class F> void each_in_pixel(std::uint32_t pixel, bool uniform, F f) const;
    // The picks of `chains` (indices into `out`) from the samples of the
    // order's pixels [begin, end) under the uniform number u; false, and no
    // pick, if there are no samples there.
    bool draw_tile(std::size_t begin, std::size_t end, std::uint32_t u,
                   const std::vector<std::uint32_t>& chains, std::vector<cl_uint2>& out) const;

    BurnInFilm film_;
    std::uint32_t width_, height_, pixels_;
    std::vector<std::uint32_t> order_;      // pixels in the draw's order
    std::vector<std::uint32_t> tile_begin_; // per tile and one more: its first place in order_
    std::vector<std::uint32_t> residue_;    // per pixel: (g + offset) mod P of its samples g
    std::vector<std::uint32_t> rounds_;
    std::vector<std::vector<float>> lum_; // per round added
    int exponent_ = 0;                    // of the fixed-point weights
    double total_ = 0;                    // the luminances' sum
    double largest_ = 0;                  // the largest luminance
};

} // namespace smallmlt
