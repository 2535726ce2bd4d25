// Scene, OBJ and MTL readers: a valid scene loads; each unsupported or
// malformed input gives its own error naming the file and line.
#include "base/error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

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
    {"mtl_unknown_directive", "mtl", "newmtl white\nKx 1 1 1\n",
     "m.mtl:2: unsupported material directive 'Kx'"},
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
