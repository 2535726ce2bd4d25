// Burn-in by OMC (Frolov and Galaktionov, section 3.1): how its samples are
// numbered and placed on the film, and what its paths leave for the split's
// OMC part. The chains' starts drawn from them: start_picks.hpp.
#pragma once
#include "shared_types.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace smallmlt {

// OMC samples of a render are numbered by (round, index): round r < T of
// burn-in (T = --burn-in-iters) draws indices 0..N-1, and the fresh starts of
// --burn-in none are round T. Sample (r, i) is number g = r N + i (64-bit,
// so it does not wrap), and g fixes its pixel and its Sobol sample there
// (burn_in_film_sample), from which mlt_init regenerates a picked path.

// Where the burn-in's samples lie on the film (BurnInFilm,
// cl/sampling/burnin_film.cl): the first Sobol samples of the pixels' sequences under
// pixel_seed (the split's OMC part's), spread over the P pixels in the order
// (j * step) mod P, step coprime with P and near 0.618 P so that consecutive
// samples land far apart, from an offset in [0, P) drawn from offset_seed.
// Sample (r, i) is number g = r * per_round + i.
BurnInFilm burn_in_film(std::uint64_t pixel_seed, std::uint64_t offset_seed, std::uint32_t pixels,
                        std::uint32_t per_round);
// The pixel and the Sobol sample number of burn-in sample g, as the kernels
// place it (cl/core/burnin_order.h).
std::pair<std::uint32_t, std::uint32_t> burn_in_film_sample(const BurnInFilm& f,
                                                            std::uint32_t pixels, std::uint64_t g);

// Where the pixels' Sobol sequences stand after a burn-in: the OMC part's
// path tracer goes on from number `first`, one later in the `late` pixels.
struct SequenceStart {
    std::uint32_t first = 0;
    LatePixels late{};
    // Pixel p's first number.
    std::uint32_t at(std::uint32_t pixels, std::uint32_t p) const;
};
// After the burn-in's first `samples` samples.
SequenceStart burn_in_omc_start(const BurnInFilm& f, std::uint32_t pixels, std::uint64_t samples);

struct BurnInWhole;

// What the burn-in's paths leave for a split (src/render/split.hpp): per
// pixel and channel the sums of their OMC and MLT parts, and per pixel how
// many landed there (cl/kernels/mlt.cl, mlt_luminance, writes 8 floats per
// path: the OMC part's RGB, the pixel's bits, the MLT part's RGB, its rays;
// a dropped sample's parts are 0).
struct BurnInParts {
    std::vector<double> omc, rest;       // per pixel and channel
    std::vector<double> omc_y2, rest_y2; // per pixel: sums of squared luminances
    std::vector<std::uint64_t> count;    // per pixel
    // Per pixel: sums of the paths' light behind smooth transmitters (path.cl).
    std::vector<double> behind;
    explicit BurnInParts(std::uint64_t pixels = 0)
        : omc(3 * pixels, 0.0), rest(3 * pixels, 0.0), omc_y2(pixels, 0.0), rest_y2(pixels, 0.0),
          count(pixels, 0), behind(pixels, 0.0) {}
    // Adds a round's paths, in sample order; with `in`, only those that
    // landed in a pixel p with (*in)[p].
    void add(const std::vector<float>& samples, const std::vector<bool>* in = nullptr);
    // Adds other paths of the same film as whole paths, to the OMC part's
    // sums and the counts: for the image of path tracing alone, which adds
    // the two parts (the squared sums and `behind` stay those of the rest).
    void add_whole(const BurnInWhole& other);
    // V_o (or V_m) of split.hpp over all pixels (PixelVariance), from a
    // part's sums per pixel (`sums`, RGB; `y2`, squared luminances).
    double variance(const std::vector<double>& sums, const std::vector<double>& y2) const;
    // The luminance of a part's sums (`sums`, RGB) at pixel p.
    double luminance(const std::vector<double>& sums, std::size_t p) const;
    // A part's mean luminance per path, from its sums per pixel (`sums`, RGB).
    double mean(const std::vector<double>& sums) const;
    // The share of the MLT part's light, found or behind smooth
    // transmitters, that lay behind them: behind_share of the means of
    // `behind` and of the MLT part.
    double behind_specular_share() const;
};

// Paths' light per pixel, both parts together (RGB), and their count: the
// image's share of burn-in rounds whose parts are no longer needed, kept in
// 32 bytes a pixel, not BurnInParts' 80.
struct BurnInWhole {
    std::vector<double> rgb;
    std::vector<std::uint64_t> count;
    BurnInWhole() = default;
    explicit BurnInWhole(const BurnInParts& parts);
};

// V_o (or V_m) of split.hpp, sum_p Var_p over P pixels of one sample's
// luminance, gathered pixel by pixel from a part's sums: P times the mean of
// the unbiased sample variances of the pixels that have two samples or more
// (which pixels those are does not depend on what they hold: where paths
// land is fixed by cl/sampling/burnin_film.cl). Subtracting sum_p mu_p^2
// from the second moment instead is unbiased too, but at a few samples per
// pixel it is the difference of two large, noisy sums and came out 0 (no
// OMC samples at all) for a light's edges at 512x512. Without such pixels:
// the second moment, an overestimate.
class PixelVariance {
  public:
    // A pixel's sum of luminances y, of their squares y2, and its n samples.
    void add(double y, double y2, std::uint64_t n);
    double value() const;
    // What value() would gain from one sample of luminance y more in a
    // pixel of the mean sample count whose samples are otherwise 0: the
    // least V_o that a light the samples hit at all can give.
    double one_sample(double y) const;

  private:
    double within_ = 0, moment_ = 0, samples_ = 0;
    std::uint64_t pixels_ = 0, used_ = 0;
};

// The share of light behind smooth transmitters in s + b, s and b the means
// per path of that light and of the MLT part found (0 where both are 0).
double behind_share(double behind_mean, double b);

} // namespace smallmlt
