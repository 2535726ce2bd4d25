// The scene on the device: the read-only buffers of SCENE_BUFFERS
// (cl/core/shared_types.h) and the frame, which every program's kernels
// take first, as one unit (SCENE_ARGS, cl/path/path.cl).
#pragma once
#include "device/ocl.hpp"
#include "scene/device_scene.hpp"

namespace smallmlt {

template <typename T> ClBuffer upload(const ClContext& cl, const std::vector<T>& v) {
    return ClBuffer(cl, CL_MEM_READ_ONLY, v.size() * sizeof(T), v.data());
}

struct SceneBuffers {
#define SMALLMLT_SCENE_MEMBER(T, name) ClBuffer name;
    SCENE_BUFFERS(SMALLMLT_SCENE_MEMBER)
#undef SMALLMLT_SCENE_MEMBER
    Frame frame;

    SceneBuffers(const ClContext& cl, const DeviceScene& ds)
        :
#define SMALLMLT_SCENE_UPLOAD(T, name) name(upload<T>(cl, ds.name)),
          SCENE_BUFFERS(SMALLMLT_SCENE_UPLOAD)
#undef SMALLMLT_SCENE_UPLOAD
              frame(ds.frame) {
    }
};

// Binds the scene as SCENE_ARGS: its buffers in SCENE_BUFFERS' order, then
// the frame.
inline void kernel_arg(ClKernel& k, cl_uint& i, const SceneBuffers& s) {
#define SMALLMLT_SCENE_BIND(T, name) k.set_arg(i++, s.name);
    SCENE_BUFFERS(SMALLMLT_SCENE_BIND)
#undef SMALLMLT_SCENE_BIND
    k.set_arg(i++, s.frame);
}

} // namespace smallmlt
