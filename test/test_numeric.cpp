// Numerical trouble: NaN radiance from some paths never reaches the image
// and is counted (PT and MLT), and a scene whose light is boxed in renders
// black without dividing by zero.
#include "render/mlt.hpp"
#include "scene/material.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace smallmlt;

namespace {

// cornell with the red wall's albedo NaN: every path that bounces off it
// carries NaN radiance; the rest of the scene is intact.
DeviceScene cornell_with_nan_wall() {
    Scene s = test::scene("cornell", 32, 32, 4);
    bool found = false;
    for (std::size_t i = 0; i < s.materials.size(); ++i)
        if (s.material_names[i] == "red") {
            for (float& c : s.materials[i].kd)
                c = std::numeric_limits<float>::quiet_NaN();
            found = true;
        }
    EXPECT_TRUE(found);
    return prepare_scene(s);
}

std::size_t nonfinite_pixels(const Image& img) {
    std::size_t n = 0;
    for (float v : img.rgb)
        n += !std::isfinite(v);
    return n;
}

} // namespace

TEST(Numeric, PathTracerDropsAndCountsNonFiniteSamples) {
    DeviceScene ds = cornell_with_nan_wall();
    PathTracer pt(test::cl(), ds, 3);
    pt.add_samples(16);
    Image img = pt.image();
    EXPECT_EQ(nonfinite_pixels(img), 0u);
    EXPECT_GT(pt.nonfinite(), 100u);
    EXPECT_LT(pt.nonfinite(), std::uint64_t(16) * pt.pixels()); // not every path
    EXPECT_GT(img.mean_luminance(), 0.01);
    ASSERT_EQ(pt.notes().size(), 1u);
    EXPECT_NE(pt.notes()[0].find("NaN or infinite"), std::string::npos);
}

TEST(Numeric, MltDropsAndCountsNonFiniteSamples) {
    DeviceScene ds = cornell_with_nan_wall();
    MltOptions opt = test::plain_mlt();
    opt.threads = 1024;
    opt.seed = 5;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    mlt.step(16);
    Image img = mlt.image();
    EXPECT_TRUE(std::isfinite(mlt.b()));
    EXPECT_GT(mlt.b(), 0.0);
    EXPECT_EQ(nonfinite_pixels(img), 0u);
    EXPECT_GT(mlt.stats().nonfinite, 100u);
    EXPECT_GT(img.mean_luminance(), 0.01);
}

// The cornell light's emission pointed into a closed box: no path finds it.
TEST(Numeric, BoxedInLightRendersBlack) {
    Scene s = test::scene("cornell", 16, 16, 4);
    for (Material& m : s.materials)
        if (m.emissive) {
            m.ke[0] = m.ke[1] = m.ke[2] = 0.0f;
            m.emissive = 0;
        }
    // One emitter that faces away from everything: a tiny triangle far
    // behind the camera, facing away from the scene.
    Material lamp = diffuse_material({0, 0, 0});
    set_emission(lamp, {1, 1, 1});
    s.materials.push_back(lamp);
    s.material_names.push_back("lamp");
    std::uint32_t id = std::uint32_t(s.materials.size() - 1);
    s.triangles.push_back(
        SceneTriangle::flat({0, 100, 100}, {0.01f, 100, 100}, {0, 100.01f, 100}, id));
    DeviceScene ds = prepare_scene(s);
    PathTracer pt(test::cl(), ds, 1);
    pt.add_samples(4);
    Image img = pt.image();
    EXPECT_EQ(nonfinite_pixels(img), 0u);
    EXPECT_EQ(img.mean_luminance(), 0.0);
    MltOptions opt = test::plain_mlt();
    opt.threads = 256;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    EXPECT_EQ(mlt.b(), 0.0);
    EXPECT_TRUE(mlt.finished());
    Image m = mlt.image();
    EXPECT_EQ(nonfinite_pixels(m), 0u);
    EXPECT_EQ(m.mean_luminance(), 0.0);
}

// ajar: light reaches the room through a slit, so few OMC samples carry it
// and b is uncertain at small burn-in sizes. The render says so, and its
// mean (which b sets) still tracks PT's within b's stated error: at most 4
// standard errors of b plus 2% for the PT reference's own noise and MLT's.
TEST(Numeric, UncertainBIsReportedAndTheMeanStillTracksPt) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 32, 32));
    double pt_mean = test::render_pt(ds, 11, 1024).mean_luminance();
    for (std::uint32_t iters : {4u, 16u, 64u}) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 1024;
        opt.burn_in_iters = iters;
        opt.large_step = 0.1f;
        opt.seed = 21 + iters;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(64);
        double mean = mlt.image().mean_luminance();
        SCOPED_TRACE("burn-in iterations " + std::to_string(iters) + ", b " +
                     std::to_string(mlt.b()) + " +- " + std::to_string(100 * mlt.b_rel_error()) +
                     "%, PT " + std::to_string(pt_mean));
        EXPECT_GT(mlt.b_rel_error(), kMaxBRelError);
        ASSERT_FALSE(mlt.notes().empty());
        EXPECT_NE(mlt.notes()[0].find("few OMC samples carried light"), std::string::npos);
        // The image mean is b (burn-in starts every chain on a lit path): this checks b.
        EXPECT_LT(std::abs(mean - pt_mean) / pt_mean, 4 * mlt.b_rel_error() + 0.02);
    }
}
