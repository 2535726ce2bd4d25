// Scene, OBJ and MTL readers: a valid scene loads; each unsupported or
// malformed input gives its own error naming the file and line.
#include "base/error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

const char* kScene = "film 8 8\ncamera 0 1 3  0 1 0  0 1 0  40\ndepth 4\nmesh m.obj\n";
const char* kObj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl white\nf 1 2 3\n"
                   "usemtl lamp\nf 1 2 4\n";
const char* kMtl = "newmtl white\nKd 0.5 0.5 0.5\nnewmtl lamp\nKe 1 1 1\n";

struct Files {
    std::string scene = kScene, obj = kObj, mtl = kMtl;
};

// Writes the three files into a fresh directory and loads the scene;
// returns the error message ("" if it loaded).
std::string load_error(const Files& f, const std::string& dir_name) {
    std::string dir = test::scratch_dir("parse-" + dir_name);
    test::write_file(dir + "/s.scene", f.scene);
    test::write_file(dir + "/m.obj", f.obj);
    test::write_file(dir + "/m.mtl", f.mtl);
    try {
        load_scene(dir + "/s.scene");
    } catch (const InputError& e) {
        std::string msg = e.what();
        return msg.substr(msg.find(dir_name) + dir_name.size() + 1); // relative to dir
    }
    return "";
}

struct Case {
    const char* name;
    const char* file; // which file to change: scene, obj or mtl
    const char* text;
    const char* expected; // the message must start with this
};

const Case kCases[] = {
    {"empty_scene", "scene", "", "s.scene: no 'camera' line"},
    {"film_negative", "scene", "film -8 8\n", "s.scene:1: film size must be 1..16384"},
    {"film_truncated", "scene", "film 8 8\ncamera 0 1 3  0 1", "s.scene:2: 'camera' takes"},
    {"depth_text", "scene", "depth many\n", "s.scene:1: depth: 'many' is not an integer"},
    {"no_light", "obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1 2 3\n",
     "s.scene: no emissive triangle"},
    {"emitter_zero_area", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nusemtl white\nf 1 2 3\n"
     "usemtl lamp\nf 1 2 4\n",
     "s.scene: no emissive triangle"},
    {"all_degenerate", "obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nusemtl lamp\nf 1 2 2\n",
     "s.scene: the scene has no triangles"},
    {"obj_empty", "obj", "", "s.scene: the scene has no triangles"},
    {"obj_truncated_vertex", "obj", "mtllib m.mtl\nv 0 0", "m.obj:2: 'v' takes 3 coordinates"},
    {"obj_inf_vertex", "obj", "v 0 inf 0\n", "m.obj:1: vertex coordinate: 'inf' is not finite"},
    {"obj_huge_vertex", "obj", "v 0 1e39 0\n", "m.obj:1: vertex coordinate: '1e39' is not finite"},
    {"mtl_nan", "mtl", "newmtl white\nKd nan 0 0\n", "m.mtl:2: Kd: 'nan' is not finite"},
    {"mtl_truncated", "mtl", "newmtl white\nKd 0.5", "m.mtl:2: 'Kd' takes"},
    {"unknown_directive", "scene", "film 8 8\nlens 2\n", "s.scene:2: unknown directive 'lens'"},
    {"film_arity", "scene", "film 8\n", "s.scene:1: 'film' takes 2 value(s)"},
    {"film_zero", "scene", "film 0 8\n", "s.scene:1: film size must be 1..16384"},
    {"film_huge", "scene", "film 100000 8\n", "s.scene:1: film size must be 1..16384"},
    {"film_text", "scene", "film 8 abc\n", "s.scene:1: film height: 'abc' is not an integer"},
    {"film_twice", "scene", "film 8 8\nfilm 8 8\n", "s.scene:2: 'film' given twice"},
    {"depth_range", "scene", "depth 65\n", "s.scene:1: depth must be 0..64"},
    {"depth_negative", "scene", "depth -1\n", "s.scene:1: depth must be 0..64"},
    {"camera_nan", "scene", "camera 0 nan 3  0 1 0  0 1 0  40\n",
     "s.scene:1: camera eye: 'nan' is not finite"},
    {"camera_inf", "scene", "camera 0 1 inf  0 1 0  0 1 0  40\n",
     "s.scene:1: camera eye: 'inf' is not finite"},
    {"camera_fov", "scene", "camera 0 1 3  0 1 0  0 1 0  180\n",
     "s.scene:1: camera field of view must be in (0, 180) degrees"},
    {"camera_coincide", "scene", "camera 0 1 0  0 1 0  0 1 0  40\n",
     "s.scene:1: camera eye and target coincide"},
    {"camera_up", "scene", "camera 0 1 3  0 1 0  0 0 1  40\n",
     "s.scene:1: camera up is zero or parallel"},
    {"no_camera", "scene", "film 8 8\nmesh m.obj\n", "s.scene: no 'camera' line"},
    {"no_mesh", "scene", "camera 0 1 3  0 1 0  0 1 0  40\n", "s.scene: no 'mesh' line"},
    {"missing_mesh", "scene", "camera 0 1 3  0 1 0  0 1 0  40\nmesh nope.obj\n",
     "s.scene:2: cannot open mesh file"},
    {"obj_directive", "obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nl 1 2\n",
     "m.obj:4: unsupported OBJ directive 'l'"},
    {"obj_index", "obj", "mtllib m.mtl\nv 0 0 0\nusemtl white\nf 1 2 3\n",
     "m.obj:4: face refers to vertex 2 but 1 are defined"},
    {"obj_no_material", "obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
     "m.obj:4: face without a material"},
    {"obj_unknown_material", "obj", "mtllib m.mtl\nusemtl chrome\n",
     "m.obj:2: material 'chrome' is not defined"},
    {"obj_nan_vertex", "obj", "v 0 nan 0\n", "m.obj:1: vertex coordinate: 'nan' is not finite"},
    {"obj_short_face", "obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nusemtl white\nf 1 2\n",
     "m.obj:5: a face needs at least 3 vertices"},
    {"obj_missing_mtl", "obj", "mtllib other.mtl\n", "m.obj:1: cannot open material file"},
    {"mtl_illum_range", "mtl", "newmtl white\nillum 11\n",
     "m.mtl:2: material 'white': illum 11 is not supported (0-10:"},
    {"mtl_illum_negative", "mtl", "newmtl white\nillum -1\n",
     "m.mtl:2: material 'white': illum -1 is not supported (0-10:"},
    {"mtl_glass_no_ni", "mtl", "newmtl white\nillum 7\n",
     "m.mtl:2: material 'white': a dielectric (illum 7) needs Ni > 0"},
    {"mtl_illum4_no_ni", "mtl", "newmtl white\nKd 1 1 1\nillum 4\n",
     "m.mtl:3: material 'white': a dielectric (illum 4) needs Ni > 0"},
    {"mtl_mirror_no_ks", "mtl", "newmtl white\nillum 5\n",
     "m.mtl:2: material 'white': a mirror (illum 5) needs Ks"},
    {"mtl_ni_zero", "mtl", "newmtl white\nNi 0\n", "m.mtl:2: 'Ni' must be > 0"},
    {"mtl_ns_range", "mtl", "newmtl white\nNs 1000.5\n", "m.mtl:2: 'Ns' must be in [0, 1000]"},
    {"mtl_ns_negative", "mtl", "newmtl white\nNs -1\n", "m.mtl:2: 'Ns' must be in [0, 1000]"},
    {"mtl_ns_text", "mtl", "newmtl white\nNs shiny\n", "m.mtl:2: Ns: 'shiny' is not a number"},
    {"mtl_ns_arity", "mtl", "newmtl white\nNs 1 2\n", "m.mtl:2: 'Ns' takes one number"},
    {"mtl_pr_range", "mtl", "newmtl white\nPr 1.5\n", "m.mtl:2: 'Pr' must be in [0, 1]"},
    {"mtl_pr_text", "mtl", "newmtl white\nPr rough\n", "m.mtl:2: Pr: 'rough' is not a number"},
    {"mtl_pm_range", "mtl", "newmtl white\nPm -0.5\n", "m.mtl:2: 'Pm' must be in [0, 1]"},
    {"mtl_d_range", "mtl", "newmtl white\nd 1.5\n", "m.mtl:2: 'd' must be in [0, 1]"},
    {"mtl_tr_range", "mtl", "newmtl white\nTr -0.5\n", "m.mtl:2: 'Tr' must be in [0, 1]"},
    {"mtl_d_text", "mtl", "newmtl white\nd half\n", "m.mtl:2: d: 'half' is not a number"},
    {"mtl_ka_text", "mtl", "newmtl white\nKa 1 x 1\n", "m.mtl:2: Ka: 'x' is not a number"},
    {"mtl_pc_text", "mtl", "newmtl white\nPc nan\n", "m.mtl:2: Pc: 'nan' is not finite"},
    {"mtl_map_without_file", "mtl", "newmtl white\nmap_Kd\n",
     "m.mtl:2: 'map_Kd' takes a file name"},
    {"mtl_texture_missing", "mtl",
     "newmtl white\nKd 0.5 0.5 0.5\nmap_Kd -s 1 1 1 nope.png\nnewmtl lamp\nKe 1 1 1\n",
     "m.mtl:3: cannot read texture build/test-scratch/parse-mtl_texture_missing/nope.png: "},
    {"mtl_texture_not_an_image", "mtl", "newmtl white\nmap_d m.obj\nnewmtl lamp\nKe 1 1 1\n",
     "m.mtl:2: cannot read texture build/test-scratch/parse-mtl_texture_not_an_image/m.obj: "},
    {"mtl_unknown_directive", "mtl", "newmtl white\nKx 1 1 1\n",
     "m.mtl:2: unsupported material directive 'Kx'"},
    {"obj_normal_arity", "obj", "vn 0 1\n", "m.obj:1: 'vn' takes 3 numbers"},
    {"obj_normal_text", "obj", "vn 0 up 1\n", "m.obj:1: normal: 'up' is not a number"},
    {"obj_normal_zero", "obj", "vn 0 0 0\n", "m.obj:1: 'vn' has zero length"},
    {"obj_normal_index", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nusemtl white\nf 1//1 2//2 3//1\n",
     "m.obj:7: face refers to normal 2 but 1 are defined"},
    {"obj_normal_index_zero", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nusemtl white\nf 1//0 2//1 3//1\n",
     "m.obj:7: face refers to normal 0 but 1 are defined"},
    {"obj_normal_index_negative", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nusemtl white\nf 1//-2 2//1 3//1\n",
     "m.obj:7: face refers to normal -2 but 1 are defined"},
    {"obj_normals_mixed", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nusemtl white\nf 1//1 2 3//1\n",
     "m.obj:7: face mixes references with and without normals"},
    {"obj_texcoord_index", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl white\nf 1/1 2/2 3/1\n",
     "m.obj:7: face refers to texture coordinate 2 but 1 are defined"},
    {"obj_reference_form", "obj",
     "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1/ 2 3\n",
     "m.obj:6: face reference '1/' is not v, v/t, v//n or v/t/n"},
    {"obj_smoothing_text", "obj", "s smooth\n",
     "m.obj:1: smoothing group: 'smooth' is not an integer"},
    {"obj_smoothing_negative", "obj", "s -1\n",
     "m.obj:1: 's' takes a smoothing group number or 'off'"},
    {"mtl_albedo_range", "mtl", "newmtl white\nKd 1.5 0 0\n", "m.mtl:2: 'Kd' values must be in"},
    {"mtl_negative_emission", "mtl", "newmtl white\nKe -1 0 0\n",
     "m.mtl:2: 'Ke' values must be in"},
    {"mtl_before_newmtl", "mtl", "Kd 1 1 1\n", "m.mtl:1: 'Kd' before any 'newmtl'"},
    {"mtl_duplicate", "mtl", "newmtl white\nnewmtl white\n",
     "m.mtl:2: material 'white' is defined twice"},
};

} // namespace

TEST(SceneParse, ValidSceneLoads) {
    EXPECT_EQ(load_error(Files(), "valid"), "");
    Scene s = test::scene("cornell-water", 16, 16);
    EXPECT_GT(s.triangles.size(), 1000u);
    EXPECT_EQ(s.depth, 24);
}

class SceneErrors : public ::testing::TestWithParam<Case> {};

TEST_P(SceneErrors, GiveTheirOwnMessage) {
    const Case& c = GetParam();
    Files f;
    if (std::string(c.file) == "scene") f.scene = c.text;
    if (std::string(c.file) == "obj") f.obj = c.text;
    if (std::string(c.file) == "mtl") f.mtl = c.text;
    std::string msg = load_error(f, c.name);
    EXPECT_EQ(msg.rfind(c.expected, 0), 0u) << "got: " << msg;
}

INSTANTIATE_TEST_SUITE_P(All, SceneErrors, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SceneParse, ZeroAreaTrianglesAreLeftOutAndCounted) {
    std::string dir = test::scratch_dir("parse-degenerate");
    test::write_file(dir + "/s.scene", kScene);
    test::write_file(dir + "/m.obj", std::string(kObj) + "usemtl white\nf 1 2 2\nf 1 1 1\n");
    test::write_file(dir + "/m.mtl", kMtl);
    Scene s = load_scene(dir + "/s.scene");
    EXPECT_EQ(s.triangles.size(), 2u);
    EXPECT_EQ(s.dropped_degenerate, 2);
}

namespace {

// The triangles of m.obj (`obj`) in the test scene, with kMtl's materials.
std::vector<SceneTriangle> load_triangles(const std::string& name, const std::string& obj) {
    std::string dir = test::scratch_dir("parse-" + name);
    test::write_file(dir + "/s.scene", kScene);
    test::write_file(dir + "/m.obj", obj);
    test::write_file(dir + "/m.mtl", kMtl);
    return load_scene(dir + "/s.scene").triangles;
}

bool same_point(Vec3 a, Vec3 b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

void expect_vec(Vec3 got, Vec3 want, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, 1e-6) << what;
    EXPECT_NEAR(got.y, want.y, 1e-6) << what;
    EXPECT_NEAR(got.z, want.z, 1e-6) << what;
}

// The lamp of the normals tests: a triangle of its own, at y = 5, in no
// smoothing group; flat, of normal (0, -1, 0).
const char* kLamp = "s off\nusemtl lamp\nf -3 -2 -1\n";
const char* kLampVertices = "v 0 5 0\nv 1 5 0\nv 0 5 1\n";

void expect_flat_lamp(const SceneTriangle& t) {
    EXPECT_FALSE(t.smooth);
    for (int k = 0; k < 3; ++k)
        expect_vec(t.n[k], {0, -1, 0}, "lamp vertex " + std::to_string(k));
}

} // namespace

// A quad whose corners carry normals of other lengths is split in two; each
// triangle vertex has the normal its corner gave, normalized, also in a
// smoothing group.
TEST(SceneParse, QuadVertexNormalsFollowTheirCornersIntoBothTriangles) {
    const Vec3 corner[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Vec3 normal[4] = {{0, 0, 1}, {0.6f, 0, 0.8f}, {0, 0.6f, 0.8f}, {-0.8f, 0, 0.6f}};
    std::vector<SceneTriangle> tris = load_triangles(
        "quad-normals", std::string("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n") +
                            kLampVertices + "vn 0 0 2\nvn 3 0 4\nvn 0 3 4\nvn -4 0 3\n" +
                            "s 1\nusemtl white\nf 1//1 2//2 3//3 4//4\n" + kLamp);
    ASSERT_EQ(tris.size(), 3u);
    bool covered[4] = {};
    for (int t = 0; t < 2; ++t) {
        EXPECT_TRUE(tris[t].smooth);
        for (int k = 0; k < 3; ++k) {
            int c = 0;
            while (c < 4 && !same_point(tris[t].v[k], corner[c]))
                ++c;
            ASSERT_LT(c, 4) << "triangle " << t << " vertex " << k << " is no corner";
            covered[c] = true;
            expect_vec(tris[t].n[k], normal[c],
                       "triangle " + std::to_string(t) + " vertex " + std::to_string(k));
        }
    }
    for (bool c : covered)
        EXPECT_TRUE(c);
    expect_flat_lamp(tris[2]);
}

TEST(SceneParse, TextureAndNormalReferencesTakeTheNormals) {
    std::vector<SceneTriangle> tris = load_triangles(
        "vtn-normals", std::string("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                   "vt 0 1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\nusemtl white\n"
                                   "f 1/1/3 2/2/2 3/3/1\nf -3/-3/-1 -2/-2/-2 -1/-1/-3\n") +
                           kLampVertices + kLamp);
    ASSERT_EQ(tris.size(), 3u);
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    expect_vec(tris[0].n[0], z, "first face, vertex 0");
    expect_vec(tris[0].n[1], y, "first face, vertex 1");
    expect_vec(tris[0].n[2], x, "first face, vertex 2");
    // Relative indices count back from the last element defined so far.
    expect_vec(tris[1].n[0], z, "second face, vertex 0");
    expect_vec(tris[1].n[1], y, "second face, vertex 1");
    expect_vec(tris[1].n[2], x, "second face, vertex 2");
    EXPECT_TRUE(tris[0].smooth && tris[1].smooth);
}

// Two triangles of one smoothing group meet at the edge A B at an angle:
// T1 = (A, B, C) has cross(e1, e2) = (0, 0, 1), T2 = (A, D, B) has
// (0, 2, 2). At A and B the normal is their sum normalized, (0, 2, 3) /
// sqrt(13); at C and D each triangle's own.
TEST(SceneParse, SmoothingGroupAveragesAreaWeightedNormalsAtSharedVertices) {
    std::vector<SceneTriangle> tris = load_triangles(
        "smooth-group", std::string("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -2 2\n") +
                            kLampVertices + "usemtl white\ns 1\nf 1 2 3\nf 1 4 2\n" + kLamp);
    ASSERT_EQ(tris.size(), 3u);
    const float r13 = 1 / std::sqrt(13.0f), r2 = 1 / std::sqrt(2.0f);
    const Vec3 shared{0, 2 * r13, 3 * r13};
    EXPECT_TRUE(tris[0].smooth && tris[1].smooth);
    expect_vec(tris[0].n[0], shared, "T1 at A");
    expect_vec(tris[0].n[1], shared, "T1 at B");
    expect_vec(tris[0].n[2], {0, 0, 1}, "T1 at C");
    expect_vec(tris[1].n[0], shared, "T2 at A");
    expect_vec(tris[1].n[1], {0, r2, r2}, "T2 at D");
    expect_vec(tris[1].n[2], shared, "T2 at B");
    expect_flat_lamp(tris[2]);
}

// The same two triangles: in two groups, each keeps its own normal (smooth,
// but nothing to average); with smoothing off (`s off`, `s 0`, no `s`),
// both are flat.
TEST(SceneParse, FacesOutsideOneSmoothingGroupKeepTheirGeometricNormals) {
    const char* variants[] = {"s 1\nf 1 2 3\ns 2\nf 1 4 2\n", "s off\nf 1 2 3\nf 1 4 2\n",
                              "s 0\nf 1 2 3\nf 1 4 2\n", "f 1 2 3\nf 1 4 2\n"};
    const float r2 = 1 / std::sqrt(2.0f);
    for (int i = 0; i < 4; ++i) {
        std::vector<SceneTriangle> tris =
            load_triangles("flat-" + std::to_string(i),
                           std::string("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -2 2\n") +
                               kLampVertices + "usemtl white\n" + variants[i] + kLamp);
        ASSERT_EQ(tris.size(), 3u);
        EXPECT_EQ(tris[0].smooth, i == 0) << variants[i];
        EXPECT_EQ(tris[1].smooth, i == 0) << variants[i];
        for (int k = 0; k < 3; ++k) {
            expect_vec(tris[0].n[k], {0, 0, 1}, std::string(variants[i]) + "T1");
            expect_vec(tris[1].n[k], {0, r2, r2}, std::string(variants[i]) + "T2");
        }
        expect_flat_lamp(tris[2]);
    }
}
