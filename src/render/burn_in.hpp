// Burn-in by OMC (Frolov and Galaktionov, section 3.1): how its samples are
// numbered, the weighted reservoir that picks the chains' starts on the
// device (cl/mlt/burnin.cl), and what its paths leave for the split's OMC part.
#pragma once
#include "device/ocl.hpp"
#include "device/scan.hpp"
#include "shared_types.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace smallmlt {

// OMC samples of a render are numbered by (round, index): round r < T of
// burn-in (T = --burn-in-iters) draws indices 0..N-1, and the fresh starts of
// --burn-in none are round T. Sample (r, i) is the path of key
// rng_key(omc_round_seed(omc_seed, r), i, 0) (cl/core/rng.h), so keys stay
// distinct however many rounds of however many threads run (a single 32-bit
// number r * N + i would wrap at 2^32 and repeat samples), and mlt_init
// regenerates a picked path from its round's seed and its index.
std::uint64_t omc_round_seed(std::uint64_t omc_seed, std::uint32_t round);
// The key of sample (round, index), as the kernels make it.
std::uint64_t omc_sample_key(std::uint64_t omc_seed, std::uint32_t round, std::uint32_t index);

// Where the burn-in's samples lie on the film (BurnInFilm,
// cl/sampling/burnin_film.cl): the first Sobol samples of the pixels' sequences under
// pixel_seed (the split's OMC part's), spread over the P pixels in the order
// (j * step) mod P, step coprime with P and near 0.618 P so that consecutive
// samples land far apart, from an offset in [0, P) drawn from offset_seed.
// Sample (r, i) is number g = r * per_round + i.
BurnInFilm burn_in_film(std::uint64_t pixel_seed, std::uint64_t offset_seed, std::uint32_t pixels,
                        std::uint32_t per_round);
// The pixel and the Sobol sample number of burn-in sample g, as the kernels
// place it.
std::pair<std::uint32_t, std::uint32_t> burn_in_film_sample(const BurnInFilm& f,
                                                            std::uint32_t pixels, std::uint64_t g);
// The first Sobol sample number that no pixel reaches in the burn-in's first
// `samples` samples: where the OMC part's path tracer begins.
std::uint32_t burn_in_film_end(const BurnInFilm& f, std::uint32_t pixels, std::uint64_t samples);

// The exponent e of the burn-in's fixed-point weights (cl/mlt/burnin.cl,
// burnin_weights): the largest with sum * 2^e < 2^62, where sum is the sum
// of a round's finite luminances (0 if it is not positive).
int burnin_weight_exponent(double sum);

// The reservoir's replacement threshold for a round of luminance sum s, when
// the sums of all rounds so far, this one included, make `total`: 2^32 s /
// total rounded (2^32: always), or, while total is 0 (no light yet),
// 2^32 / (round + 1), so that picks stay uniform over all samples so far.
std::uint64_t burnin_replace_threshold(double s, double total, std::uint32_t round);

// Which stratum (src/render/strata.hpp) each sample of a round and each
// chain is in: sample i of the round in tile sample_tile[i], chain j in tile
// group_tile[j / group_chains] on the device. The default is one stratum.
struct PickStrata {
    const std::vector<std::uint32_t>* sample_tile = nullptr; // null: every sample in tile 0
    const ClBuffer* group_tile = nullptr;                    // null: every chain in tile 0
    std::uint32_t group_chains = 0xFFFFFFFFu;
};

// The burn-in's chain starts, on the device, pooled over rounds by a
// weighted reservoir (cl/mlt/burnin.cl): in each round, every chain replaces
// its pick with probability s_r / (s_0 + .. + s_r), the sums of its
// stratum's luminances, by a sample of the round in its stratum drawn in
// proportion to luminance (fixed-point weights in the order of the strata,
// their prefix sum, binary search within the stratum's part). After the
// last round each chain's pick is an independent draw from all the rounds'
// samples of its stratum in proportion to luminance (uniform among them if
// none had light).
class BurnInPicker {
  public:
    // For rounds of up to max_n samples in `tiles` strata, with room for
    // tile_room (the memory plan's); `program` holds cl/core/rng.h,
    // cl/core/scan.cl (SCAN_T ulong) and cl/mlt/burnin.cl.
    BurnInPicker(const ClContext& cl, cl_program program, std::uint32_t max_n,
                 std::uint32_t tiles = 1, std::uint32_t tile_room = 1);
    // Adds the next round, the samples of burn-in round `round`, of n samples
    // whose luminances are `lum` on the device and `host` (the same values,
    // read back): each of the `count` picks (uint2 (round, index) each, in
    // `picks`) is replaced as above, with the streams of `seed` and the
    // round. `scan` (n x 8 bytes) is left holding the prefix sums of the
    // round's weights in the strata's order.
    void add_round(const ClBuffer& lum, const std::vector<float>& host, std::uint32_t n,
                   const ClBuffer& scan, std::uint64_t seed, std::uint32_t round,
                   std::uint32_t count, const ClBuffer& picks, const PickStrata& strata = {});
    std::uint32_t rounds() const { return rounds_; }

  private:
    const ClContext& cl_;
    DeviceScan scan_;
    ClKernel weights_, pick_;
    ClBuffer order_, first_, replace_, one_tile_;
    std::uint32_t rounds_ = 0;
    std::vector<double> total_;       // per stratum, luminance sum of the rounds so far
    std::vector<std::uint32_t> seen_; // per stratum, rounds that had samples in it
};

// What the burn-in's paths leave for a split (src/render/split.hpp): per
// pixel and channel the sums of their OMC and MLT parts, and per pixel how
// many landed there (cl/kernels/mlt.cl, mlt_luminance, writes 8 floats per
// path: the OMC part's RGB, the pixel's bits, the MLT part's RGB, its rays;
// a dropped sample's parts are 0).
struct BurnInParts {
    std::vector<double> omc, rest;       // per pixel and channel
    std::vector<double> omc_y2, rest_y2; // per pixel: sums of squared luminances
    std::vector<std::uint64_t> count;    // per pixel
    double behind_specular = 0; // sum of the paths' light behind smooth transmitters (path.cl)
    explicit BurnInParts(std::uint64_t pixels = 0)
        : omc(3 * pixels, 0.0), rest(3 * pixels, 0.0), omc_y2(pixels, 0.0), rest_y2(pixels, 0.0),
          count(pixels, 0) {}
    // Adds a round's paths, in sample order.
    void add(const std::vector<float>& samples);
    // V_o (or V_m) of split.hpp, sum_p Var_p over the P pixels of one
    // sample's luminance, from a part's sums per pixel (`sums`, RGB; `y2`,
    // squared luminances) and the samples per pixel: P times the mean of the
    // unbiased sample variances of the pixels that have two samples or more
    // (which pixels those are does not depend on what they hold: where paths
    // land is fixed by cl/sampling/burnin_film.cl). Subtracting sum_p mu_p^2 from the second moment
    // instead is unbiased too, but at a few samples per pixel it is the difference of two large,
    // noisy sums and came out 0 (no OMC samples at all) for a light's edges at 512x512. Without
    // such pixels: the second moment, an overestimate.
    double variance(const std::vector<double>& sums, const std::vector<double>& y2) const;
    // A part's mean luminance per path, from its sums per pixel (`sums`, RGB).
    double mean(const std::vector<double>& sums) const;
    // The share of the MLT part's light, found or behind smooth
    // transmitters, that lay behind them: s / (s + b_m), s and b_m the
    // means of behind_specular and of the MLT part (0 where both are 0).
    double behind_specular_share() const;
};

} // namespace smallmlt
