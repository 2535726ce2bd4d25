// Reader of OBJ meshes. A first pass checks every line (so errors name the
// file and line) and loads the MTL files; tinyobjloader then reads and
// triangulates the faces, and the shading normals are taken from vn or
// computed for smoothing groups. The only translation unit that includes it.
#include "base/error.hpp"
#include "scene/scene.hpp"
#include "scene/text_parse.hpp"

#include <tiny_obj_loader.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <unordered_map>

namespace smallmlt {

namespace {

int material_index(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.material_names.size(); ++i)
        if (scene.material_names[i] == name) return static_cast<int>(i);
    return -1;
}

// Element counts so far, against which face references are checked.
struct ObjCounts {
    long vertices = 0, texcoords = 0, normals = 0;
};

// Checks index `i` of a face reference against the `defined` elements of
// that kind (negative indices count back from the last).
void check_index(const std::string& tok, long defined, const char* what, const std::string& file,
                 int line) {
    long i = parse_int(tok, file, line, (std::string("face ") + what + " index").c_str());
    if (i == 0 || i > defined || -i > defined)
        throw input_error(file, line,
                          "face refers to " + std::string(what) + " " + std::to_string(i) +
                              " but " + std::to_string(defined) + " are defined");
}

// A face reference "v", "v/t", "v//n" or "v/t/n"; returns whether it has n.
bool check_reference(const std::string& ref, const ObjCounts& c, const std::string& file,
                     int line) {
    std::vector<std::string> part(1);
    for (char ch : ref) {
        if (ch == '/')
            part.emplace_back();
        else
            part.back() += ch;
    }
    if (part.size() > 3 || (part.size() == 2 && part[1].empty()))
        throw input_error(file, line, "face reference '" + ref + "' is not v, v/t, v//n or v/t/n");
    check_index(part[0], c.vertices, "vertex", file, line);
    if (part.size() >= 2 && !part[1].empty())
        check_index(part[1], c.texcoords, "texture coordinate", file, line);
    if (part.size() < 3) return false;
    check_index(part[2], c.normals, "normal", file, line);
    return true;
}

// The references of a face (at least 3): all with normals or none.
void check_face(const std::vector<std::string>& t, const ObjCounts& c, const std::string& file,
                int line) {
    std::size_t with_normals = 0;
    for (std::size_t i = 1; i < t.size(); ++i)
        with_normals += check_reference(t[i], c, file, line);
    if (with_normals != 0 && with_normals != t.size() - 1)
        throw input_error(file, line, "face mixes references with and without normals");
}

void check_normal(const std::vector<std::string>& t, const std::string& file, int line) {
    if (t.size() != 4) throw input_error(file, line, "'vn' takes 3 numbers");
    double sq = 0;
    for (int i = 1; i <= 3; ++i) {
        double x = parse_float(t[i], file, line, "normal");
        sq += x * x;
    }
    if (!(sq > 0)) throw input_error(file, line, "'vn' has zero length");
}

// `s N` (N >= 0; 0 ends smoothing) or `s off`.
void check_smoothing(const std::vector<std::string>& t, const std::string& file, int line) {
    const char* usage = "'s' takes a smoothing group number or 'off'";
    if (t.size() != 2) throw input_error(file, line, usage);
    if (t[1] == "off") return;
    long g = parse_int(t[1], file, line, "smoothing group");
    if (g < 0 || g > 0x7fffffffL) throw input_error(file, line, usage);
}

// Checks the OBJ line by line and, with `mtl`, loads the MTL files it names
// and requires a material for every face; without, mtllib and usemtl are
// not read (Mitsuba's obj shape).
void check_obj(const std::string& path, Scene& scene, bool mtl) {
    ObjCounts counts;
    bool has_material = false;
    for_each_directive(path, "mesh", [&](int line, const std::vector<std::string>& t) {
        const std::string& d = t[0];
        if (d == "v") {
            if (t.size() != 4 && t.size() != 5)
                throw input_error(path, line, "'v' takes 3 coordinates");
            for (int i = 1; i <= 3; ++i)
                parse_float(t[i], path, line, "vertex coordinate");
            ++counts.vertices;
        } else if (d == "vn") {
            check_normal(t, path, line);
            ++counts.normals;
        } else if (d == "vt") {
            // Read and ignored until textures are read.
            if (t.size() < 2 || t.size() > 4)
                throw input_error(path, line, "'vt' takes 1 to 3 numbers");
            for (std::size_t i = 1; i < t.size(); ++i)
                parse_float(t[i], path, line, "texture coordinate");
            ++counts.texcoords;
        } else if (d == "f") {
            if (t.size() < 4) throw input_error(path, line, "a face needs at least 3 vertices");
            if (mtl && !has_material)
                throw input_error(path, line, "face without a material (no 'usemtl' before it)");
            check_face(t, counts, path, line);
        } else if (!mtl && (d == "usemtl" || d == "mtllib")) {
            // Not read: the shape's BSDF gives every face its material.
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
        } else if (d == "s") {
            check_smoothing(t, path, line);
        } else if (d == "o" || d == "g") {
            // Object and group names carry no meaning here.
        } else {
            throw input_error(path, line, "unsupported OBJ directive '" + d + "'");
        }
    });
}

Vec3 unit(double x, double y, double z) {
    double len = std::sqrt(x * x + y * y + z * z);
    return {static_cast<float>(x / len), static_cast<float>(y / len), static_cast<float>(z / len)};
}

// Sums of the area-weighted geometric normals cross(e1, e2) of a smoothing
// group's triangles at each vertex they share, keyed by group and vertex.
class GroupNormals {
  public:
    void add(unsigned group, int vertex, Vec3 weighted) {
        std::array<double, 3>& s = sums_[key(group, vertex)];
        s[0] += weighted.x;
        s[1] += weighted.y;
        s[2] += weighted.z;
    }
    // The normalized sum, or `flat` where it is zero (faces that cancel).
    Vec3 at(unsigned group, int vertex, Vec3 flat) const {
        const std::array<double, 3>& s = sums_.at(key(group, vertex));
        if (!(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] > 0)) return flat;
        return unit(s[0], s[1], s[2]);
    }

  private:
    static std::uint64_t key(unsigned group, int vertex) {
        return (std::uint64_t(group) << 32) | std::uint32_t(vertex);
    }
    std::unordered_map<std::uint64_t, std::array<double, 3>> sums_;
};

Vec3 vertex_at(const tinyobj::attrib_t& a, int i) {
    return {a.vertices[3 * i], a.vertices[3 * i + 1], a.vertices[3 * i + 2]};
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

unsigned smoothing_group(const tinyobj::shape_t& shape, std::size_t f) {
    const std::vector<unsigned>& ids = shape.mesh.smoothing_group_ids;
    return f < ids.size() ? ids[f] : 0u;
}

// The triangles of the OBJ at `path`, appended to scene.triangles: with
// their usemtl materials where `fixed` is null, else all `*fixed` with the
// smoothing groups not read.
void read_obj(const std::string& path, const std::string& where, Scene& scene,
              const std::uint32_t* fixed) {
    check_obj(path, scene, fixed == nullptr);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> mtls;
    std::string warn, err;
    std::ifstream in(path);
    SceneMaterials materials(scene);
    if (!in || !tinyobj::LoadObj(&attrib, &shapes, &mtls, &warn, &err, &in, &materials, true))
        throw InputError(where + ": cannot read " + path + ": " + err);
    auto group_of = [&](const tinyobj::shape_t& shape, std::size_t f) {
        return fixed ? 0u : smoothing_group(shape, f);
    };

    // The triangles of smoothing groups, as they add to their vertices.
    GroupNormals groups;
    for (const tinyobj::shape_t& shape : shapes) {
        const std::vector<tinyobj::index_t>& idx = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            unsigned g = group_of(shape, f);
            if (g == 0) continue;
            int vi[3] = {idx[3 * f].vertex_index, idx[3 * f + 1].vertex_index,
                         idx[3 * f + 2].vertex_index};
            Vec3 p0 = vertex_at(attrib, vi[0]);
            Vec3 weighted = cross(vertex_at(attrib, vi[1]) - p0, vertex_at(attrib, vi[2]) - p0);
            for (int k = 0; k < 3; ++k)
                groups.add(g, vi[k], weighted);
        }
    }

    for (const tinyobj::shape_t& shape : shapes) {
        const std::vector<tinyobj::index_t>& idx = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            int mid = fixed ? int(*fixed) : shape.mesh.material_ids[f];
            if (mid < 0 || mid >= static_cast<int>(scene.materials.size()))
                throw InputError(path + ": a face has no known material");
            SceneTriangle tri;
            tri.material = static_cast<std::uint32_t>(mid);
            for (int k = 0; k < 3; ++k)
                tri.v[k] = vertex_at(attrib, idx[3 * f + k].vertex_index);
            Vec3 geometric = cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
            if (!(length(geometric) > 0)) {
                ++scene.dropped_degenerate;
                continue;
            }
            Vec3 flat = tri.flat_normal();
            unsigned g = group_of(shape, f);
            // Each triangle vertex keeps the reference of its face vertex:
            // its normal is the one the face gave there.
            bool given = idx[3 * f].normal_index >= 0;
            tri.smooth = given || g != 0;
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& r = idx[3 * f + k];
                if (r.texcoord_index >= 0) {
                    tri.uv[k][0] = attrib.texcoords[2 * std::size_t(r.texcoord_index)];
                    tri.uv[k][1] = attrib.texcoords[2 * std::size_t(r.texcoord_index) + 1];
                }
                if (given) {
                    const float* n = &attrib.normals[3 * r.normal_index];
                    tri.n[k] = unit(n[0], n[1], n[2]);
                } else {
                    tri.n[k] = g != 0 ? groups.at(g, r.vertex_index, flat) : flat;
                }
            }
            scene.triangles.push_back(tri);
        }
    }
}

} // namespace

Vec3 SceneTriangle::flat_normal() const {
    Vec3 g = cross(v[1] - v[0], v[2] - v[0]);
    return unit(g.x, g.y, g.z);
}

void load_obj(const std::string& obj_path, const std::string& where, Scene& scene) {
    read_obj(obj_path, where, scene, nullptr);
}

void load_obj_geometry(const std::string& obj_path, const std::string& where,
                       std::uint32_t material, Scene& scene) {
    read_obj(obj_path, where, scene, &material);
}

} // namespace smallmlt
