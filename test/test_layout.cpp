// Shared struct layouts agree between host and device, and the sample layout
// has exactly the slots a scene needs.
#include "render/programs.hpp"
#include "scene/sample_layout.hpp"
#include "scene/shared_layout.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numeric>

using namespace smallmlt;

TEST(SharedLayout, DeviceAgreesWithHost) {
    std::vector<std::uint32_t> host = host_layout();
    ClProgram prog(test::cl().build(
        program_files({Program::PathTracer, "", "", {"test/cl/probe.cl"}}, Stage::Geometry), ""));
    ClKernel k(prog.p, "probe_layout");
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, host.size() * sizeof(std::uint32_t));
    k.set_args(out);
    k.run(test::cl(), 1);
    std::vector<std::uint32_t> dev(host.size());
    out.read(test::cl(), dev.data());
    EXPECT_EQ(dev, host);
}

TEST(SampleLayout, OnlyTheSlotsTheSceneNeeds) {
    SceneFeatures diffuse_one_light{true, false, false, 1, 3};
    SampleLayout l = make_layout(diffuse_one_light);
    EXPECT_TRUE(l.has(kBsdfU) && l.has(kBsdfV) && l.has(kLightU) && l.has(kLightV));
    EXPECT_FALSE(l.has(kLightPick)) << "one light needs no light-pick slot";
    EXPECT_FALSE(l.has(kFresnel)) << "no dielectric, no reflect/refract slot";
    EXPECT_FALSE(l.has(kRoulette)) << "depth 3 ends before Russian roulette starts";
    EXPECT_EQ(l.bounce_bits, 4 * kHighBits);

    SceneFeatures water{true, false, true, 2, 24};
    l = make_layout(water);
    EXPECT_TRUE(l.has(kLightPick) && l.has(kFresnel) && l.has(kRoulette));
    EXPECT_EQ(l.bounce_dims, 7);
    EXPECT_EQ(l.bounce_bits, 4 * kHighBits + 3 * kLowBits);
    EXPECT_EQ(l.vector_dims(), kCameraDims + 24 * 7);

    SceneFeatures glass_only{false, false, true, 5, 8};
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
