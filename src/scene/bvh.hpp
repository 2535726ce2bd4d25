// Bounding volume hierarchy over the scene's triangles: binned SAH build on
// the host, flattened depth-first into BvhNode (cl/core/shared_types.h) for the
// traversal in cl/geometry/bvh.cl.
#pragma once
#include "scene/scene.hpp"

#include <vector>

namespace smallmlt {

struct Bvh {
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> order; // leaf triangle slot i holds scene triangle order[i]
    int depth = 0;                    // longest root-to-leaf path, in nodes
};

constexpr int kBvhMaxDepth = 60; // below the kernel's traversal stack of 64

Bvh bvh_build(const std::vector<SceneTriangle>& tris);

} // namespace smallmlt
