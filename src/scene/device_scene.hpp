// A scene flattened into the structs of cl/core/shared_types.h, ready to copy to
// the device: triangles in BVH leaf order, BVH nodes, materials, the light
// table, the camera frame and the sample layout that fits the scene.
#pragma once
#include "scene/bvh.hpp"
#include "scene/sample_layout.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace smallmlt {

struct DeviceScene {
    std::vector<Triangle> tris;
    std::vector<TriangleNormals> normals;   // per triangle, or one unused entry
    std::vector<TriangleUVs> uvs;           // per triangle, or one unused entry
    std::vector<TextureInfo> textures;      // or one unused entry
    std::vector<Texel> texels;              // all textures' texels, or one unused
    std::vector<std::string> texture_files; // of each TextureInfo, for `budget`
    std::vector<BvhNode> nodes;
    std::vector<Material> materials;
    std::vector<LightEntry> lights;
    Frame frame{};
    SampleLayout layout{};
};

// Frame for a film of width x height pixels and the scene's camera.
Frame make_frame(const Camera& cam, int width, int height, int depth);

// Uses scene.width/height/depth (apply command-line overrides before).
DeviceScene prepare_scene(const Scene& scene);

} // namespace smallmlt
