// Reader of the .scene format (doc/scene-format.md).
#include "scene/scene.hpp"

#include "base/error.hpp"
#include "scene/text_parse.hpp"

#include <cmath>
#include <fstream>

namespace smallmlt {

namespace {

void expect_args(const std::vector<std::string>& t, std::size_t n, const std::string& file,
                 int line, const char* usage) {
    if (t.size() != n + 1)
        throw input_error(file, line,
                          "'" + t[0] + "' takes " + std::to_string(n) + " value(s): " + usage);
}

Vec3 parse_vec(const std::vector<std::string>& t, std::size_t at, const std::string& file, int line,
               const char* what) {
    return {parse_float(t[at], file, line, what), parse_float(t[at + 1], file, line, what),
            parse_float(t[at + 2], file, line, what)};
}

void parse_camera(const std::vector<std::string>& t, const std::string& file, int line,
                  Camera& cam) {
    expect_args(t, 10, file, line, "camera EX EY EZ  TX TY TZ  UX UY UZ  FOV_DEGREES");
    cam.eye = parse_vec(t, 1, file, line, "camera eye");
    cam.target = parse_vec(t, 4, file, line, "camera target");
    cam.up = parse_vec(t, 7, file, line, "camera up");
    cam.fov_y_deg = parse_float(t[10], file, line, "camera field of view");
    if (!(cam.fov_y_deg > 0 && cam.fov_y_deg < 180))
        throw input_error(file, line, "camera field of view must be in (0, 180) degrees");
    Vec3 view = cam.target - cam.eye;
    if (!(length(view) > 0)) throw input_error(file, line, "camera eye and target coincide");
    if (!(length(cross(normalize(view), cam.up)) > 1e-6f))
        throw input_error(file, line, "camera up is zero or parallel to the view direction");
}

} // namespace

Scene load_scene(const std::string& path) {
    if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".xml") == 0)
        return load_mitsuba_scene(path);
    Scene scene;
    bool seen_film = false, seen_camera = false, seen_depth = false;
    int meshes = 0;
    for_each_directive(path, "scene", [&](int line, const std::vector<std::string>& t) {
        const std::string& d = t[0];
        if (d == "film") {
            if (seen_film) throw input_error(path, line, "'film' given twice");
            expect_args(t, 2, path, line, "film WIDTH HEIGHT");
            long w = parse_int(t[1], path, line, "film width");
            long h = parse_int(t[2], path, line, "film height");
            if (w < 1 || h < 1 || w > kMaxFilmSide || h > kMaxFilmSide)
                throw input_error(path, line,
                                  "film size must be 1.." + std::to_string(kMaxFilmSide) +
                                      " pixels on each side");
            scene.width = static_cast<int>(w);
            scene.height = static_cast<int>(h);
            seen_film = true;
        } else if (d == "camera") {
            if (seen_camera) throw input_error(path, line, "'camera' given twice");
            parse_camera(t, path, line, scene.camera);
            seen_camera = true;
        } else if (d == "depth") {
            if (seen_depth) throw input_error(path, line, "'depth' given twice");
            expect_args(t, 1, path, line, "depth BOUNCES");
            long v = parse_int(t[1], path, line, "depth");
            if (v < 0 || v > kMaxDepth)
                throw input_error(path, line, "depth must be 0.." + std::to_string(kMaxDepth));
            scene.depth = static_cast<int>(v);
            seen_depth = true;
        } else if (d == "mesh") {
            expect_args(t, 1, path, line, "mesh FILE.obj");
            std::string obj = dir_of(path) + t[1];
            if (!std::ifstream(obj)) throw input_error(path, line, "cannot open mesh file " + obj);
            load_obj(obj, path + ":" + std::to_string(line), scene);
            ++meshes;
        } else {
            throw input_error(path, line,
                              "unknown directive '" + d + "' (expected film, camera, depth, mesh)");
        }
    });
    if (!seen_camera) throw InputError(path + ": no 'camera' line");
    if (meshes == 0) throw InputError(path + ": no 'mesh' line");
    if (scene.triangles.empty()) throw InputError(path + ": the scene has no triangles");
    require_lit(scene, path);
    return scene;
}

void require_lit(const Scene& scene, const std::string& path) {
    for (const SceneTriangle& t : scene.triangles)
        if (scene.materials[t.material].emissive) return;
    throw InputError(path + ": no emissive triangle (no emitting material is used on a "
                            "triangle of non-zero area): nothing would be lit");
}

} // namespace smallmlt
