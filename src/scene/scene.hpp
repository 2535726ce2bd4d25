// A scene as loaded from a .scene file (format: doc/scene-format.md):
// film, camera, depth and the triangles and materials of its meshes.
#pragma once
#include "base/vec3.hpp"
#include "scene/sample_layout.hpp"
#include "scene/texture.hpp"
#include "shared_types.h"

#include <set>
#include <string>
#include <vector>

namespace smallmlt {

struct Camera {
    Vec3 eye, target, up{0, 1, 0};
    float fov_y_deg = 40;
};

// A triangle as loaded. n[k] is the shading normal at v[k] (unit length):
// interpolated across the triangle where `smooth` (from the OBJ's vn, or
// computed for a smoothing group), else the geometric normal at all three.
// The geometric normal cross(v1 - v0, v2 - v0) still decides the sides.
struct SceneTriangle {
    Vec3 v[3];
    std::uint32_t material = 0;
    Vec3 n[3];           // shading normals at v[0..2] (unit), when smooth
    bool smooth = false; // has interpolated normals
    float uv[3][2] = {}; // texture coordinates at v[0..2] (0 where the mesh has none)

    // The unit geometric normal (normalized in double precision).
    Vec3 flat_normal() const;

    // A flat triangle.
    static SceneTriangle flat(Vec3 a, Vec3 b, Vec3 c, std::uint32_t material) {
        SceneTriangle t;
        t.v[0] = a;
        t.v[1] = b;
        t.v[2] = c;
        t.material = material;
        return t;
    }
};

struct Scene {
    int width = 512, height = 512;
    int depth = 8;
    Roulette roulette; // a render setting (command line), not in the file
    Camera camera;
    std::vector<SceneTriangle> triangles;
    std::vector<Material> materials;
    std::vector<std::string> material_names;
    std::vector<SceneTexture> textures; // Material.*_tex index into it
    std::set<std::string> mtl_files;    // MTL files read so far (meshes may share one)
    int dropped_degenerate = 0;         // zero-area triangles left out at load
    // What loads but is not rendered as written: "FILE:LINE: warning: ...".
    std::vector<std::string> warnings;
};

constexpr int kMaxDepth = 64;
constexpr int kMaxFilmSide = 16384;

// Parses a .scene file and the meshes it names, or a Mitsuba scene file
// (a name ending in .xml). Throws InputError naming the file and line of the
// first problem.
Scene load_scene(const std::string& path);

// Throws InputError naming `path` unless some triangle emits.
void require_lit(const Scene& scene, const std::string& path);

// Reads the triangles of an OBJ file and the materials of the MTL files it
// names into `scene` (src/scene/obj_loader.cpp). `where` is "scene:line" of the
// mesh directive, for messages about the file as a whole.
void load_obj(const std::string& obj_path, const std::string& where, Scene& scene);

// The triangles of an OBJ file as Mitsuba's obj shape reads them, appended
// to scene.triangles: every face of material `material`, mtllib, usemtl and
// smoothing groups not read; shading normals from vn only (src/scene/obj_loader.cpp).
void load_obj_geometry(const std::string& obj_path, const std::string& where,
                       std::uint32_t material, Scene& scene);

// The triangles of a PLY file (ASCII or binary) as Mitsuba's ply shape
// reads them, appended to scene.triangles, all of material `material`:
// shading normals from nx, ny, nz, texture coordinates as the file has
// them (src/scene/ply_loader.cpp). `where` names the shape for errors.
void load_ply_geometry(const std::string& ply_path, const std::string& where,
                       std::uint32_t material, Scene& scene);

// Reads a Mitsuba scene file (src/scene/mitsuba_scene.cpp; doc/scene-format.md).
Scene load_mitsuba_scene(const std::string& path);

// Materials of one MTL file, appended to scene.materials/material_names,
// and its warnings to scene.warnings (src/scene/mtl_loader.cpp).
void load_mtl(const std::string& mtl_path, Scene& scene);

} // namespace smallmlt
