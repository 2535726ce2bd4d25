// Reader of OBJ meshes. A first pass checks every line (so errors name the
// file and line) and loads the MTL files; tinyobjloader then reads and
// triangulates the faces. The only translation unit that includes it.
#include "base/error.hpp"
#include "scene/scene.hpp"
#include "scene/text_parse.hpp"

#include <tiny_obj_loader.h>

#include <fstream>
#include <map>

namespace smallmlt {

namespace {

int material_index(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.material_names.size(); ++i)
        if (scene.material_names[i] == name) return static_cast<int>(i);
    return -1;
}

// Vertex index of a face reference "v", "v/t", "v//n" or "v/t/n".
long face_vertex(const std::string& ref, const std::string& file, int line) {
    return parse_int(ref.substr(0, ref.find('/')), file, line, "face vertex index");
}

// Checks the OBJ line by line and loads the MTL files it names.
void check_obj(const std::string& path, Scene& scene) {
    long vertices = 0;
    bool has_material = false;
    for_each_directive(path, "mesh", [&](int line, const std::vector<std::string>& t) {
        const std::string& d = t[0];
        if (d == "v") {
            if (t.size() != 4 && t.size() != 5)
                throw input_error(path, line, "'v' takes 3 coordinates");
            for (int i = 1; i <= 3; ++i)
                parse_float(t[i], path, line, "vertex coordinate");
            ++vertices;
        } else if (d == "vn" || d == "vt") {
            // Read and ignored: shading uses geometric normals, no textures.
            for (std::size_t i = 1; i < t.size(); ++i)
                parse_float(t[i], path, line, d.c_str());
        } else if (d == "f") {
            if (t.size() < 4) throw input_error(path, line, "a face needs at least 3 vertices");
            if (!has_material)
                throw input_error(path, line, "face without a material (no 'usemtl' before it)");
            for (std::size_t i = 1; i < t.size(); ++i) {
                long v = face_vertex(t[i], path, line);
                if (v == 0 || v > vertices || -v > vertices)
                    throw input_error(path, line,
                                      "face refers to vertex " + std::to_string(v) + " but " +
                                          std::to_string(vertices) + " are defined");
            }
        } else if (d == "usemtl") {
            if (t.size() != 2) throw input_error(path, line, "'usemtl' takes one name");
            if (material_index(scene, t[1]) < 0)
                throw input_error(path, line,
                                  "material '" + t[1] + "' is not defined in any mtllib");
            has_material = true;
        } else if (d == "mtllib") {
            if (t.size() < 2) throw input_error(path, line, "'mtllib' takes a file name");
            for (std::size_t i = 1; i < t.size(); ++i) {
                std::string mtl = dir_of(path) + t[i];
                if (!scene.mtl_files.insert(mtl).second) continue; // shared by meshes
                if (!std::ifstream(mtl))
                    throw input_error(path, line, "cannot open material file " + mtl);
                load_mtl(mtl, scene);
            }
        } else if (d == "o" || d == "g" || d == "s") {
            // Object, group and smoothing-group names carry no meaning here.
        } else {
            throw input_error(path, line, "unsupported OBJ directive '" + d + "'");
        }
    });
}

// Gives tinyobjloader the scene's materials whatever file an mtllib line
// names (check_obj has read them all; tinyobjloader would read only the
// first file of a line): a face's material id is its index in
// scene.materials.
class SceneMaterials : public tinyobj::MaterialReader {
  public:
    explicit SceneMaterials(const Scene& scene) : scene_(scene) {}
    bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* ids, std::string*, std::string*) override {
        const std::vector<std::string>& names = scene_.material_names;
        materials->assign(names.size(), tinyobj::material_t());
        for (std::size_t i = 0; i < names.size(); ++i) {
            (*materials)[i].name = names[i];
            (*ids)[names[i]] = static_cast<int>(i);
        }
        return true;
    }

  private:
    const Scene& scene_;
};

} // namespace

void load_obj(const std::string& path, const std::string& where, Scene& scene) {
    check_obj(path, scene);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> mtls;
    std::string warn, err;
    std::ifstream in(path);
    SceneMaterials materials(scene);
    if (!in || !tinyobj::LoadObj(&attrib, &shapes, &mtls, &warn, &err, &in, &materials, true))
        throw InputError(where + ": cannot read " + path + ": " + err);
    for (const tinyobj::shape_t& shape : shapes) {
        const std::vector<tinyobj::index_t>& idx = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            int mid = shape.mesh.material_ids[f];
            if (mid < 0 || mid >= static_cast<int>(scene.materials.size()))
                throw InputError(path + ": a face has no known material");
            SceneTriangle tri;
            tri.material = static_cast<std::uint32_t>(mid);
            for (int k = 0; k < 3; ++k) {
                int vi = idx[3 * f + k].vertex_index;
                tri.v[k] = {attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1],
                            attrib.vertices[3 * vi + 2]};
            }
            if (!(length(cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0])) > 0)) {
                ++scene.dropped_degenerate;
                continue;
            }
            scene.triangles.push_back(tri);
        }
    }
}

} // namespace smallmlt
