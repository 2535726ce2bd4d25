// The pass loop (src/render/render_loop.hpp) with a method that only counts
// its work: how many units it renders for --spp and for --time. No device.
#include "render/render_loop.hpp"

#include <gtest/gtest.h>

namespace smallmlt {
namespace {

// Renders nothing; counts prepare() and the units of advance().
class CountingMethod : public Integrator {
  public:
    void prepare(RankGroup&) override { ++prepares; }
    void advance(std::uint32_t units) override {
        done += units;
        ++passes;
    }
    std::uint64_t units_for_spp(std::uint32_t spp, int, int) const override {
        return std::uint64_t(spp) * kUnitsPerSpp;
    }
    double spp_done() const override { return double(done) / kUnitsPerSpp; }
    Tally tally() const override { return {}; }
    Image image_from(const Tally&) const override { return Image(); }
    std::string summary(double) const override { return {}; }

    static constexpr std::uint32_t kUnitsPerSpp = 3;
    int prepares = 0;
    std::uint64_t done = 0;
    std::uint32_t passes = 0;
};

LoopResult run(CountingMethod& m, const LoopLimits& limits) {
    Progress progress(false);
    SingleRank rank;
    return render_loop(m, limits, nullptr, progress, rank);
}

TEST(RenderLoop, SppRendersExactlyItsUnits) {
    CountingMethod m;
    LoopResult r = run(m, LoopLimits{5u, std::nullopt});
    EXPECT_EQ(m.prepares, 1);
    EXPECT_EQ(m.done, 5u * CountingMethod::kUnitsPerSpp);
    EXPECT_EQ(r.passes, m.passes);
    EXPECT_FALSE(r.interrupted);
}

// A time that is up before the first pass (as when MLT's burn-in outlasts
// --time) still gets one pass, and only one: without it the image would
// have none of the method's units (MLT's chains: a black image).
TEST(RenderLoop, TimeUpBeforeTheFirstPassStillRendersOne) {
    CountingMethod m;
    LoopResult r = run(m, LoopLimits{std::nullopt, 1e-12});
    EXPECT_EQ(m.prepares, 1);
    EXPECT_EQ(m.passes, 1u);
    EXPECT_EQ(m.done, 1u);
    EXPECT_EQ(r.passes, 1u);
}

} // namespace
} // namespace smallmlt
