// Cells of the film whose MLT part path tracing renders well, which the
// split's OMC part then renders whole: the chains' target is 0 there
// (cl/core/target_cells.h), the OMC part's per-pixel samples trace the
// whole path there (cl/kernels/pt.cl), and the chains spend every mutation
// on the rest of the film. It is the split's rule whether the chains pay
// (split.hpp, chains_pay) applied to the cells of the target (target.hpp):
// alone, a cell would go where the MLT part's per-pixel relative variance
// r_c = V_c / (P_c b_c^2) of its P_c pixels is below kChainsPayRatio; as
// the cells that go share one rate of samples, they are chosen together
// (omc_cells.cpp, choose; doc/design.md), and the chains' error counts
// where they would stay on small areas far brighter than b
// (chain_correlation).
// Never chosen: a cell with more than kChainsPayBehindShare of the light
// its paths aimed at behind smooth transmitters, and one where the paths
// found no MLT-part light: light there is rare, and finding rare light is
// what the chains are for.
// The cells are chosen by burn-in rounds of their own, before the usual
// ones (burn_in_rounds). Where some go to the OMC part, those rounds' parts
// are dropped (src/render/mlt_burn_in.hpp): the image and b use only
// samples drawn after the choice, so it biases neither. Where none do,
// nothing changed, and every round counts.
#pragma once
#include "render/burn_in.hpp"
#include "shared_types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace smallmlt {

// On: lower MSE on ajar, veach-mis and cornell-glossy, half the block error
// on the first two and about `off`'s on cornell-glossy, no change elsewhere
// (doc/RESULTS.md, "Cells for the OMC part" and "Large steps on the chains'
// part of the film").
constexpr bool kDefaultOmcCells = true;

// Throws UsageError naming `flag` unless `name` is on or off.
bool parse_omc_cells(const std::string& flag, const std::string& name);

// What the cells' rule needs of the chains' steps: the probability of a
// large step and a small step's largest move on the film, in pixels.
struct ChainSteps {
    double large = 0;
    std::uint32_t film_pixels = 1;
};

// The chains' correlation at a pixel of mean luminance `mean`, in units of
// tau (kChainCorrelation). A chain in a state far brighter than the chains'
// mean b leaves the bright area around it only when a large step
// (probability p) proposes a state it accepts, about b / I of them: it stays
// about I / (p b) steps. The count of chains in an area of A pixels of such
// light is then what sets their brightness, so each pixel's samples are
// correlated over about I / (p b A) steps, where chains that move freely
// have tau: max(1, mean / (tau p b A)) for A = `area`; 1 without large steps
// or light.
double chain_correlation(double mean, double b, double area, double large_step);

// Per pixel of a width x height film, the chains' excess correlation where
// they would stay (chain_correlation less 1), kept only where another pixel
// within kLoneReach has some too. At a burn-in sample or two per pixel
// (512x512) a single sample far brighter than b reads as such a pixel; such
// samples are as likely in any cell of their kind of light, and the cells'
// rule, which picks the largest terms, picked the cells where the burn-in
// happened to find one (on ajar, for the slit's). A small light's image
// lights pixels beside it too, even where, at a sample per pixel, every
// other one misses it. Of the 24 others in reach, ajar's single bright
// samples (0.4% of its pixels at 512x512) find one by chance about one
// time in ten.
constexpr std::uint32_t kLoneReach = 2;
std::vector<double> without_lone_pixels(std::vector<double> excess, std::uint32_t width,
                                        std::uint32_t height);

// Per pixel of a width x height film of mean luminances `means`: the area,
// in pixels, of light like its own within `reach` pixels of it: 1 + (W - 1)
// min(1, n / m), where the W - 1 other pixels in reach have the mean n and
// it has m.
std::vector<double> light_areas(const std::vector<double>& means, std::uint32_t width,
                                std::uint32_t height, std::uint32_t reach);

// Per pixel of a width x height film: the mean luminance per sample of the
// MLT parts of the other pixels within kNeighbourReach, 0 where they hold
// no sample. Independent of the pixel's own samples.
constexpr std::uint32_t kNeighbourReach = 1;
std::vector<double> neighbour_means(const BurnInParts& parts, std::uint32_t width,
                                    std::uint32_t height);

// Per pixel of a width x height film of mean luminances `means`, for chains
// of mean b whose steps are `steps`: the excess correlation where they
// would stay (chain_correlation less 1, over light_areas), without lone
// pixels.
std::vector<double> stay_excess(const std::vector<double>& means, double b, std::uint32_t width,
                                std::uint32_t height, const ChainSteps& steps);

// The chains' error where they would stay on small bright areas over their
// error were they free everywhere, before any cell goes (K / L^2 of
// omc_cells.cpp's ChainsError), measured two ways. K weights each pixel's
// light by its excess correlation, a function of its mean: `own` takes that
// mean from the pixel's samples, `neighbours` from its neighbours'
// (neighbour_means). At a burn-in sample or two per pixel a single bright
// sample weights itself by its own square, and `own` reads high: on
// veach-mis at 512x384 it fell from 2.7-3.7 at 1.3 burn-in samples per
// pixel to 0.28-0.31 at 43. `neighbours` pairs each pixel's light with
// other samples, which spreads a small area's peak a little: it read
// 0.05-0.36 over that range, 0.17-0.18 at 43, and reads low only where a
// small bright area holds too few samples to pair (0.002-0.08 at 0.33)
// (doc/RESULTS.md, "The chains' stay, two ways").
struct ChainsStay {
    double own = 0, neighbours = 0;
};

// Per cell of `cells` on a width x height film: true where the OMC part
// renders it whole, from the burn-in's parts, for chains whose steps are
// `steps`. And, where `stay` is given, the chains' stay (ChainsStay).
std::vector<bool> omc_cells(const TargetCells& cells, std::uint32_t width, std::uint32_t height,
                            const BurnInParts& parts, const ChainSteps& steps,
                            ChainsStay* stay = nullptr);

} // namespace smallmlt
