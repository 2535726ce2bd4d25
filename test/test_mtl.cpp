// The MTL reader as modelling tools write MTL files: every illum value and
// the PBR directives become the Material of doc/scene-format.md's tables;
// what no model shows warns once per file and directive; Blender's exports
// load.
#include "base/error.hpp"
#include "scene/material.hpp"
#include "scene/mtl_models.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

// Strips "DIR/" from the start of each warning.
void relative(std::vector<std::string>& warnings, const std::string& dir) {
    for (std::string& w : warnings)
        if (w.rfind(dir + "/", 0) == 0) w = w.substr(dir.size() + 1);
}

// Writes `text` as m.mtl in a fresh directory and reads it; its warnings
// name m.mtl relative to that directory.
Scene read_mtl(const std::string& name, const std::string& text) {
    std::string dir = test::scratch_dir("mtl-" + name);
    test::write_file(dir + "/m.mtl", text);
    Scene s;
    load_mtl(dir + "/m.mtl", s);
    relative(s.warnings, dir);
    return s;
}

std::string str(Vec3 v) {
    return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z);
}

void expect_rgb(const f32 got[3], Vec3 want, const char* what) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(got[i], want[i], 1e-6) << what << " channel " << i << ", want " << str(want);
}

struct ModelCase {
    const char* name;
    const char* body; // the lines after "newmtl m"
    u32 type;
    Vec3 kd, ks;
    float ior, alpha;
    Vec3 eta, k;
};

const Vec3 kZero{0, 0, 0}, kOne{1, 1, 1}, kColour{0.2f, 0.4f, 0.6f}, kHalf{0.5f, 0.5f, 0.5f};

// Ns 250 is roughness 1 - sqrt(250 / 1000) = 0.5, alpha 0.25; Ns 90 is
// roughness 0.7, alpha 0.49.
const ModelCase kModels[] = {
    {"illum0_is_diffuse", "Kd 0.2 0.4 0.6\nillum 0\n", MAT_DIFFUSE, kColour, kZero, 1, 0, kZero,
     kZero},
    {"illum1_is_diffuse_without_its_ks", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 250\nillum 1\n",
     MAT_DIFFUSE, kColour, kZero, 1, 0, kZero, kZero},
    {"no_illum_is_diffuse", "Kd 0.2 0.4 0.6\n", MAT_DIFFUSE, kColour, kZero, 1, 0, kZero, kZero},
    {"illum2_is_plastic_roughened_by_ns",
     "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNi 1.45\nNs 250\nillum 2\n", MAT_ROUGH_PLASTIC, kColour,
     kHalf, 1.45f, 0.25f, kZero, kZero},
    {"illum2_without_ni_has_index_1_5", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nillum 2\n", MAT_PLASTIC,
     kColour, kHalf, 1.5f, 0, kZero, kZero},
    {"illum2_with_zero_ks_is_diffuse", "Kd 0.2 0.4 0.6\nKs 0 0 0\nNs 250\nillum 2\n", MAT_DIFFUSE,
     kColour, kZero, 1, 0, kZero, kZero},
    {"illum3_is_a_mirror_of_ks",
     "Kd 0.2 0.4 0.6\nKs 0.9 0.8 0.7\nillum 3\n",
     MAT_CONDUCTOR,
     kZero,
     {0.9f, 0.8f, 0.7f},
     1,
     0,
     kZero,
     kOne},
    {"illum5_with_ns_is_a_rough_mirror",
     "Ks 0.9 0.8 0.7\nNs 90\nillum 5\n",
     MAT_ROUGH_CONDUCTOR,
     kZero,
     {0.9f, 0.8f, 0.7f},
     1,
     0.49f,
     kZero,
     kOne},
    {"illum8_is_a_mirror", "Ks 0.5 0.5 0.5\nillum 8\n", MAT_CONDUCTOR, kZero, kHalf, 1, 0, kZero,
     kOne},
    {"illum4_is_a_dielectric", "Ni 1.33\nillum 4\n", MAT_DIELECTRIC, kZero, kOne, 1.33f, 0, kZero,
     kZero},
    {"illum6_is_a_dielectric", "Ni 1.33\nillum 6\n", MAT_DIELECTRIC, kZero, kOne, 1.33f, 0, kZero,
     kZero},
    {"illum7_is_a_dielectric", "Ni 1.5\nillum 7\n", MAT_DIELECTRIC, kZero, kOne, 1.5f, 0, kZero,
     kZero},
    {"illum9_with_pr_is_a_rough_dielectric", "Ni 1.5\nPr 0.3\nillum 9\n", MAT_ROUGH_DIELECTRIC,
     kZero, kOne, 1.5f, 0.09f, kZero, kZero},
    {"illum10_is_diffuse", "Kd 0.2 0.4 0.6\nillum 10\n", MAT_DIFFUSE, kColour, kZero, 1, 0, kZero,
     kZero},
    {"pr_overrides_ns", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 250\nPr 0.2\nillum 2\n",
     MAT_ROUGH_PLASTIC, kColour, kHalf, 1.5f, 0.04f, kZero, kZero},
    {"ns_0_is_the_roughest", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 0\nillum 2\n", MAT_ROUGH_PLASTIC,
     kColour, kHalf, 1.5f, 1, kZero, kZero},
    {"ns_1000_is_smooth", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 1000\nillum 2\n", MAT_PLASTIC,
     kColour, kHalf, 1.5f, 0, kZero, kZero},
    {"pr_below_the_smooth_limit_is_smooth", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nPr 0.03\nillum 2\n",
     MAT_PLASTIC, kColour, kHalf, 1.5f, 0, kZero, kZero},
    {"pm1_is_a_rough_conductor_of_kd",
     "Kd 0.8 0.6 0.2\nKs 0.5 0.5 0.5\nNi 1.45\nPr 0.5\nPm 1\nillum 2\n",
     MAT_ROUGH_CONDUCTOR,
     kZero,
     {0.8f, 0.6f, 0.2f},
     1,
     0.25f,
     kZero,
     kOne},
    {"pm1_makes_illum1_a_metal",
     "Kd 0.8 0.6 0.2\nPm 1\nillum 1\n",
     MAT_CONDUCTOR,
     kZero,
     {0.8f, 0.6f, 0.2f},
     1,
     0,
     kZero,
     kOne},
    {"pm_one_half_is_a_metal_without_ks",
     "Kd 0.8 0.6 0.2\nPm 0.5\nillum 3\n",
     MAT_CONDUCTOR,
     kZero,
     {0.8f, 0.6f, 0.2f},
     1,
     0,
     kZero,
     kOne},
    {"pm_below_one_half_is_not_a_metal", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nPm 0.4\nillum 2\n",
     MAT_PLASTIC, kColour, kHalf, 1.5f, 0, kZero, kZero},
    {"pm1_leaves_a_dielectric_a_dielectric", "Kd 0.8 0.6 0.2\nNi 1.5\nPm 1\nillum 7\n",
     MAT_DIELECTRIC, kZero, kOne, 1.5f, 0, kZero, kZero},
};

void PrintTo(const ModelCase& c, std::ostream* os) {
    *os << c.name;
}

class MtlModels : public ::testing::TestWithParam<ModelCase> {};

} // namespace

TEST_P(MtlModels, BecomeTheMaterialOfTheirRow) {
    const ModelCase& c = GetParam();
    Scene s = read_mtl(c.name, std::string("newmtl m\n") + c.body);
    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_EQ(m.type, c.type);
    expect_rgb(m.kd, c.kd, "kd");
    expect_rgb(m.ks, c.ks, "ks");
    EXPECT_NEAR(m.ior, c.ior, 1e-6);
    EXPECT_NEAR(m.alpha, c.alpha, 1e-6);
    expect_rgb(m.eta, c.eta, "eta");
    expect_rgb(m.k, c.k, "k");
    EXPECT_EQ(m.emissive, 0u);
}

INSTANTIATE_TEST_SUITE_P(Rows, MtlModels, ::testing::ValuesIn(kModels),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(MtlRoughness, NsIsBlendersExportInverted) {
    // Blender writes Ns = 1000 (1 - r)^2.
    for (float r : {0.0f, 0.1f, 0.5f, 0.9f, 1.0f})
        EXPECT_NEAR(roughness_from_ns(1000 * (1 - r) * (1 - r)), r, 1e-6) << "r = " << r;
    EXPECT_EQ(roughness_from_ns(0), 1.0f);
    EXPECT_EQ(roughness_from_ns(1000), 0.0f);
}

TEST(MtlEmission, EveryModelEmitsItsKe) {
    const char* bodies[] = {"illum 1\n", "Ks 0.5 0.5 0.5\nillum 2\n", "Ks 1 1 1\nillum 3\n",
                            "Ni 1.5\nillum 7\n", "Kd 1 1 1\nPm 1\n"};
    for (const char* body : bodies) {
        Scene s = read_mtl("emission", std::string("newmtl m\nKe 2 3 4\n") + body);
        ASSERT_EQ(s.materials.size(), 1u);
        EXPECT_EQ(s.materials[0].emissive, 1u) << body;
        expect_rgb(s.materials[0].ke, {2, 3, 4}, body);
    }
}

namespace {

// A directive that changes nothing in the model its context makes: the
// file has two materials, each with the context's lines and then `line`.
struct IgnoredCase {
    const char* name;
    const char* context;   // lines after newmtl, each ending in \n
    const char* line;      // the directive's line
    const char* directive; // as the warning names it
    const char* constant;  // a texture map's: the constant used instead
};

std::string changes_nothing(const std::string& d) {
    return "'" + d + "' changes nothing in these models";
}

std::string not_read(const std::string& map, const std::string& constant) {
    return "'" + map + "' is not read yet (textures are not supported): the constant '" + constant +
           "' is used, or its default";
}

const IgnoredCase kIgnored[] = {
    {"ka", "illum 1\n", "Ka 1 1 1", "Ka", nullptr},
    {"map_ka", "illum 1\n", "map_Ka -s 1 1 1 a.png", "map_Ka", nullptr},
    {"tf", "illum 1\n", "Tf 1 1 1", "Tf", nullptr},
    {"ni_on_diffuse", "illum 1\n", "Ni 1.45", "Ni", nullptr},
    {"ni_on_a_mirror", "Ks 1 1 1\nillum 3\n", "Ni 1.45", "Ni", nullptr},
    {"ni_on_a_metal", "Kd 1 1 1\nPm 1\n", "Ni 1.45", "Ni", nullptr},
    {"ns_on_diffuse", "illum 1\n", "Ns 250", "Ns", nullptr},
    {"ns_beside_pr", "Ks 0.5 0.5 0.5\nPr 0.5\nillum 2\n", "Ns 250", "Ns", nullptr},
    {"pr_on_diffuse", "illum 0\n", "Pr 0.5", "Pr", nullptr},
    {"ks_on_diffuse", "illum 1\n", "Ks 0.5 0.5 0.5", "Ks", nullptr},
    {"ks_on_a_dielectric", "Ni 1.5\nillum 7\n", "Ks 0.5 0.5 0.5", "Ks", nullptr},
    {"ks_on_a_metal", "Kd 1 1 1\nPm 1\n", "Ks 0.5 0.5 0.5", "Ks", nullptr},
    {"kd_on_a_dielectric", "Ni 1.5\nillum 7\n", "Kd 0.5 0.5 0.5", "Kd", nullptr},
    {"kd_on_a_mirror", "Ks 1 1 1\nillum 5\n", "Kd 0.5 0.5 0.5", "Kd", nullptr},
    {"pm_on_a_dielectric", "Ni 1.5\nillum 7\n", "Pm 1", "Pm", nullptr},
    {"pc", "illum 1\n", "Pc 0.5", "Pc", nullptr},
    {"pcr_under_a_coat", "Pc 0.5\n", "Pcr 0.03", "Pcr", nullptr},
    {"ps", "illum 1\n", "Ps 0.5", "Ps", nullptr},
    {"aniso", "illum 1\n", "aniso 0.5", "aniso", nullptr},
    {"anisor_of_anisotropy", "aniso 0.5\n", "anisor 0.25", "anisor", nullptr},
    {"sharpness", "illum 1\n", "sharpness 60", "sharpness", nullptr},
    {"map_bump", "illum 1\n", "map_Bump -bm 1.000000 normal.png", "map_Bump", nullptr},
    {"bump", "illum 1\n", "bump -bm 0.5 height.png", "bump", nullptr},
    {"norm", "illum 1\n", "norm normal.png", "norm", nullptr},
    {"disp", "illum 1\n", "disp height.png", "disp", nullptr},
    {"decal", "illum 1\n", "decal mask.png", "decal", nullptr},
    {"refl", "illum 1\n", "refl -type sphere sky.png", "refl", nullptr},
    {"map_ps", "illum 1\n", "map_Ps sheen.png", "map_Ps", nullptr},
    {"map_kd", "illum 1\n", "map_Kd -o 0.5 0.5 0 wood.png", "map_Kd", "Kd"},
    {"map_ks", "Ks 0.5 0.5 0.5\nillum 2\n", "map_Ks spec.png", "map_Ks", "Ks"},
    {"map_ke", "illum 1\n", "map_Ke glow.png", "map_Ke", "Ke"},
    {"map_ns", "Ks 0.5 0.5 0.5\nillum 2\n", "map_Ns gloss.png", "map_Ns", "Ns"},
    {"map_pr", "Ks 0.5 0.5 0.5\nillum 2\n", "map_Pr -s 2 2 1 rough.png", "map_Pr", "Pr"},
    {"map_pm", "illum 1\n", "map_Pm metal.png", "map_Pm", "Pm"},
    {"map_d", "illum 1\n", "map_d -imfchan m alpha.png", "map_d", "d"},
};

void PrintTo(const IgnoredCase& c, std::ostream* os) {
    *os << c.name;
}

class MtlIgnored : public ::testing::TestWithParam<IgnoredCase> {};

int lines_in(const std::string& s) {
    int n = 0;
    for (char c : s)
        n += c == '\n';
    return n;
}

} // namespace

// Two materials each have the line: one warning, at the first.
TEST_P(MtlIgnored, WarnsOncePerFileAtTheFirstLineWithTheCount) {
    const IgnoredCase& c = GetParam();
    std::string block = std::string(c.context) + c.line + "\n";
    Scene s =
        read_mtl(std::string("ignored-") + c.name, "newmtl a\n" + block + "newmtl b\n" + block);
    ASSERT_EQ(s.materials.size(), 2u);
    std::string text =
        c.constant ? not_read(c.directive, c.constant) : changes_nothing(c.directive);
    std::string want = "m.mtl:" + std::to_string(2 + lines_in(c.context)) + ": warning: " + text +
                       " (ignored; 2 lines)";
    std::vector<std::string> about;
    for (const std::string& w : s.warnings)
        if (w.find("'" + std::string(c.directive) + "'") != std::string::npos) about.push_back(w);
    ASSERT_EQ(about.size(), 1u) << (s.warnings.empty() ? "no warning" : s.warnings[0]);
    EXPECT_EQ(about[0], want);
}

INSTANTIATE_TEST_SUITE_P(Directives, MtlIgnored, ::testing::ValuesIn(kIgnored),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(MtlWarnings, UsedDirectivesAndNeutralValuesDoNotWarn) {
    Scene s = read_mtl("quiet", "newmtl plastic\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nKe 0 0 0\n"
                                "Ni 1.45\nNs 250\nd 1\nTr 0\nillum 2\nPm 0\nPc 0\nPcr 0.03\n"
                                "Ps 0\naniso 0\nanisor 0\n"
                                "newmtl glass\nKd 0 0 0\nKs 0 0 0\nNi 1.5\nPr 0.1\nillum 7\n"
                                "newmtl mirror\nKs 0.9 0.9 0.9\nNs 500\nillum 3\n"
                                "newmtl metal\nKd 0.9 0.6 0.3\nPr 0.2\nPm 1\nillum 2\n"
                                "newmtl lamp\nKd 0 0 0\nKs 0 0 0\nKe 5 5 5\nillum 1\n");
    EXPECT_EQ(s.materials.size(), 5u);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
}

TEST(MtlWarnings, OpaqueDoesNotWarnAndPartialTransparencyDoes) {
    EXPECT_TRUE(read_mtl("d-1", "newmtl m\nd 1.000000\n").warnings.empty());
    EXPECT_TRUE(read_mtl("tr-0", "newmtl m\nTr 0.000000\n").warnings.empty());
    const std::string rest = "': partial transparency is not modelled and the surface renders "
                             "opaque; a cut-out through map_d will come with textures (1 line)";
    Scene d = read_mtl("d-half", "newmtl m\nKd 1 1 1\nd 0.5\n");
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_EQ(d.warnings[0], "m.mtl:3: warning: 'd 0.5" + rest);
    EXPECT_EQ(d.materials[0].type, u32(MAT_DIFFUSE));
    Scene tr = read_mtl("tr-quarter", "newmtl m\nTr 0.25\n");
    ASSERT_EQ(tr.warnings.size(), 1u);
    EXPECT_EQ(tr.warnings[0], "m.mtl:2: warning: 'Tr 0.25" + rest);
}

TEST(MtlWarnings, MetallicBelowOneHalfIsRoundedToZero) {
    Scene s = read_mtl("pm-low", "newmtl a\nPm 0.3\nnewmtl b\nPm 0.2\nnewmtl c\nPm 0\n");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], "m.mtl:2: warning: metallic Pm 0.3 is rounded to 0: materials are "
                             "either metal or not, and metal from Pm 0.5 up (2 lines)");
    for (const Material& m : s.materials)
        EXPECT_EQ(m.type, u32(MAT_DIFFUSE));
}

TEST(MtlWarnings, Illum10SaysTheShadowMatteIsNotModelled) {
    Scene s = read_mtl("illum10", "newmtl m\nKd 1 1 1\nillum 10\n");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], "m.mtl:3: warning: illum 10: the shadow matte is not modelled; the "
                             "material renders as with illum 1 (1 line)");
}

// Two meshes, each with its MTL file: each file warns about its own lines,
// and the scene carries both warnings.
TEST(MtlWarnings, EachFileWarnsForItselfAndTheSceneKeepsTheWarnings) {
    std::string dir = test::scratch_dir("mtl-two-files");
    test::write_file(dir + "/s.scene", "camera 0 1 3  0 1 0  0 1 0  40\nmesh a.obj\nmesh b.obj\n");
    test::write_file(dir + "/a.obj", "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\n"
                                     "f 1 2 3\n");
    test::write_file(dir + "/b.obj", "mtllib b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl grey\n"
                                     "f 1 2 3\n");
    test::write_file(dir + "/a.mtl", "newmtl lamp\nKa 1 1 1\nKe 1 1 1\n");
    test::write_file(dir + "/b.mtl", "# grey\nnewmtl grey\nKd 0.5 0.5 0.5\nKa 0 0 0\nKa 1 1 1\n");
    Scene s = load_scene(dir + "/s.scene");
    relative(s.warnings, dir);
    std::vector<std::string> want = {
        "a.mtl:2: warning: 'Ka' changes nothing in these models (ignored; 1 line)",
        "b.mtl:4: warning: 'Ka' changes nothing in these models (ignored; 2 lines)"};
    EXPECT_EQ(s.warnings, want);
}

// Also: the warnings of a file come in the order of their first lines,
// whether found as the line is read (maps) or once its material is complete.
TEST(MtlBlender, DefaultExportOfBlender41LoadsAsRoughPlastic) {
    std::string dir = test::scratch_dir("mtl-blender41");
    test::write_file(dir + "/s.scene", "camera 0 1 3  0 1 0  0 1 0  40\nmesh m.obj\n");
    test::write_file(dir + "/m.obj", "# Blender 4.1\nmtllib m.mtl lamp.mtl\no Cube\nv 0 0 0\n"
                                     "v 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\n"
                                     "vt 1 1\nvt 0 1\ns 0\nusemtl Material\n"
                                     "f 1/1/1 2/2/1 3/3/1 4/4/1\nusemtl lamp\nf 1 2 3\n");
    test::write_file(dir + "/m.mtl", "# Blender 4.1 MTL File: 'None'\n# www.blender.org\n\n"
                                     "newmtl Material\nNs 250.000000\nKa 1.000000 1.000000 "
                                     "1.000000\nKs 0.500000 0.500000 0.500000\nKe 0.000000 "
                                     "0.000000 0.000000\nNi 1.450000\nd 1.000000\nillum 2\n"
                                     "map_Kd texture.png\n");
    test::write_file(dir + "/lamp.mtl", "newmtl lamp\nKe 1 1 1\n");
    Scene s = load_scene(dir + "/s.scene");
    relative(s.warnings, dir);
    ASSERT_EQ(s.material_names[0], "Material");
    const Material& m = s.materials[0];
    EXPECT_EQ(m.type, u32(MAT_ROUGH_PLASTIC));
    expect_rgb(m.kd, kZero, "kd"); // no Kd where map_Kd is written
    expect_rgb(m.ks, kHalf, "ks");
    EXPECT_NEAR(m.ior, 1.45f, 1e-6);
    EXPECT_NEAR(m.alpha, 0.25f, 1e-6); // roughness 0.5, Blender's default
    std::vector<std::string> want = {
        "m.mtl:6: warning: 'Ka' changes nothing in these models (ignored; 1 line)",
        "m.mtl:12: warning: 'map_Kd' is not read yet (textures are not supported): the constant "
        "'Kd' is used, or its default (ignored; 1 line)"};
    EXPECT_EQ(s.warnings, want);
    EXPECT_EQ(s.triangles.size(), 3u);
}

TEST(MtlBlender, PbrExportOfBlender4Loads) {
    Scene s = read_mtl("blender-pbr",
                       "# Blender 4.1 MTL File: 'None'\n# www.blender.org\n\n"
                       "newmtl Metal\n" // 4
                       "Kd 0.800000 0.500000 0.200000\n"
                       "Ks 0.500000 0.500000 0.500000\n" // 6
                       "Ke 0.000000 0.000000 0.000000\n"
                       "Ni 1.500000\n" // 8
                       "d 1.000000\nillum 3\nPr 0.300000\nPm 1.000000\nPs 0.000000\n"
                       "Pc 0.000000\nPcr 0.030000\naniso 0.000000\nanisor 0.000000\n\n" // 18
                       "newmtl Painted\n"                                               // 19
                       "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\n"
                       "Ni 1.450000\nd 1.000000\nillum 2\nPm 0.000000\nPs 0.000000\n" // 26
                       "Pc 0.000000\nPcr 0.030000\naniso 0.000000\nanisor 0.000000\n" // 30
                       "map_Kd paint.png\n"                                           // 31
                       "map_Pr -s 2.000000 2.000000 1.000000 rough.png\n");           // 32
    ASSERT_EQ(s.materials.size(), 2u);
    const Material& metal = s.materials[0];
    EXPECT_EQ(metal.type, u32(MAT_ROUGH_CONDUCTOR));
    expect_rgb(metal.ks, {0.8f, 0.5f, 0.2f}, "metal ks");
    EXPECT_NEAR(metal.alpha, 0.09f, 1e-6);
    EXPECT_EQ(s.materials[1].type, u32(MAT_PLASTIC)); // its roughness is in the map
    std::vector<std::string> want = {
        "m.mtl:6: warning: 'Ks' changes nothing in these models (ignored; 1 line)",
        "m.mtl:8: warning: 'Ni' changes nothing in these models (ignored; 1 line)",
        "m.mtl:31: warning: " + not_read("map_Kd", "Kd") + " (ignored; 1 line)",
        "m.mtl:32: warning: " + not_read("map_Pr", "Pr") + " (ignored; 1 line)"};
    EXPECT_EQ(s.warnings, want);
}
