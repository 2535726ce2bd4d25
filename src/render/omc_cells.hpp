// Cells of the film whose MLT part path tracing renders well, which the
// split's OMC part then renders whole: the chains' target is 0 there
// (cl/core/target_cells.h), the OMC part's per-pixel samples trace the
// whole path there (cl/kernels/pt.cl), and the chains spend every mutation
// on the rest of the film. It is the split's rule whether the chains pay
// (split.hpp, chains_pay) applied to the cells of the target (target.hpp):
// alone, a cell would go where the MLT part's per-pixel relative variance
// r_c = V_c / (P_c b_c^2) of its P_c pixels is below kChainsPayRatio; as
// the cells that go share one rate of samples, they are chosen together
// (omc_cells.cpp, choose; doc/design.md). Never chosen: a cell with more
// than kChainsPayBehindShare of the light its paths aimed at behind smooth
// transmitters, and one where the paths found no MLT-part light: light
// there is rare, and finding rare light is what the chains are for.
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

// Per cell of `cells` on a width x height film: true where the OMC part
// renders it whole, from the burn-in's parts.
std::vector<bool> omc_cells(const TargetCells& cells, std::uint32_t width, std::uint32_t height,
                            const BurnInParts& parts);

} // namespace smallmlt
