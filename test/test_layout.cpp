// Shared struct layouts agree between host and device, and the sample layout
// has exactly the slots a scene needs.
#include "fixed_point.h"
#include "render/programs.hpp"
#include "scene/sample_layout.hpp"
#include "scene/shared_layout.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace smallmlt;

TEST(SharedLayout, DeviceAgreesWithHost) {
    std::vector<std::uint32_t> host = host_layout();
    ClProgram prog(test::probe_program());
    ClKernel k(prog.p, "probe_layout");
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, host.size() * sizeof(std::uint32_t));
    k.set_args(out);
    k.run(test::cl(), 1);
    std::vector<std::uint32_t> dev(host.size());
    out.read(test::cl(), dev.data());
    EXPECT_EQ(dev, host);
}

TEST(SampleLayout, OnlyTheSlotsTheSceneNeeds) {
    SceneFeatures diffuse_one_light = SceneFeatures().with(MAT_DIFFUSE);
    diffuse_one_light.num_lights = 1;
    diffuse_one_light.depth = 3;
    SampleLayout l = make_layout(diffuse_one_light);
    EXPECT_TRUE(l.has(kBsdfU) && l.has(kBsdfV) && l.has(kLightU) && l.has(kLightV));
    EXPECT_FALSE(l.has(kLightPick)) << "one light needs no light-pick slot";
    EXPECT_FALSE(l.has(kBsdfChoice)) << "no dielectric, no reflect/refract slot";
    EXPECT_FALSE(l.has(kRoulette)) << "depth 3 ends before Russian roulette starts";
    EXPECT_EQ(l.bounce_bits, 4 * kHighBits);

    SceneFeatures water = SceneFeatures().with(MAT_DIFFUSE).with(MAT_DIELECTRIC);
    water.num_lights = 2;
    water.depth = 24;
    l = make_layout(water);
    EXPECT_TRUE(l.has(kLightPick) && l.has(kBsdfChoice) && l.has(kRoulette));
    EXPECT_EQ(l.bounce_dims, 7);
    EXPECT_EQ(l.bounce_bits, 4 * kHighBits + 3 * kLowBits);
    EXPECT_EQ(l.vector_dims(), kCameraDims + 24 * 7);

    SceneFeatures glass_only = SceneFeatures().with(MAT_DIELECTRIC);
    glass_only.num_lights = 5;
    glass_only.depth = 8;
    l = make_layout(glass_only);
    EXPECT_EQ(l.bounce_dims, 2) << "no diffuse surface: no BSDF or light sampling slots";
}

TEST(SampleLayout, LightPickWidensWithLightCount) {
    EXPECT_EQ(light_pick_bits(2), kLowBits);
    EXPECT_EQ(light_pick_bits(256), kLowBits);
    EXPECT_EQ(light_pick_bits(257), 17);
    EXPECT_EQ(light_pick_bits(70000), 24);
    EXPECT_LE(light_pick_bits(1u << 30), kMaxLightPickBits);
}

TEST(SampleLayout, LightPickProbabilitiesAreExactAndSumToOne) {
    DeviceScene ds = prepare_scene(test::scene("furnace", 8, 8));
    ASSERT_EQ(ds.lights.size(), 12u);
    double sum = 0;
    for (const LightEntry& e : ds.lights)
        sum += ds.tris[e.triangle].light_pick_prob;
    EXPECT_EQ(sum, 1.0);
    EXPECT_EQ(ds.lights.back().cdf_hi, 1u << light_pick_bits(12));
}

// b's fixed point (cl/core/fixed_point.h) is one definition: the host's sum
// of the burn-in and the device's of the large steps round alike, for
// luminances where float and double rounding differ among them.
TEST(SharedFixedPoint, HostAndDeviceRoundBsSamplesAlike) {
    std::vector<float> lum = {0.0f,     -1.0f,         1e-9f, 0.3f,
                              0.5f,     0.75f + 1e-7f, 1.0f,  std::nextafter(1.0f, 2.0f),
                              3.14159f, 1234.567f,     1e20f};
    for (std::uint32_t i = 0; i < 200; ++i)
        lum.push_back(0.5f + float(i) * 0.0123457f);
    ClProgram prog(test::probe_program());
    ClKernel k(prog.p, "probe_fixed_b");
    ClBuffer in(test::cl(), CL_MEM_READ_ONLY, lum.size() * sizeof(float), lum.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, lum.size() * sizeof(cl_ulong));
    k.set_args(in, cl_uint(lum.size()), out);
    k.run(test::cl(), lum.size());
    std::vector<cl_ulong> dev(lum.size());
    out.read(test::cl(), dev.data());
    for (std::size_t i = 0; i < lum.size(); ++i)
        EXPECT_EQ(dev[i], fixed_b_sample(lum[i])) << "luminance " << lum[i];
    EXPECT_EQ(fixed_b_sample(0.0f), 0u);
    EXPECT_EQ(fixed_b_sample(1.0f), std::uint64_t(1) << MLT_B_FRAC_BITS);
    EXPECT_EQ(fixed_b_sample(1e20f), std::uint64_t(1) << (32 + MLT_B_FRAC_BITS));
}
