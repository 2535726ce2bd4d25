// The emission the camera sees directly, by sampling the emitters from the
// eye (src/render/emission_seen.hpp): its second moment over the film
// against closed forms, and the floor it puts under the split's V_o.
#include "render/emission_seen.hpp"
#include "render/mlt.hpp"
#include "scene/material.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace smallmlt;

namespace {

constexpr int kSide = 64;      // the film, square
constexpr float kFovDeg = 40;  // vertical (and horizontal) field of view
constexpr float kDistance = 4; // from the eye to the lights' plane z = 0

// Film units (pixels) per unit length on the plane z = 0, which faces the
// camera: a perspective projection of a plane parallel to the film is a
// uniform scale.
double pixels_per_unit() {
    return kSide / (2 * kDistance * std::tan(kFovDeg / 2 * 3.14159265358979 / 180));
}

void quad(Scene& s, Vec3 lo, Vec3 hi, std::uint32_t material, bool facing_camera) {
    // lo, hi: opposite corners in a plane z = const.
    Vec3 a = lo, b{hi.x, lo.y, lo.z}, c = hi, d{lo.x, hi.y, lo.z};
    if (facing_camera) { // counter-clockwise seen from +z: normal +z
        s.triangles.push_back(SceneTriangle::flat(a, b, c, material));
        s.triangles.push_back(SceneTriangle::flat(a, c, d, material));
    } else {
        s.triangles.push_back(SceneTriangle::flat(a, c, b, material));
        s.triangles.push_back(SceneTriangle::flat(a, d, c, material));
    }
}

// Seen from (0, 0, 4) toward -z: light A (luminance 10, 0.2 x 0.2 about
// (-1.2, 0.5), 18 degrees off the axis) facing the camera, its left half
// hidden by a grey card at z = 1; light B (luminance 20) turned away from it; light C (luminance
// 30) behind the eye, facing it.
DeviceScene three_lights_scene() {
    Scene s;
    s.width = s.height = kSide;
    s.depth = 2;
    s.camera.eye = {0, 0, kDistance};
    s.camera.target = {0, 0, 0};
    s.camera.fov_y_deg = kFovDeg;
    s.materials.push_back(diffuse_material({0.5f, 0.5f, 0.5f}));
    for (float y : {10.0f, 20.0f, 30.0f}) {
        Material light = diffuse_material({0, 0, 0});
        set_emission(light, {y, y, y});
        s.materials.push_back(light);
    }
    quad(s, {-1.3f, 0.4f, 0}, {-1.1f, 0.6f, 0}, 1, true);
    // The eye's rays to x = -1.2 on z = 0 cross z = 1 at x = -0.9.
    quad(s, {-1.5f, -0.5f, 1}, {-0.9f, 1.0f, 1}, 0, true);
    quad(s, {0.4f, -0.1f, 0}, {0.6f, 0.1f, 0}, 2, false);
    quad(s, {-0.1f, -0.1f, 5}, {0.1f, 0.1f, 5}, 3, false);
    return prepare_scene(s);
}

} // namespace

// Light A's visible half, x in [-1.2, -1.1], lands on pixel columns 5.63
// to 7.82 and rows 18.81 to 23.21, and the moment there is Y^2 times its
// area in pixels (one camera sample per pixel: E[Y^2] is Y^2 times the share
// of the pixel it covers). Column 6 lies wholly inside it: its share is Y^2
// times the image's height. Off the axis, the film's pixels per steradian
// grow as 1 / cos^3: at 18 degrees, 16% more than on the axis. Light B faces away, light C is
// behind the eye, and the card hides A's other half: none adds to the moment, nor C's or B's
// luminance to the brightest seen. 2^20 samples, a sixth of them on A (the lights are picked by
// power): the binomial error of the visible share is 0.24%, of column 6's 0.44%, and the
// bound 2.5%.
TEST(EmissionSeen, MomentIsTheLightsImageOnTheFilm) {
    DeviceScene ds = three_lights_scene();
    MltOptions opt;
    opt.threads = 256;
    MltRenderer mlt(test::cl(), ds, opt);
    SceneBuffers scene(test::cl(), ds);
    ClBuffer scratch(test::cl(), CL_MEM_READ_WRITE, (1u << 20) * sizeof(cl_float4));
    std::set<std::uint32_t> pixels;
    EmissionSeenParts seen = emission_seen(test::cl(), MltInspect::program(mlt), scene, scratch, 7,
                                           [&](std::uint32_t p) {
                                               pixels.insert(p);
                                               return p % kSide == 6;
                                           });
    const double k = pixels_per_unit(), y2 = 10.0 * 10.0;
    const double half_area = (0.1 * k) * (0.2 * k), column = 0.2 * k;
    std::printf("moment %.2f (closed form %.2f), column 6 %.2f (%.2f), brightest %.3g\n",
                seen.film.moment + seen.cells.moment, y2 * half_area, seen.cells.moment,
                y2 * column, std::max(seen.film.luminance, seen.cells.luminance));
    EXPECT_NEAR(seen.film.moment + seen.cells.moment, y2 * half_area, 0.025 * y2 * half_area);
    EXPECT_NEAR(seen.cells.moment, y2 * column, 0.025 * y2 * column);
    EXPECT_DOUBLE_EQ(seen.film.luminance, 10.0);
    EXPECT_DOUBLE_EQ(seen.cells.luminance, 10.0);
    for (std::uint32_t p : pixels) {
        const std::uint32_t x = p % kSide, y = p / kSide;
        EXPECT_TRUE(x >= 5 && x <= 7 && y >= 18 && y <= 23) << "pixel " << x << ", " << y;
    }
}

// The floor (variance_with_emission_seen): the burn-in's V_o where it
// exceeds one sample of the brightest light seen, else that sample's worth,
// or the lights' moment where that is less.
TEST(EmissionSeen, FloorIsOneSampleOfTheBrightestLightSeen) {
    PixelVariance dark, twice; // 4 pixels of 8 samples
    for (int p = 0; p < 4; ++p)
        dark.add(0, 0, 8);
    twice.add(200, 2 * 100 * 100, 8); // two samples of 100
    for (int p = 0; p < 3; ++p)
        twice.add(0, 0, 8);
    EXPECT_DOUBLE_EQ(dark.value(), 0.0);
    // One sample of 100 among 8: variance 100^2 / 8, times 4 pixels over 4.
    EXPECT_DOUBLE_EQ(dark.one_sample(100), 1250.0);
    EXPECT_NEAR(twice.value(), (2e4 - 4e4 / 8) / 7, 1e-9);
    const EmissionSeen light{1e6, 100}, faint{300, 100}, none{};
    EXPECT_DOUBLE_EQ(variance_with_emission_seen(dark, light), 1250.0);
    EXPECT_DOUBLE_EQ(variance_with_emission_seen(dark, faint), 300.0);
    EXPECT_DOUBLE_EQ(variance_with_emission_seen(dark, none), 0.0);
    EXPECT_DOUBLE_EQ(variance_with_emission_seen(twice, light), twice.value());
    // Without pixels of two samples: the second moment's estimate.
    PixelVariance sparse;
    sparse.add(0, 0, 1);
    sparse.add(0, 0, 1);
    EXPECT_DOUBLE_EQ(sparse.one_sample(10), 100.0);
}
