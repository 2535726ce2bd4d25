// The scene on the device: the read-only buffers every program's kernels
// take first (triangles, BVH nodes, materials, lights).
#pragma once
#include "device/ocl.hpp"
#include "scene/device_scene.hpp"

namespace smallmlt {

template <typename T> ClBuffer upload(const ClContext& cl, const std::vector<T>& v) {
    return ClBuffer(cl, CL_MEM_READ_ONLY, v.size() * sizeof(T), v.data());
}

struct SceneBuffers {
    ClBuffer tris, nodes, mats, lights;
    SceneBuffers(const ClContext& cl, const DeviceScene& ds)
        : tris(upload(cl, ds.tris)), nodes(upload(cl, ds.nodes)), mats(upload(cl, ds.materials)),
          lights(upload(cl, ds.lights)) {}
};

} // namespace smallmlt
