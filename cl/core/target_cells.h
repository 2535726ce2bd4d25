/* The cell of a pixel in the chains' target (TargetCells, src/render/target.hpp),
 * one definition for the host (C++17) and the kernels (OpenCL C 1.2). A
 * cell's weight w > 0 scales the chains' target there; w = 0 marks a cell
 * whose MLT part the split's OMC part renders whole (src/render/omc_cells.hpp),
 * so that the chains' target, their splats and b are 0 there. */
#ifndef SMALLMLT_TARGET_CELLS_H
#define SMALLMLT_TARGET_CELLS_H

#ifndef __OPENCL_VERSION__
#include "shared_types.h"
#endif

/* The cell of pixel (x, y): one cell for shift 31 and above. */
inline u32 target_cell(const TargetCells* c, u32 x, u32 y) {
    return c->shift >= 31u ? 0u : (y >> c->shift) * c->columns + (x >> c->shift);
}

/* The weight of pixel `pixel` of a film `width` pixels across. */
#ifdef __OPENCL_VERSION__
inline float target_weight(__global const float* weight, const TargetCells* c, u32 width,
                           u32 pixel) {
    return weight[target_cell(c, pixel % width, pixel / width)];
}
#endif

#endif
