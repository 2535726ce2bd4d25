// The PLY reader (src/scene/ply_loader.cpp) through Mitsuba's ply shape:
// ASCII and binary of both byte orders read the same mesh, polygons fan
// into triangles, properties and elements it does not use are read past,
// texture coordinates follow flip_tex_coords, normals are the file's or
// computed, and every error names its file and line.
#include "base/error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

using namespace smallmlt;

namespace {

// One mesh, written three ways: 4 vertices (x y z, a colour byte the reader
// skips, nx ny nz of length 2, u v), a quad and a triangle (each with a
// trailing float property), and an edge element after them.
struct Vertex {
    float p[3];
    std::uint8_t red;
    float n[3];
    float uv[2];
};
const Vertex kVerts[4] = {{{0, 0, 0}, 9, {0, 0, 2}, {0, 0.25f}},
                          {{1, 0, 0}, 9, {0, 0, 2}, {1, 0.25f}},
                          {{1, 1, 0}, 9, {0, 2, 0}, {1, 1}},
                          {{0, 1, 0}, 9, {2, 0, 0}, {0, 1}}};

std::string header(const char* format) {
    return std::string("ply\nformat ") + format +
           " 1.0\ncomment written by test_ply\nelement vertex 4\nproperty float x\n"
           "property float y\nproperty float z\nproperty uchar red\nproperty float nx\n"
           "property float ny\nproperty float nz\nproperty float u\nproperty float v\n"
           "element face 2\nproperty list uchar int vertex_indices\nproperty float weight\n"
           "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
}

std::string ascii_ply() {
    std::string s = header("ascii");
    for (const Vertex& v : kVerts) {
        char line[256];
        std::snprintf(line, sizeof line, "%g %g %g %d %g %g %g %g %g\n", v.p[0], v.p[1], v.p[2],
                      v.red, v.n[0], v.n[1], v.n[2], v.uv[0], v.uv[1]);
        s += line;
    }
    return s + "4 0 1 2 3 0.5\n3 0 2 3 0.5\n0 1\n";
}

template <typename T> void put(std::string& out, T value, bool big) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i)
        out += char(b[big ? sizeof(T) - 1 - i : i]);
}

// Written for a little-endian host (x86-64, AArch64).
std::string binary_ply(bool big) {
    std::string s = header(big ? "binary_big_endian" : "binary_little_endian");
    for (const Vertex& v : kVerts) {
        for (float x : v.p)
            put(s, x, big);
        put(s, v.red, big);
        for (float x : v.n)
            put(s, x, big);
        for (float x : v.uv)
            put(s, x, big);
    }
    const int faces[2][5] = {{4, 0, 1, 2, 3}, {3, 0, 2, 3, -1}};
    for (const auto& f : faces) {
        put(s, std::uint8_t(f[0]), big);
        for (int k = 1; k <= f[0]; ++k)
            put(s, std::int32_t(f[k]), big);
        put(s, 0.5f, big);
    }
    put(s, std::int32_t(0), big);
    put(s, std::int32_t(1), big);
    return s;
}

const char* kSensor =
    R"(<sensor type="perspective"><float name="fov" value="40"/><transform name="to_world">
        <lookat origin="0, 0, 3" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film></sensor>)";

// A scene of the ply file `ply` (as mesh.ply) under an emitting rectangle,
// with `params` inside the ply shape.
Scene load_ply(const std::string& dir_name, const std::string& ply,
               const std::string& params = "") {
    std::string dir = test::scratch_dir("ply-" + dir_name);
    test::write_file(dir + "/mesh.ply", ply);
    test::write_file(
        dir + "/s.xml",
        std::string("<scene version=\"3.0.0\">\n") + kSensor +
            "\n<shape type=\"rectangle\"><emitter type=\"area\"><rgb name=\"radiance\" "
            "value=\"1\"/></emitter></shape>\n<shape type=\"ply\"><string "
            "name=\"filename\" value=\"mesh.ply\"/>" +
            params + "</shape>\n</scene>\n");
    return load_scene(dir + "/s.xml");
}

// The mesh's triangles: those after the rectangle's two.
std::vector<SceneTriangle> mesh_of(const Scene& s) {
    return std::vector<SceneTriangle>(s.triangles.begin() + 2, s.triangles.end());
}

// Every field alike, bit for bit.
bool same(const SceneTriangle& a, const SceneTriangle& b) {
    for (int k = 0; k < 3; ++k) {
        const float fa[7] = {a.v[k].x, a.v[k].y,   a.v[k].z,  a.n[k].x,
                             a.n[k].y, a.uv[k][0], a.uv[k][1]};
        const float fb[7] = {b.v[k].x, b.v[k].y,   b.v[k].z,  b.n[k].x,
                             b.n[k].y, b.uv[k][0], b.uv[k][1]};
        if (std::memcmp(fa, fb, sizeof fa) != 0 || a.n[k].z != b.n[k].z) return false;
    }
    return a.smooth == b.smooth && a.material == b.material;
}

std::string ply_error(const std::string& ply) {
    return test::message_from(test::input_error_of([&] { load_ply("errors", ply); }), "mesh.ply:");
}

} // namespace

TEST(Ply, AsciiAndBothBinaryOrdersReadTheSameMesh) {
    const std::vector<SceneTriangle> a = mesh_of(load_ply("ascii", ascii_ply()));
    const std::vector<SceneTriangle> le = mesh_of(load_ply("le", binary_ply(false)));
    const std::vector<SceneTriangle> be = mesh_of(load_ply("be", binary_ply(true)));
    // The quad fans into (0 1 2), (0 2 3); then the triangle (0 2 3).
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(le.size(), 3u);
    ASSERT_EQ(be.size(), 3u);
    const int want[3][3] = {{0, 1, 2}, {0, 2, 3}, {0, 2, 3}};
    for (int t = 0; t < 3; ++t) {
        EXPECT_TRUE(a[t].smooth) << "the file's normals shade";
        for (int k = 0; k < 3; ++k) {
            const Vertex& v = kVerts[want[t][k]];
            EXPECT_EQ(a[t].v[k].x, v.p[0]);
            EXPECT_EQ(a[t].v[k].y, v.p[1]);
            EXPECT_EQ(a[t].v[k].z, v.p[2]);
            EXPECT_FLOAT_EQ(a[t].n[k].x, v.n[0] / 2) << "normalized";
            EXPECT_FLOAT_EQ(a[t].n[k].y, v.n[1] / 2);
            EXPECT_FLOAT_EQ(a[t].n[k].z, v.n[2] / 2);
            EXPECT_FLOAT_EQ(a[t].uv[k][0], v.uv[0]);
            // flip_tex_coords is false for ply: Mitsuba reads v as written,
            // which is 1 - v in smallmlt's convention (v = 1 the top row).
            EXPECT_FLOAT_EQ(a[t].uv[k][1], 1 - v.uv[1]);
        }
        EXPECT_TRUE(same(a[t], le[t])) << "little-endian " << t;
        EXPECT_TRUE(same(a[t], be[t])) << "big-endian " << t;
    }
    const std::vector<SceneTriangle> f = mesh_of(
        load_ply("flip", ascii_ply(), "<boolean name=\"flip_tex_coords\" value=\"true\"/>"));
    EXPECT_FLOAT_EQ(f[0].uv[0][1], 0.25f) << "flip_tex_coords: the file's v";
}

TEST(Ply, WithoutNormalsComputesThemAndFaceNormalsKeepsItFlat) {
    // Two triangles meeting at a right angle along the x axis, as in
    // MitsubaShapes.ObjIgnoresMaterialsAndComputesAngleWeightedNormals.
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
                            "property double y\nproperty double z\nelement face 2\n"
                            "property list uint8 uint32 vertex_index\nend_header\n"
                            "0 0 0\n1 0 0\n0 0 -1\n0 2 0\n3 0 1 2\n3 0 1 3\n";
    const std::vector<SceneTriangle> s = mesh_of(load_ply("computed", ply));
    ASSERT_EQ(s.size(), 2u);
    EXPECT_TRUE(s[0].smooth);
    EXPECT_NEAR(s[0].n[0].y, std::sqrt(0.5), 1e-6) << "the shared vertex: the bisector";
    EXPECT_NEAR(s[0].n[0].z, std::sqrt(0.5), 1e-6);
    EXPECT_FLOAT_EQ(s[0].uv[0][1], 1.0f) << "no texture coordinates: v = 0 as Mitsuba reads it";
    const std::vector<SceneTriangle> f =
        mesh_of(load_ply("flat", ply, "<boolean name=\"face_normals\" value=\"true\"/>"));
    EXPECT_FALSE(f[0].smooth);
    EXPECT_FLOAT_EQ(f[0].n[0].y, 1.0f);
}

TEST(Ply, EveryErrorNamesItsFileAndLine) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1\n"
                             "property list uchar int vertex_indices\nend_header\n";
    const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
    std::string truncated = binary_ply(false);
    truncated.resize(truncated.size() - 20);
    struct Row {
        std::string ply;
        const char* want;
    } rows[] = {
        {"solid cube\n", "mesh.ply:1: not a PLY file"},
        {"ply\nformat binary_middle_endian 1.0\nend_header\n", "mesh.ply:2: format"},
        {"ply\nformat ascii 1.0\nelement vertex 3\n", "mesh.ply:3: the file ends before"},
        {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", "mesh.ply:3: 'property' before"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty quaternion x\nend_header\n",
         "mesh.ply:4: 'property' takes"},
        {"ply\nformat ascii 1.0\nvertices 3\nend_header\n", "mesh.ply:3: unknown PLY header"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "end_header\n0 0\n",
         "mesh.ply:3: element 'vertex' needs properties x, y and z"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int corners\nend_header\n" +
             verts + "3 0 1 2\n",
         "mesh.ply:7: element 'face' needs a list property 'vertex_indices'"},
        {head + verts + "3 0 1 7\n", "mesh.ply:13: face 0: vertex index 7 is out of range"},
        {head + verts + "2 0 1\n", "mesh.ply:13: face 0: a face needs at least 3 vertices"},
        {head + "0 0 0\n1 x 0\n", "mesh.ply:11: vertex 1"},
        {head + "0 0 0\n1 nan 0\n", "mesh.ply:11: vertex 1"},
        {head + verts, "mesh.ply:12: the file ends inside face 0"},
        {truncated, "mesh.ply:14: the file ends inside face 1"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n" +
             verts,
         "mesh.ply:7: no element 'face'"},
    };
    for (const Row& r : rows) {
        std::string got = ply_error(r.ply);
        EXPECT_EQ(got.rfind(r.want, 0), 0u) << "got: " << got << "\nwant: " << r.want;
    }
}
