// The chains' target (cl/mlt/mlt_step.cl): I(x) = lum(F(x)) w(x), with w a
// weight per cell of pixels (TargetCells in cl/core/shared_types.h).
// - Target::Luminance: w = 1, the luminance of Kelemen et al. (2002).
// - Target::TwoStage: w = c_max / max(c, floor), with c a cell's mean
//   luminance of the chains' part as the first half of the burn-in measured
//   it (Veach's two-stage MLT): dim cells get about as many mutations per
//   pixel as bright ones, instead of a share in proportion to their light.
// Any w > 0 keeps the image unbiased: a splat is F/I and b = E[I], estimated
// from samples drawn after w was fixed (the burn-in's second half and every
// large step). w >= 1, so no splat outweighs the luminance target's.
#pragma once
#include "shared_types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace smallmlt {

enum class Target { Luminance, TwoStage };

// Chosen by the error-against-time bench (doc/RESULTS.md).
constexpr Target kDefaultTarget = Target::Luminance;

const char* target_name(Target t);
// Throws UsageError naming `flag` for an unknown name.
Target parse_target(const std::string& flag, const std::string& name);

// The burn-in's samples per cell that measure c (fewer cells if there are
// fewer samples), and the most cells.
constexpr std::uint64_t kTargetSamplesPerCell = 1024;
constexpr std::uint64_t kTargetMaxCells = 4096;
// c below this share of the image's mean counts as this share (a cell where
// the burn-in found no light still gets mutations).
constexpr double kTargetFloor = 0.1;

// One cell of the whole film (w = 1 everywhere: the luminance).
TargetCells target_one_cell();
// Squares of 2^shift pixels, the smallest shift that makes at most
// max(1, min(samples / kTargetSamplesPerCell, kTargetMaxCells)) cells.
TargetCells target_cells(std::uint32_t width, std::uint32_t height, std::uint64_t samples);
// Cells of a film `height` pixels high (cells.columns across).
std::uint32_t target_cell_count(const TargetCells& cells, std::uint32_t height);

// w per cell from the per-pixel RGB sums of uniform samples' MLT parts
// (BurnInParts::rest): c is a cell's mean luminance per pixel.
std::vector<float> target_weights(const TargetCells& cells, std::uint32_t width,
                                  std::uint32_t height, const std::vector<double>& rgb_sums);

} // namespace smallmlt
