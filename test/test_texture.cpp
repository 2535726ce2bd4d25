// Textures: sRGB decoding, bilinear lookup with wrap, the cut-out, halving
// and the fit to memory (src/scene/texture.cpp, cl/shading/texture.cl).
#include "device/scene_buffers.hpp"
#include "render/programs.hpp"
#include "scene/material.hpp"
#include "scene/texture.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace smallmlt;

namespace {

std::uint32_t rgba(int r, int g, int b, int a) {
    return std::uint32_t(r) | std::uint32_t(g) << 8 | std::uint32_t(b) << 16 |
           std::uint32_t(a) << 24;
}

SceneTexture texture(int w, int h, TextureKind kind, std::vector<std::uint32_t> texels) {
    SceneTexture t;
    t.file = "test";
    t.kind = kind;
    t.width = w;
    t.height = h;
    t.texels = std::move(texels);
    return t;
}

struct Lookup {
    std::vector<cl_float4> rgba;
    std::vector<cl_uint> hole;
};

// Looks texture 0 of `ds` up at `uv` on the device.
Lookup device_lookup(const DeviceScene& ds, const std::vector<cl_float2>& uv) {
    ClProgram prog(test::cl().build(
        program_files(
            {Program::PathTracer, "cl/sampling/sample_omc.cl", "", {"test/cl/probe_texture.cl"}},
            Stage::Shading),
        ds.layout.defines()));
    const cl_uint n = cl_uint(uv.size());
    ClBuffer infos = upload(test::cl(), ds.textures), texels = upload(test::cl(), ds.texels);
    ClBuffer uvb(test::cl(), CL_MEM_READ_ONLY, n * sizeof(cl_float2), uv.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClBuffer hole(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_uint));
    ClKernel k(prog.p, "probe_tex_lookup");
    k.set_args(infos, texels, cl_uint(0), uvb, n, out, hole);
    k.run(test::cl(), n);
    Lookup l{std::vector<cl_float4>(n), std::vector<cl_uint>(n)};
    out.read(test::cl(), l.rgba.data());
    hole.read(test::cl(), l.hole.data());
    return l;
}

DeviceScene scene_with(const SceneTexture& t) {
    Scene s = test::scene("furnace", 4, 4, 1);
    s.textures.push_back(t);
    return prepare_scene(s);
}

} // namespace

// The sRGB transfer function of IEC 61966-2-1 at known points, and its
// inverse.
TEST(Texture, SrgbDecodesByTheStandardCurve) {
    EXPECT_NEAR(srgb_to_linear(0.0), 0.0, 1e-15);
    EXPECT_NEAR(srgb_to_linear(1.0), 1.0, 1e-12);
    EXPECT_NEAR(srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-12); // the linear segment's end
    EXPECT_NEAR(srgb_to_linear(0.5), 0.21404114048223255, 1e-12);
    EXPECT_NEAR(srgb_to_linear(188 / 255.0), 0.5028864580325687, 1e-12);
    for (double c : {0.001, 0.02, 0.3, 0.77})
        EXPECT_NEAR(linear_to_srgb(srgb_to_linear(c)), c, 1e-12);
}

// A 2x2 colour texture: at texel centres a lookup returns the texel,
// decoded from sRGB; between centres it is the bilinear mix of the decoded
// values; past an edge it wraps to the opposite side. A data texture is
// not decoded.
TEST(Texture, LookupIsBilinearWithWrapInLinearLight) {
    const std::uint32_t a = rgba(255, 0, 0, 255), b = rgba(0, 188, 0, 255),
                        c = rgba(0, 0, 128, 255), d = rgba(64, 64, 64, 0);
    SceneTexture t = texture(2, 2, TextureKind::Colour, {a, b, c, d}); // top row a b
    DeviceScene ds = scene_with(t);
    ASSERT_TRUE(ds.layout.features.textures == false); // no material uses it
    const double l188 = srgb_to_linear(188 / 255.0), l128 = srgb_to_linear(128 / 255.0),
                 l64 = srgb_to_linear(64 / 255.0);
    std::vector<cl_float2> uv = {{{0.25f, 0.75f}}, // centre of a (top left)
                                 {{0.75f, 0.75f}}, // b
                                 {{0.25f, 0.25f}}, // c
                                 {{0.5f, 0.75f}},  // between a and b
                                 {{0.5f, 0.5f}},   // the middle of all four
                                 {{1.0f, 0.75f}},  // between b and a, across the right edge
                                 {{1.25f, -0.25f}}};
    struct Want {
        double r, g, b, a;
    };
    const Want want[] = {{1, 0, 0, 1},
                         {0, l188, 0, 1},
                         {0, 0, l128, 1},
                         {0.5, 0.5 * l188, 0, 1},
                         {0.25 * (1 + l64), 0.25 * (l188 + l64), 0.25 * (l128 + l64), 0.75},
                         {0.5, 0.5 * l188, 0, 1},
                         {1, 0, 0, 1}}; // wraps to a's centre
    Lookup l = device_lookup(ds, uv);
    for (std::size_t i = 0; i < uv.size(); ++i) {
        EXPECT_NEAR(l.rgba[i].s[0], want[i].r, 2e-6) << "lookup " << i;
        EXPECT_NEAR(l.rgba[i].s[1], want[i].g, 2e-6) << "lookup " << i;
        EXPECT_NEAR(l.rgba[i].s[2], want[i].b, 2e-6) << "lookup " << i;
        EXPECT_NEAR(l.rgba[i].s[3], want[i].a, 2e-6) << "lookup " << i;
    }
    SceneTexture data = texture(1, 1, TextureKind::Data, {rgba(128, 0, 0, 255)});
    EXPECT_NEAR(device_lookup(scene_with(data), {{{0.3f, 0.6f}}}).rgba[0].s[0], 128 / 255.0, 1e-6)
        << "a data texture is linear";
}

// TEX_FLAG_NEAREST: a lookup is the texel the point falls in, wrapping,
// up to the texel's edge (no blend with its neighbour).
TEST(Texture, NearestLookupTakesTheTexelThePointFallsIn) {
    const std::uint32_t a = rgba(255, 0, 0, 255), b = rgba(0, 255, 0, 255),
                        c = rgba(0, 0, 255, 255), d = rgba(51, 102, 153, 255);
    SceneTexture t = texture(2, 2, TextureKind::Data, {a, b, c, d}); // top row a b
    t.nearest = true;
    std::vector<cl_float2> uv = {{{0.01f, 0.99f}}, {{0.49f, 0.51f}}, {{0.51f, 0.99f}},
                                 {{0.26f, 0.49f}}, {{0.99f, 0.01f}}, {{1.49f, 0.51f}},
                                 {{-0.25f, 1.25f}}};
    const std::uint32_t want[] = {a, a, b, c, d, a, d};
    Lookup l = device_lookup(scene_with(t), uv);
    for (std::size_t i = 0; i < uv.size(); ++i)
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(l.rgba[i].s[ch], double((want[i] >> (8 * ch)) & 0xFFu) / 255.0, 1e-6)
                << "lookup " << i << " channel " << ch;
}

// A cut-out mask: a hole where the filtered alpha is below 1/2.
TEST(Texture, CutOutHasHolesWhereAlphaIsBelowAHalf) {
    SceneTexture t = texture(2, 1, TextureKind::Mask, {rgba(0, 0, 0, 0), rgba(0, 0, 0, 255)});
    DeviceScene ds = scene_with(t);
    Lookup l =
        device_lookup(ds, {{{0.25f, 0.5f}}, {{0.75f, 0.5f}}, {{0.45f, 0.5f}}, {{0.55f, 0.5f}}});
    EXPECT_EQ(l.hole, (std::vector<cl_uint>{1, 0, 1, 0}));
}

// Halving averages 2x2 texels in linear light (black and sRGB 128 make
// sRGB 92, not 64), data textures in their own values; fit_textures
// halves the largest texture first until the total fits, and caps sides.
TEST(Texture, HalvingAveragesInLinearLightAndFitsTheLargestFirst) {
    SceneTexture t = texture(2, 2, TextureKind::Colour,
                             {rgba(0, 0, 0, 255), rgba(128, 128, 128, 255), rgba(0, 0, 0, 255),
                              rgba(128, 128, 128, 255)});
    SceneTexture d = t;
    d.kind = TextureKind::Data;
    halve(t);
    halve(d);
    ASSERT_EQ(t.width, 1);
    ASSERT_EQ(t.height, 1);
    // Linear light: (0 + 0.2158) / 2 = 0.1079 is sRGB 92.4; the mean of the
    // encoded values would be 64.
    EXPECT_EQ(t.texels[0] & 0xFFu, 92u);
    EXPECT_EQ(d.texels[0] & 0xFFu, 64u);
    EXPECT_EQ(t.texels[0] >> 24, 255u);

    std::vector<SceneTexture> set = {
        texture(64, 64, TextureKind::Colour, std::vector<std::uint32_t>(64 * 64, 0)),
        texture(16, 16, TextureKind::Colour, std::vector<std::uint32_t>(16 * 16, 0))};
    // 16 KiB + 1 KiB; at most 6 KiB: the large one halves to 32x32 (4 KiB).
    EXPECT_EQ(fit_textures(set, 6 * 1024, 0), 1);
    EXPECT_EQ(set[0].width, 32);
    EXPECT_EQ(set[1].width, 16);
    EXPECT_EQ(set[0].halvings, 1);
    EXPECT_EQ(fit_textures(set, 1u << 20, 8), 3); // 32 -> 16 -> 8, and 16 -> 8
    EXPECT_EQ(set[0].width, 8);
    EXPECT_EQ(set[1].width, 8);
}

namespace {

// A floor under a lamp, seen from below a large plane between them whose
// cut-out mask is `mask` (nothing between them without one).
Scene screened_floor(const SceneTexture* mask) {
    Scene s;
    s.width = s.height = 16;
    s.depth = 3;
    s.camera.eye = {0, 0.8f, 2.5f};
    s.camera.target = {0, 0, 0};
    s.camera.fov_y_deg = 50;
    s.materials.push_back(diffuse_material({0.7f, 0.7f, 0.7f}));
    Material lamp = diffuse_material({0, 0, 0});
    set_emission(lamp, {5, 5, 5});
    s.materials.push_back(lamp);
    Material screen = diffuse_material({0.5f, 0.5f, 0.5f});
    s.materials.push_back(screen);
    s.material_names = {"floor", "lamp", "screen"};
    auto quad = [&](float y, float half, std::uint32_t mat, bool down) {
        Vec3 a{-half, y, -half}, b{half, y, -half}, c{half, y, half}, d{-half, y, half};
        SceneTriangle t1 =
            down ? SceneTriangle::flat(a, b, c, mat) : SceneTriangle::flat(a, c, b, mat);
        SceneTriangle t2 =
            down ? SceneTriangle::flat(a, c, d, mat) : SceneTriangle::flat(a, d, c, mat);
        const float uv_a[2] = {0, 0}, uv_b[2] = {1, 0}, uv_c[2] = {1, 1}, uv_d[2] = {0, 1};
        auto set = [](SceneTriangle& t, const float* p, const float* q, const float* r) {
            for (int k = 0; k < 2; ++k)
                t.uv[0][k] = p[k], t.uv[1][k] = q[k], t.uv[2][k] = r[k];
        };
        if (down) {
            set(t1, uv_a, uv_b, uv_c);
            set(t2, uv_a, uv_c, uv_d);
        } else {
            set(t1, uv_a, uv_c, uv_b);
            set(t2, uv_a, uv_d, uv_c);
        }
        s.triangles.push_back(t1);
        s.triangles.push_back(t2);
    };
    quad(0, 3, 0, false);   // the floor, facing up
    quad(3, 0.5f, 1, true); // the lamp, facing down
    if (mask) {
        s.textures.push_back(*mask);
        s.materials[2].alpha_tex = 0;
        quad(1.5f, 20, 2, true);
    }
    return s;
}

double floor_mean(const SceneTexture* mask) {
    return test::render_pt(prepare_scene(screened_floor(mask)), 9, 64).mean_luminance();
}

} // namespace

// A screen between a lamp and the floor: with a cut-out mask of alpha 0 the
// floor is lit as without it (within 1%: the same samples, the rays pushed
// on past the screen), of alpha 1 it is black, and with holes in half of a
// fine checker the light is about halved. Shadow rays that took a hole for
// an occluder would darken the open screen far more than 1%.
TEST(Texture, CutOutsLetRaysAndShadowRaysThrough) {
    const double open_sky = floor_mean(nullptr);
    ASSERT_GT(open_sky, 0.05);
    SceneTexture clear = texture(1, 1, TextureKind::Mask, {rgba(0, 0, 0, 0)});
    SceneTexture solid = texture(1, 1, TextureKind::Mask, {rgba(0, 0, 0, 255)});
    std::vector<std::uint32_t> checker(256 * 256);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x)
            checker[std::size_t(y) * 256 + x] = rgba(0, 0, 0, ((x / 2 + y / 2) % 2) ? 255 : 0);
    SceneTexture half = texture(256, 256, TextureKind::Mask, checker);
    ASSERT_TRUE(prepare_scene(screened_floor(&clear)).layout.features.cutouts);
    EXPECT_NEAR(floor_mean(&clear), open_sky, 0.01 * open_sky);
    EXPECT_EQ(floor_mean(&solid), 0.0);
    double h = floor_mean(&half);
    EXPECT_GT(h, 0.35 * open_sky);
    EXPECT_LT(h, 0.65 * open_sky);
}
