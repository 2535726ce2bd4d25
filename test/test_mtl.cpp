// The MTL reader as modelling tools write MTL files: every illum value and
// the PBR directives become the Material of doc/scene-format.md's tables;
// the texture maps go to the fields their model reads, each file loaded once
// per kind; what no model shows warns once per file and directive;
// Blender's exports load.
#include "base/error.hpp"
#include "scene/material.hpp"
#include "scene/mtl_models.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdint>

using namespace smallmlt;

namespace {

// Strips "DIR/" from the start of each warning and each texture's file.
void relative(Scene& s, const std::string& dir) {
    for (std::string& w : s.warnings)
        if (w.rfind(dir + "/", 0) == 0) w = w.substr(dir.size() + 1);
    for (SceneTexture& t : s.textures)
        if (t.file.rfind(dir + "/", 0) == 0) t.file = t.file.substr(dir.size() + 1);
}

// An image the test writes beside its MTL file.
struct Png {
    const char* file;
    int width, height, channels; // 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA
};

// The test images' byte of channel c at pixel i (top row first).
std::uint8_t pattern(int i, int c) {
    return std::uint8_t(40 * c + 7 * i + 3);
}

// Pixel i of an RGBA test image as a texel: R in the low byte.
std::uint32_t rgba_texel(int i) {
    return std::uint32_t(pattern(i, 0)) | std::uint32_t(pattern(i, 1)) << 8 |
           std::uint32_t(pattern(i, 2)) << 16 | std::uint32_t(pattern(i, 3)) << 24;
}

void write_png(const std::string& path, const Png& p) {
    std::vector<std::uint8_t> px(std::size_t(p.width) * p.height * p.channels);
    for (int i = 0; i < p.width * p.height; ++i)
        for (int c = 0; c < p.channels; ++c)
            px[std::size_t(i) * p.channels + c] = pattern(i, c);
    if (!stbi_write_png(path.c_str(), p.width, p.height, p.channels, px.data(),
                        p.width * p.channels))
        throw std::runtime_error("cannot write " + path);
}

// Writes `text` as m.mtl in a fresh directory, with the images `pngs`
// beside it, and reads it; its warnings and textures name their files
// relative to that directory.
Scene read_mtl(const std::string& name, const std::string& text,
               std::initializer_list<Png> pngs = {}) {
    std::string dir = test::scratch_dir("mtl-" + name);
    test::write_file(dir + "/m.mtl", text);
    for (const Png& p : pngs)
        write_png(dir + "/" + p.file, p);
    Scene s;
    load_mtl(dir + "/m.mtl", s);
    relative(s, dir);
    return s;
}

// The texture fields of a Material, and their names for messages.
const std::pair<u32 Material::*, const char*> kTexFields[] = {{&Material::kd_tex, "kd_tex"},
                                                              {&Material::ks_tex, "ks_tex"},
                                                              {&Material::rough_tex, "rough_tex"},
                                                              {&Material::alpha_tex, "alpha_tex"}};

void expect_no_textures(const Material& m, const std::string& what) {
    for (const auto& [field, name] : kTexFields)
        EXPECT_EQ(m.*field, TEX_NONE) << what << ": " << name;
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
    expect_no_textures(m, c.name);
    EXPECT_TRUE(s.textures.empty());
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
    const char* constant;  // a map that is not read: the constant used instead
    const char* why;       // and why it is not read
};

std::string changes_nothing(const std::string& d) {
    return "'" + d + "' changes nothing in these models";
}

std::string not_read(const std::string& map, const std::string& constant, const std::string& why) {
    return "'" + map + "' is not read (" + why + "): the constant '" + constant +
           "' is used, or its default";
}

const IgnoredCase kIgnored[] = {
    {"ka", "illum 1\n", "Ka 1 1 1", "Ka", nullptr, nullptr},
    {"map_ka", "illum 1\n", "map_Ka -s 1 1 1 a.png", "map_Ka", nullptr, nullptr},
    {"tf", "illum 1\n", "Tf 1 1 1", "Tf", nullptr, nullptr},
    {"ni_on_diffuse", "illum 1\n", "Ni 1.45", "Ni", nullptr, nullptr},
    {"ni_on_a_mirror", "Ks 1 1 1\nillum 3\n", "Ni 1.45", "Ni", nullptr, nullptr},
    {"ni_on_a_metal", "Kd 1 1 1\nPm 1\n", "Ni 1.45", "Ni", nullptr, nullptr},
    {"ns_on_diffuse", "illum 1\n", "Ns 250", "Ns", nullptr, nullptr},
    {"ns_beside_pr", "Ks 0.5 0.5 0.5\nPr 0.5\nillum 2\n", "Ns 250", "Ns", nullptr, nullptr},
    {"pr_on_diffuse", "illum 0\n", "Pr 0.5", "Pr", nullptr, nullptr},
    {"ks_on_diffuse", "illum 1\n", "Ks 0.5 0.5 0.5", "Ks", nullptr, nullptr},
    {"ks_on_a_dielectric", "Ni 1.5\nillum 7\n", "Ks 0.5 0.5 0.5", "Ks", nullptr, nullptr},
    {"ks_on_a_metal", "Kd 1 1 1\nPm 1\n", "Ks 0.5 0.5 0.5", "Ks", nullptr, nullptr},
    {"kd_on_a_dielectric", "Ni 1.5\nillum 7\n", "Kd 0.5 0.5 0.5", "Kd", nullptr, nullptr},
    {"kd_on_a_mirror", "Ks 1 1 1\nillum 5\n", "Kd 0.5 0.5 0.5", "Kd", nullptr, nullptr},
    {"pm_on_a_dielectric", "Ni 1.5\nillum 7\n", "Pm 1", "Pm", nullptr, nullptr},
    {"pc", "illum 1\n", "Pc 0.5", "Pc", nullptr, nullptr},
    {"pcr_under_a_coat", "Pc 0.5\n", "Pcr 0.03", "Pcr", nullptr, nullptr},
    {"ps", "illum 1\n", "Ps 0.5", "Ps", nullptr, nullptr},
    {"aniso", "illum 1\n", "aniso 0.5", "aniso", nullptr, nullptr},
    {"anisor_of_anisotropy", "aniso 0.5\n", "anisor 0.25", "anisor", nullptr, nullptr},
    {"sharpness", "illum 1\n", "sharpness 60", "sharpness", nullptr, nullptr},
    {"map_bump", "illum 1\n", "map_Bump -bm 1.000000 normal.png", "map_Bump", nullptr, nullptr},
    {"bump", "illum 1\n", "bump -bm 0.5 height.png", "bump", nullptr, nullptr},
    {"norm", "illum 1\n", "norm normal.png", "norm", nullptr, nullptr},
    {"disp", "illum 1\n", "disp height.png", "disp", nullptr, nullptr},
    {"decal", "illum 1\n", "decal mask.png", "decal", nullptr, nullptr},
    {"refl", "illum 1\n", "refl -type sphere sky.png", "refl", nullptr, nullptr},
    {"map_ps", "illum 1\n", "map_Ps sheen.png", "map_Ps", nullptr, nullptr},
    // Maps where the model has nothing they replace: their files are not
    // read (none of these exists).
    {"map_kd_on_a_mirror", "Ks 1 1 1\nillum 3\n", "map_Kd -o 0.5 0.5 0 wood.png", "map_Kd", nullptr,
     nullptr},
    {"map_kd_on_a_dielectric", "Ni 1.5\nillum 7\n", "map_Kd wood.png", "map_Kd", nullptr, nullptr},
    {"map_ks_on_diffuse", "illum 1\n", "map_Ks spec.png", "map_Ks", nullptr, nullptr},
    {"map_ks_on_a_metal", "Kd 1 1 1\nPm 1\n", "map_Ks spec.png", "map_Ks", nullptr, nullptr},
    {"map_ks_on_a_dielectric", "Ni 1.5\nillum 7\n", "map_Ks spec.png", "map_Ks", nullptr, nullptr},
    {"map_pr_on_diffuse", "illum 1\n", "map_Pr -s 2 2 1 rough.png", "map_Pr", nullptr, nullptr},
    {"map_d_on_a_dielectric", "Ni 1.5\nillum 7\n", "map_d -imfchan m alpha.png", "map_d", nullptr,
     nullptr},
    {"map_d_on_an_emitter", "Ke 1 1 1\n", "map_d alpha.png", "map_d", nullptr, nullptr},
    // Maps of a value no model takes a texture for.
    {"map_ke", "illum 1\n", "map_Ke glow.png", "map_Ke", "Ke", "emission is not textured"},
    {"map_ns", "Ks 0.5 0.5 0.5\nillum 2\n", "map_Ns gloss.png", "map_Ns", "Ns",
     "the roughness map is map_Pr"},
    {"map_pm", "illum 1\n", "map_Pm -bm 1 metal.png", "map_Pm", "Pm", "a material is metal or not"},
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
        c.constant ? not_read(c.directive, c.constant, c.why) : changes_nothing(c.directive);
    std::string want = "m.mtl:" + std::to_string(2 + lines_in(c.context)) + ": warning: " + text +
                       " (ignored; 2 lines)";
    std::vector<std::string> about;
    for (const std::string& w : s.warnings)
        if (w.find("'" + std::string(c.directive) + "'") != std::string::npos) about.push_back(w);
    ASSERT_EQ(about.size(), 1u) << (s.warnings.empty() ? "no warning" : s.warnings[0]);
    EXPECT_EQ(about[0], want);
    // Nothing is loaded for a line that changes nothing.
    EXPECT_TRUE(s.textures.empty());
    for (const Material& m : s.materials)
        expect_no_textures(m, c.name);
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
                             "opaque (map_d makes a cut-out) (1 line)";
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
    relative(s, dir);
    std::vector<std::string> want = {
        "a.mtl:2: warning: 'Ka' changes nothing in these models (ignored; 1 line)",
        "b.mtl:4: warning: 'Ka' changes nothing in these models (ignored; 2 lines)"};
    EXPECT_EQ(s.warnings, want);
}

// With the image it names: the base colour is the texture, the quad's
// texture coordinates reach its two triangles.
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
    write_png(dir + "/texture.png", {"texture.png", 4, 3, 3});
    Scene s = load_scene(dir + "/s.scene");
    relative(s, dir);
    ASSERT_EQ(s.material_names[0], "Material");
    const Material& m = s.materials[0];
    EXPECT_EQ(m.type, u32(MAT_ROUGH_PLASTIC));
    // No Kd where map_Kd is written: the constant is the image's mean, in
    // linear light, and the coat's choice weight follows it.
    ASSERT_EQ(s.textures.size(), 1u);
    double mean[3] = {0, 0, 0};
    for (u32 t : s.textures[0].texels)
        for (int c = 0; c < 3; ++c)
            mean[c] += srgb_to_linear(((t >> (8 * c)) & 0xFFu) / 255.0) / 12;
    expect_rgb(m.kd, {float(mean[0]), float(mean[1]), float(mean[2])}, "kd");
    EXPECT_GT(mean[0] + mean[1] + mean[2], 0.1);
    expect_rgb(m.ks, kHalf, "ks");
    double lum_d = 0.2126 * mean[0] + 0.7152 * mean[1] + 0.0722 * mean[2];
    EXPECT_NEAR(m.spec_weight, 0.5 / (0.5 + lum_d), 1e-5);
    EXPECT_NEAR(m.ior, 1.45f, 1e-6);
    EXPECT_NEAR(m.alpha, 0.25f, 1e-6); // roughness 0.5, Blender's default
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(m.kd_tex, 0u);
    EXPECT_EQ(m.ks_tex, TEX_NONE);
    EXPECT_EQ(m.rough_tex, TEX_NONE);
    EXPECT_EQ(m.alpha_tex, TEX_NONE);
    EXPECT_EQ(s.textures[0].file, "texture.png");
    EXPECT_EQ(s.textures[0].kind, TextureKind::Colour);
    EXPECT_EQ(s.textures[0].width, 4);
    EXPECT_EQ(s.textures[0].height, 3);
    ASSERT_EQ(s.material_names[1], "lamp");
    expect_no_textures(s.materials[1], "lamp");
    std::vector<std::string> want = {
        "m.mtl:6: warning: 'Ka' changes nothing in these models (ignored; 1 line)"};
    EXPECT_EQ(s.warnings, want);
    ASSERT_EQ(s.triangles.size(), 3u);
    // Here vt k is vertex k's x and y; the lamp's face gives none.
    for (int t = 0; t < 2; ++t)
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(s.triangles[t].uv[k][0], s.triangles[t].v[k].x) << t << " " << k;
            EXPECT_EQ(s.triangles[t].uv[k][1], s.triangles[t].v[k].y) << t << " " << k;
        }
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(s.triangles[2].uv[k][0], 0.0f);
        EXPECT_EQ(s.triangles[2].uv[k][1], 0.0f);
    }
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
                       "map_Pr -s 2.000000 2.000000 1.000000 rough.png\n",            // 32
                       {{"paint.png", 2, 2, 3}, {"rough.png", 1, 2, 1}});
    ASSERT_EQ(s.materials.size(), 2u);
    const Material& metal = s.materials[0];
    EXPECT_EQ(metal.type, u32(MAT_ROUGH_CONDUCTOR));
    expect_rgb(metal.ks, {0.8f, 0.5f, 0.2f}, "metal ks");
    EXPECT_NEAR(metal.alpha, 0.09f, 1e-6);
    expect_no_textures(metal, "Metal");
    // Its roughness is in the map: rough, of the least alpha where no
    // constant says more.
    const Material& painted = s.materials[1];
    EXPECT_EQ(painted.type, u32(MAT_ROUGH_PLASTIC));
    EXPECT_NEAR(painted.alpha, kSmoothAlpha, 1e-9);
    expect_rgb(painted.ks, kHalf, "painted ks");
    EXPECT_NEAR(painted.ior, 1.45f, 1e-6);
    ASSERT_EQ(s.textures.size(), 2u);
    ASSERT_LT(painted.kd_tex, 2u);
    ASSERT_LT(painted.rough_tex, 2u);
    EXPECT_EQ(s.textures[painted.kd_tex].file, "paint.png");
    EXPECT_EQ(s.textures[painted.kd_tex].kind, TextureKind::Colour);
    EXPECT_EQ(s.textures[painted.rough_tex].file, "rough.png");
    EXPECT_EQ(s.textures[painted.rough_tex].kind, TextureKind::Data);
    EXPECT_EQ(s.textures[painted.rough_tex].width, 1);
    EXPECT_EQ(s.textures[painted.rough_tex].height, 2);
    EXPECT_EQ(painted.ks_tex, TEX_NONE);
    EXPECT_EQ(painted.alpha_tex, TEX_NONE);
    std::vector<std::string> want = {
        "m.mtl:6: warning: 'Ks' changes nothing in these models (ignored; 1 line)",
        "m.mtl:8: warning: 'Ni' changes nothing in these models (ignored; 1 line)"};
    EXPECT_EQ(s.warnings, want);
}

namespace {

// A texture map on a model: the Material field that takes the texture (or
// none: the map changes nothing there, with a warning), how its texels are
// read, and the model the material becomes.
enum class Field { None, Kd, Ks, Rough, Alpha };

struct MapCase {
    const char* name;
    const char* context; // lines after "newmtl m", each ending in \n
    const char* map;     // the directive; its line is "MAP tex.png"
    Field field;
    TextureKind kind;
    u32 type;
    float alpha;
};

const char* const kDiffuse = "Kd 0.2 0.4 0.6\nillum 1\n";
const char* const kDiffuse2 = "Kd 0.2 0.4 0.6\nillum 2\n"; // illum 2 without Ks
const char* const kPlastic = "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nillum 2\n";
const char* const kMirror = "Ks 0.9 0.8 0.7\nillum 3\n";
const char* const kMetal = "Kd 0.8 0.6 0.2\nPm 1\n";
const char* const kMetal3 = "Kd 0.8 0.6 0.2\nPm 1\nillum 3\n"; // Pm before illum 3's Ks
const char* const kGlass = "Ni 1.5\nillum 7\n";
const char* const kLamp = "Kd 0.5 0.5 0.5\nKe 2 2 2\n";
const char* const kDarkLamp = "Kd 0.5 0.5 0.5\nKe 0 0 0\n"; // not an emitter

constexpr TextureKind kColourTex = TextureKind::Colour, kDataTex = TextureKind::Data,
                      kMaskTex = TextureKind::Mask;
constexpr float kA = kSmoothAlpha;

const MapCase kMaps[] = {
    {"kd_on_diffuse", kDiffuse, "map_Kd", Field::Kd, kColourTex, MAT_DIFFUSE, 0},
    {"kd_on_illum2_without_ks", kDiffuse2, "map_Kd", Field::Kd, kColourTex, MAT_DIFFUSE, 0},
    {"kd_on_plastic", kPlastic, "map_Kd", Field::Kd, kColourTex, MAT_PLASTIC, 0},
    {"kd_on_an_emitter", kLamp, "map_Kd", Field::Kd, kColourTex, MAT_DIFFUSE, 0},
    {"kd_on_a_mirror", kMirror, "map_Kd", Field::None, kColourTex, MAT_CONDUCTOR, 0},
    {"kd_on_a_metal_is_its_reflectance", kMetal, "map_Kd", Field::Ks, kColourTex, MAT_CONDUCTOR, 0},
    {"kd_on_a_metal_of_illum3", kMetal3, "map_Kd", Field::Ks, kColourTex, MAT_CONDUCTOR, 0},
    {"kd_on_a_dielectric", kGlass, "map_Kd", Field::None, kColourTex, MAT_DIELECTRIC, 0},
    {"ks_on_diffuse", kDiffuse, "map_Ks", Field::None, kColourTex, MAT_DIFFUSE, 0},
    {"ks_on_illum2_without_ks", kDiffuse2, "map_Ks", Field::None, kColourTex, MAT_DIFFUSE, 0},
    {"ks_on_plastic", kPlastic, "map_Ks", Field::Ks, kColourTex, MAT_PLASTIC, 0},
    {"ks_on_a_mirror", kMirror, "map_Ks", Field::Ks, kColourTex, MAT_CONDUCTOR, 0},
    {"ks_on_a_metal", kMetal, "map_Ks", Field::None, kColourTex, MAT_CONDUCTOR, 0},
    {"ks_on_a_dielectric", kGlass, "map_Ks", Field::None, kColourTex, MAT_DIELECTRIC, 0},
    {"pr_on_diffuse", kDiffuse, "map_Pr", Field::None, kDataTex, MAT_DIFFUSE, 0},
    {"pr_makes_plastic_rough", kPlastic, "map_Pr", Field::Rough, kDataTex, MAT_ROUGH_PLASTIC, kA},
    {"pr_makes_plastic_of_pr0_rough", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nPr 0\nillum 2\n", "map_Pr",
     Field::Rough, kDataTex, MAT_ROUGH_PLASTIC, kA},
    {"pr_raises_a_smooth_pr_to_the_least_alpha",
     "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nPr 0.03\nillum 2\n", "map_Pr", Field::Rough, kDataTex,
     MAT_ROUGH_PLASTIC, kA},
    {"pr_keeps_the_alpha_of_ns", "Kd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 250\nillum 2\n", "map_Pr",
     Field::Rough, kDataTex, MAT_ROUGH_PLASTIC, 0.25f},
    {"pr_makes_a_mirror_rough", kMirror, "map_Pr", Field::Rough, kDataTex, MAT_ROUGH_CONDUCTOR, kA},
    {"pr_makes_a_metal_rough", kMetal, "map_Pr", Field::Rough, kDataTex, MAT_ROUGH_CONDUCTOR, kA},
    {"pr_makes_a_dielectric_rough", kGlass, "map_Pr", Field::Rough, kDataTex, MAT_ROUGH_DIELECTRIC,
     kA},
    {"d_on_diffuse", kDiffuse, "map_d", Field::Alpha, kMaskTex, MAT_DIFFUSE, 0},
    {"d_on_plastic", kPlastic, "map_d", Field::Alpha, kMaskTex, MAT_PLASTIC, 0},
    {"d_on_a_mirror", kMirror, "map_d", Field::Alpha, kMaskTex, MAT_CONDUCTOR, 0},
    {"d_on_a_metal", kMetal, "map_d", Field::Alpha, kMaskTex, MAT_CONDUCTOR, 0},
    {"d_on_a_dielectric", kGlass, "map_d", Field::None, kMaskTex, MAT_DIELECTRIC, 0},
    {"d_on_an_emitter", kLamp, "map_d", Field::None, kMaskTex, MAT_DIFFUSE, 0},
    {"d_on_an_emitting_metal", "Kd 0.8 0.6 0.2\nKe 1 1 1\nPm 1\n", "map_d", Field::None, kMaskTex,
     MAT_CONDUCTOR, 0},
    {"d_on_ke_0_is_no_emitter", kDarkLamp, "map_d", Field::Alpha, kMaskTex, MAT_DIFFUSE, 0},
};

void PrintTo(const MapCase& c, std::ostream* os) {
    *os << c.name;
}

class MtlMaps : public ::testing::TestWithParam<MapCase> {};

} // namespace

// The image is 3x2 RGBA: each kind keeps its bytes as in the file.
TEST_P(MtlMaps, GiveTheirTextureToTheFieldOfTheirRow) {
    const MapCase& c = GetParam();
    const std::string line = std::string(c.map) + " tex.png\n";
    Scene s = read_mtl(std::string("map-") + c.name, std::string("newmtl m\n") + c.context + line,
                       {{"tex.png", 3, 2, 4}});
    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_EQ(m.type, c.type);
    EXPECT_NEAR(m.alpha, c.alpha, 1e-9);
    for (int f = 0; f < 4; ++f) {
        const auto& [field, name] = kTexFields[f];
        EXPECT_EQ(m.*field, int(c.field) == f + 1 ? 0u : TEX_NONE) << name;
    }
    if (c.field == Field::None) {
        EXPECT_TRUE(s.textures.empty());
        std::vector<std::string> want = {"m.mtl:" + std::to_string(2 + lines_in(c.context)) +
                                         ": warning: " + changes_nothing(c.map) +
                                         " (ignored; 1 line)"};
        EXPECT_EQ(s.warnings, want);
        return;
    }
    EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
    ASSERT_EQ(s.textures.size(), 1u);
    const SceneTexture& t = s.textures[0];
    EXPECT_EQ(t.file, "tex.png");
    EXPECT_EQ(t.kind, c.kind);
    EXPECT_EQ(t.width, 3);
    EXPECT_EQ(t.height, 2);
    EXPECT_EQ(t.halvings, 0);
    ASSERT_EQ(t.texels.size(), 6u);
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(t.texels[i], rgba_texel(i)) << "texel " << i;
}

INSTANTIATE_TEST_SUITE_P(Rows, MtlMaps, ::testing::ValuesIn(kMaps),
                         [](const auto& info) { return std::string(info.param.name); });

// All four maps on one plastic, each of its own file (of its own size):
// each field holds the index of its own file's texture.
TEST(MtlTextures, EachMapHoldsTheIndexOfItsOwnFile) {
    Scene s = read_mtl(
        "four-maps",
        "newmtl m\nKd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nillum 2\nmap_Kd kd.png\n"
        "map_Ks ks.png\nmap_Pr pr.png\nmap_d d.png\n",
        {{"kd.png", 1, 1, 3}, {"ks.png", 2, 1, 3}, {"pr.png", 3, 1, 1}, {"d.png", 4, 1, 4}});
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
    const Material& m = s.materials[0];
    EXPECT_EQ(m.type, u32(MAT_ROUGH_PLASTIC));
    ASSERT_EQ(s.textures.size(), 4u);
    struct Want {
        u32 index;
        const char* file;
        TextureKind kind;
        int width;
    } want[] = {{m.kd_tex, "kd.png", kColourTex, 1},
                {m.ks_tex, "ks.png", kColourTex, 2},
                {m.rough_tex, "pr.png", kDataTex, 3},
                {m.alpha_tex, "d.png", kMaskTex, 4}};
    for (const Want& w : want) {
        ASSERT_LT(w.index, 4u) << w.file;
        const SceneTexture& t = s.textures[w.index];
        EXPECT_EQ(t.file, w.file);
        EXPECT_EQ(t.kind, w.kind) << w.file;
        EXPECT_EQ(t.width, w.width) << w.file;
        EXPECT_EQ(t.height, 1) << w.file;
    }
}

// A diffuse base, a plastic base, a metal's reflectance and a plastic coat
// are all colours: one texture for the file, however its options differ.
TEST(MtlTextures, AFileNamedBySeveralMaterialsAsOneKindIsLoadedOnce) {
    Scene s = read_mtl("shared",
                       "newmtl a\nKd 0.5 0.5 0.5\nmap_Kd wood.png\n"
                       "newmtl b\nKs 0.5 0.5 0.5\nillum 2\nmap_Kd -s 2 2 1 wood.png\n"
                       "newmtl c\nKd 1 1 1\nPm 1\nmap_Kd wood.png\n"
                       "newmtl d\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nillum 2\nmap_Ks wood.png\n",
                       {{"wood.png", 2, 2, 3}});
    ASSERT_EQ(s.materials.size(), 4u);
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].file, "wood.png");
    EXPECT_EQ(s.textures[0].kind, kColourTex);
    EXPECT_EQ(s.materials[0].kd_tex, 0u);
    EXPECT_EQ(s.materials[1].kd_tex, 0u);
    EXPECT_EQ(s.materials[2].ks_tex, 0u);
    EXPECT_EQ(s.materials[3].ks_tex, 0u);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
}

// One file as a colour, as data and as a mask: three textures, whichever
// material names it again.
TEST(MtlTextures, AFileOfSeveralKindsIsLoadedOncePerKind) {
    const std::string block =
        "Kd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nillum 2\nmap_Kd t.png\nmap_Pr t.png\nmap_d t.png\n";
    Scene s = read_mtl("kinds", "newmtl a\n" + block + "newmtl b\n" + block, {{"t.png", 2, 1, 4}});
    ASSERT_EQ(s.materials.size(), 2u);
    ASSERT_EQ(s.textures.size(), 3u);
    const Material& a = s.materials[0];
    ASSERT_LT(a.kd_tex, 3u);
    ASSERT_LT(a.rough_tex, 3u);
    ASSERT_LT(a.alpha_tex, 3u);
    EXPECT_EQ(s.textures[a.kd_tex].kind, kColourTex);
    EXPECT_EQ(s.textures[a.rough_tex].kind, kDataTex);
    EXPECT_EQ(s.textures[a.alpha_tex].kind, kMaskTex);
    for (const SceneTexture& t : s.textures)
        EXPECT_EQ(t.file, "t.png");
    const Material& b = s.materials[1];
    EXPECT_EQ(b.kd_tex, a.kd_tex);
    EXPECT_EQ(b.rough_tex, a.rough_tex);
    EXPECT_EQ(b.alpha_tex, a.alpha_tex);
}

// Options before the file name are skipped, whatever their number of
// values; a name with a folder is relative to the MTL file's folder too.
TEST(MtlTextures, TheFileIsTheLastTokenAfterTheOptions) {
    std::string dir = test::scratch_dir("mtl-options");
    test::write_file(
        dir + "/m.mtl",
        "newmtl a\nmap_Kd -bm 1 -s 1 1 1 tex.png\n"
        "newmtl b\nKs 0.5 0.5 0.5\nillum 2\nmap_Ks -o 0.5 0.5 0 -clamp on maps/ks.png\n"
        "newmtl c\nKs 0.5 0.5 0.5\nillum 2\nmap_Pr -imfchan r -mm 0 1 tex.png\n");
    std::string cmd = "mkdir -p '" + dir + "/maps'";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    write_png(dir + "/tex.png", {"tex.png", 3, 1, 3});
    write_png(dir + "/maps/ks.png", {"ks.png", 1, 3, 3});
    Scene s;
    load_mtl(dir + "/m.mtl", s);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
    ASSERT_EQ(s.materials.size(), 3u);
    ASSERT_EQ(s.textures.size(), 3u);
    ASSERT_LT(s.materials[0].kd_tex, 3u);
    ASSERT_LT(s.materials[1].ks_tex, 3u);
    ASSERT_LT(s.materials[2].rough_tex, 3u);
    const SceneTexture& a = s.textures[s.materials[0].kd_tex];
    const SceneTexture& b = s.textures[s.materials[1].ks_tex];
    const SceneTexture& c = s.textures[s.materials[2].rough_tex];
    EXPECT_EQ(a.file, dir + "/tex.png");
    EXPECT_EQ(a.width, 3);
    EXPECT_EQ(b.file, dir + "/maps/ks.png");
    EXPECT_EQ(b.width, 1);
    EXPECT_EQ(b.height, 3);
    EXPECT_EQ(c.file, dir + "/tex.png");
    EXPECT_EQ(c.kind, kDataTex);
}

// The MTL file in a folder of its own beside the scene: the texture is
// found beside the MTL file, not beside the scene or the mesh.
TEST(MtlTextures, FilesAreRelativeToTheMtlFile) {
    std::string dir = test::scratch_dir("mtl-folder");
    std::string cmd = "mkdir -p '" + dir + "/mats'";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    test::write_file(dir + "/s.scene", "camera 0 1 3  0 1 0  0 1 0  40\nmesh m.obj\n");
    test::write_file(dir + "/m.obj", "mtllib mats/m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
                                     "vt 1 0\nvt 0 1\nusemtl wood\nf 1/1 2/2 3/3\nusemtl lamp\n"
                                     "f 1 3 2\n");
    test::write_file(dir + "/mats/m.mtl", "newmtl wood\nmap_Kd wood.png\nnewmtl lamp\nKe 1 1 1\n");
    write_png(dir + "/mats/wood.png", {"wood.png", 2, 3, 3});
    Scene s = load_scene(dir + "/s.scene");
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].file, dir + "/mats/wood.png");
    EXPECT_EQ(s.textures[0].width, 2);
    EXPECT_EQ(s.textures[0].height, 3);
    EXPECT_EQ(s.materials[0].kd_tex, 0u);
}

namespace {

// The message of loading `text` as DIR/m.mtl (with the images `pngs`
// beside it), with DIR/ taken out; "" if it loads.
std::string mtl_error(const std::string& name, const std::string& text,
                      std::initializer_list<Png> pngs = {}) {
    std::string dir = test::scratch_dir("mtl-" + name);
    test::write_file(dir + "/m.mtl", text);
    for (const Png& p : pngs)
        write_png(dir + "/" + p.file, p);
    Scene s;
    std::string msg = test::input_error_of([&] { load_mtl(dir + "/m.mtl", s); });
    for (std::size_t at; (at = msg.find(dir + "/")) != std::string::npos;)
        msg.erase(at, dir.size() + 1);
    return msg;
}

} // namespace

// Each map the model reads: the error names the MTL file and the map's
// line (not the material's), and the file as it was looked for.
TEST(MtlTextures, AMissingTextureIsAnErrorAtItsLine) {
    for (const char* map : {"map_Kd", "map_Ks", "map_Pr", "map_d"}) {
        std::string msg = mtl_error(std::string("missing-") + map,
                                    "newmtl ok\nKd 1 1 1\nmap_Kd ok.png\n"
                                    "newmtl m\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nillum 2\n" +
                                        std::string(map) + " -s 1 1 1 nope.png\nNi 1.5\n",
                                    {{"ok.png", 1, 1, 3}});
        const std::string want = "m.mtl:8: cannot read texture nope.png: ";
        EXPECT_EQ(msg.rfind(want, 0), 0u) << map << ": " << msg;
        EXPECT_GT(msg.size(), want.size()) << map << ": no reason given";
    }
}

TEST(MtlTextures, AFileThatIsNoImageIsAnError) {
    std::string msg = mtl_error("not-an-image", "newmtl m\nKd 1 1 1\nmap_Kd m.mtl\n");
    const std::string want = "m.mtl:3: cannot read texture m.mtl: ";
    EXPECT_EQ(msg.rfind(want, 0), 0u) << msg;
    EXPECT_GT(msg.size(), want.size()) << "no reason given";
}

// A mask of an image without alpha takes its first channel as alpha; with
// alpha, its alpha. Colours and data keep the image's alpha, or opaque.
TEST(MtlTextures, AMaskWithoutAlphaTakesTheFirstChannel) {
    Scene s = read_mtl(
        "mask-channels",
        "newmtl grey\nmap_d grey.png\nnewmtl ga\nmap_d ga.png\n"
        "newmtl rgb\nmap_d rgb.png\nnewmtl rgba\nmap_d rgba.png\n"
        "newmtl colour\nmap_Kd rgb.png\n"
        "newmtl data\nKs 0.5 0.5 0.5\nillum 2\nmap_Pr grey.png\n",
        {{"grey.png", 2, 1, 1}, {"ga.png", 2, 1, 2}, {"rgb.png", 2, 1, 3}, {"rgba.png", 2, 1, 4}});
    ASSERT_EQ(s.materials.size(), 6u);
    ASSERT_EQ(s.textures.size(), 6u);
    auto texels = [&](u32 index) {
        EXPECT_LT(index, 6u);
        return index < 6u ? s.textures[index].texels : std::vector<std::uint32_t>{};
    };
    auto byte = [](int i, int c) { return std::uint32_t(pattern(i, c)); };
    for (int i = 0; i < 2; ++i) {
        const std::uint32_t g = byte(i, 0);
        const std::uint32_t grey = g | g << 8 | g << 16;
        const std::uint32_t rgb = byte(i, 0) | byte(i, 1) << 8 | byte(i, 2) << 16;
        const std::string at = "texel " + std::to_string(i);
        std::vector<std::uint32_t> t = texels(s.materials[0].alpha_tex);
        ASSERT_EQ(t.size(), 2u);
        EXPECT_EQ(t[i], grey | g << 24) << "grey mask, " << at;
        t = texels(s.materials[1].alpha_tex);
        ASSERT_EQ(t.size(), 2u);
        EXPECT_EQ(t[i], grey | byte(i, 1) << 24) << "grey and alpha mask, " << at;
        t = texels(s.materials[2].alpha_tex);
        ASSERT_EQ(t.size(), 2u);
        EXPECT_EQ(t[i] >> 24, byte(i, 0)) << "RGB mask's alpha, " << at;
        EXPECT_EQ(t[i], rgb | byte(i, 0) << 24) << "RGB mask, " << at;
        t = texels(s.materials[3].alpha_tex);
        ASSERT_EQ(t.size(), 2u);
        EXPECT_EQ(t[i], rgba_texel(i)) << "RGBA mask, " << at;
        t = texels(s.materials[4].kd_tex);
        ASSERT_EQ(t.size(), 2u);
        EXPECT_EQ(t[i], rgb | 0xFFu << 24) << "RGB colour, " << at;
        t = texels(s.materials[5].rough_tex);
        ASSERT_EQ(t.size(), 2u);
        EXPECT_EQ(t[i], grey | 0xFFu << 24) << "grey data, " << at;
    }
}
