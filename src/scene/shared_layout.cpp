// Host-side checks of the shared struct layouts (cl/core/shared_types.h); the
// probe_layout kernel reports the device's view in the same order, and
// test/test_layout.cpp compares the two.
#include "scene/shared_layout.hpp"

#include "scene/scene.hpp"

#include <cstddef>

namespace smallmlt {

#define SMALLMLT_CHECK_OFFSET(T, field, off) static_assert(offsetof(T, field) == off, #T "." #field)
static_assert(sizeof(Triangle) == 48, "Triangle");
SMALLMLT_CHECK_OFFSET(Triangle, material, 12);
SMALLMLT_CHECK_OFFSET(Triangle, e1, 16);
SMALLMLT_CHECK_OFFSET(Triangle, light_pick_prob, 28);
SMALLMLT_CHECK_OFFSET(Triangle, e2, 32);
SMALLMLT_CHECK_OFFSET(Triangle, light_index, 44);
static_assert(sizeof(BvhNode) == 32, "BvhNode");
SMALLMLT_CHECK_OFFSET(BvhNode, offset, 12);
SMALLMLT_CHECK_OFFSET(BvhNode, hi, 16);
SMALLMLT_CHECK_OFFSET(BvhNode, count, 28);
static_assert(sizeof(Material) == 48, "Material");
SMALLMLT_CHECK_OFFSET(Material, type, 12);
SMALLMLT_CHECK_OFFSET(Material, ke, 16);
SMALLMLT_CHECK_OFFSET(Material, ior, 28);
SMALLMLT_CHECK_OFFSET(Material, ks, 32);
SMALLMLT_CHECK_OFFSET(Material, emissive, 44);
static_assert(sizeof(LightEntry) == 8, "LightEntry");
SMALLMLT_CHECK_OFFSET(LightEntry, cdf_hi, 4);
static_assert(sizeof(Frame) == 64, "Frame");
SMALLMLT_CHECK_OFFSET(Frame, width, 12);
SMALLMLT_CHECK_OFFSET(Frame, top_left, 16);
SMALLMLT_CHECK_OFFSET(Frame, height, 28);
SMALLMLT_CHECK_OFFSET(Frame, du, 32);
SMALLMLT_CHECK_OFFSET(Frame, depth, 44);
SMALLMLT_CHECK_OFFSET(Frame, dv, 48);
SMALLMLT_CHECK_OFFSET(Frame, num_lights, 60);
static_assert(sizeof(ChainValue) == 20, "ChainValue");
SMALLMLT_CHECK_OFFSET(ChainValue, meta, 12);
SMALLMLT_CHECK_OFFSET(ChainValue, stay, 16);
static_assert(kMaxDepth <= CHAIN_BOUNCES_MASK, "ChainValue.meta holds the live bounces");
static_assert(sizeof(TargetCells) == 8, "TargetCells");
SMALLMLT_CHECK_OFFSET(TargetCells, columns, 4);
static_assert(sizeof(BurnInFilm) == 20, "BurnInFilm");
SMALLMLT_CHECK_OFFSET(BurnInFilm, seed_hi, 4);
SMALLMLT_CHECK_OFFSET(BurnInFilm, offset, 8);
SMALLMLT_CHECK_OFFSET(BurnInFilm, step, 12);
SMALLMLT_CHECK_OFFSET(BurnInFilm, per_round, 16);
#undef SMALLMLT_CHECK_OFFSET

std::vector<std::uint32_t> host_layout() {
    return {sizeof(Triangle),
            offsetof(Triangle, material),
            offsetof(Triangle, e1),
            offsetof(Triangle, light_pick_prob),
            offsetof(Triangle, e2),
            offsetof(Triangle, light_index),
            sizeof(BvhNode),
            offsetof(BvhNode, offset),
            offsetof(BvhNode, hi),
            offsetof(BvhNode, count),
            sizeof(Material),
            offsetof(Material, type),
            offsetof(Material, ke),
            offsetof(Material, ior),
            offsetof(Material, ks),
            offsetof(Material, emissive),
            sizeof(LightEntry),
            offsetof(LightEntry, cdf_hi),
            sizeof(Frame),
            offsetof(Frame, width),
            offsetof(Frame, top_left),
            offsetof(Frame, height),
            offsetof(Frame, du),
            offsetof(Frame, depth),
            offsetof(Frame, dv),
            offsetof(Frame, num_lights),
            sizeof(ChainValue),
            offsetof(ChainValue, meta),
            offsetof(ChainValue, stay),
            sizeof(TargetCells),
            offsetof(TargetCells, columns),
            sizeof(BurnInFilm),
            offsetof(BurnInFilm, seed_hi),
            offsetof(BurnInFilm, offset),
            offsetof(BurnInFilm, step),
            offsetof(BurnInFilm, per_round)};
}

} // namespace smallmlt
