// Stability where methods fail (doc/stability.md): stuck chains are counted,
// chains at zero contribution move, a scene with more lights than 16 bits
// can address keeps its image, and large K, extreme thread counts and
// truncated paths give PT's image. Every comparison with PT checks the mean
// (which b sets) and each quadrant's share of the light (where the chains
// went), with the fixed seeds and tolerances stated beside each test. These
// catch gross errors only; test_render_blocks.cpp compares MLT with PT block
// by block against the measured noise.
#include "device/memory_plan.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace smallmlt;

namespace {

// PT reference of a 32 x 32 film, 1024 samples per pixel (1 M paths: the
// mean's relative standard error is below 0.3% on these scenes), cached per
// scene and depth.
const Image& reference(const std::string& name, int depth = -1) {
    static std::map<std::pair<std::string, int>, Image> cache;
    auto key = std::make_pair(name, depth);
    auto it = cache.find(key);
    if (it == cache.end()) {
        DeviceScene ds = prepare_scene(test::scene(name, 32, 32, depth));
        it = cache.emplace(key, test::render_pt(ds, 4242, 1024)).first;
    }
    return it->second;
}

struct MltRun {
    Image image;
    double b_rel_error;
    MltStats stats;
};

MltRun run_mlt(const DeviceScene& ds, const MltOptions& opt, std::uint32_t steps) {
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    mlt.step(steps);
    return {mlt.image(), mlt.b_rel_error(), mlt.stats()};
}

// The MLT image's mean is within 4 standard errors of b plus 1% (the
// reference's own noise and rounding) of PT's, and every quadrant's share of
// the light within `share_tol` (relative) of PT's. With burn-in every chain
// sits on a lit path and a step's splat weights sum to its work-items, so
// the image mean is b: the mean check checks b against PT.
void expect_tracks_pt(const MltRun& run, const Image& pt, double share_tol) {
    double m = run.image.mean_luminance(), r = pt.mean_luminance();
    std::printf("  mean %.5f, PT %.5f (%+.2f%%, b +-%.2f%%), shares", m, r, 100 * (m / r - 1),
                100 * run.b_rel_error);
    EXPECT_LT(std::abs(m / r - 1), 4 * run.b_rel_error + 0.01) << "image mean";
    auto q = test::quadrant_shares(run.image), qr = test::quadrant_shares(pt);
    for (int k = 0; k < 4; ++k) {
        std::printf(" %+.2f%%", 100 * (q[k] / qr[k] - 1));
        EXPECT_LT(std::abs(q[k] / qr[k] - 1), share_tol) << "quadrant " << k;
    }
    std::printf("\n");
}

std::vector<ChainValue> chain_values(const MltRenderer& mlt) {
    std::vector<ChainValue> v(mlt.chains());
    MltInspect::values(mlt).read(test::cl(), v.data());
    return v;
}

std::vector<std::uint32_t> chain_state(const MltRenderer& mlt) {
    std::vector<std::uint32_t> s(MltInspect::state(mlt).bytes() / 4);
    MltInspect::state(mlt).read(test::cl(), s.data());
    return s;
}

double value_luminance(const ChainValue& v) {
    return rgb_luminance(v.rgb[0], v.rgb[1], v.rgb[2]);
}

} // namespace

// Item 3. tiny-caustic's focused light makes a few chains reject every
// proposal for hundreds of steps; the diffuse cornell box, with the same
// settings (1024 chains, large step 0.1, 600 steps, a run of 100 counting as
// stuck), has none of its own. So that the count is checked whatever the
// seed, 16 chains of each are held where they start (test::hold_chains):
// they stay all 600 steps. The counts agree with the chains' own records:
// every chain whose current run reaches the threshold is marked, the marks
// add up to the count, and no current run exceeds the longest; on cornell
// the held chains are all that is counted (its own runs stay near 30).
TEST(StuckChains, AreCountedWhereABrightCausticHoldsThem) {
    const std::uint32_t steps = 600;
    for (const char* name : {"tiny-caustic", "cornell"}) {
        DeviceScene ds = prepare_scene(test::scene(name, 32, 32));
        MltOptions opt = test::plain_mlt();
        opt.threads = 1024;
        opt.large_step = 0.1f;
        opt.seed = 5;
        opt.stuck_run = 100;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        std::vector<std::uint32_t> held = test::hold_chains(mlt, 64);
        mlt.step(steps);
        MltStats s = mlt.stats();
        std::printf("%s: %llu stuck chains (%zu held), longest run %llu\n", name,
                    static_cast<unsigned long long>(s.stuck), held.size(),
                    static_cast<unsigned long long>(s.longest_run));
        EXPECT_EQ(s.longest_run, std::uint64_t(steps)) << "a held chain moved";
        if (std::string(name) == "cornell")
            EXPECT_EQ(s.stuck, held.size()) << "cornell's own chains got stuck";
        else
            EXPECT_GE(s.stuck, held.size());
        EXPECT_NE(mlt.notes().back().find("stayed on one path"), std::string::npos);
        std::vector<ChainValue> values = chain_values(mlt);
        for (std::uint32_t h : held)
            EXPECT_TRUE(values[h].meta & CHAIN_STUCK_BIT) << "held chain " << h;
        std::uint64_t marked = 0;
        for (const ChainValue& v : values) {
            std::uint32_t run = v.meta >> CHAIN_RUN_SHIFT;
            bool stuck = v.meta & CHAIN_STUCK_BIT;
            marked += stuck;
            EXPECT_LE(run, s.longest_run);
            if (run >= opt.stuck_run) {
                EXPECT_TRUE(stuck) << "run " << run;
            }
        }
        EXPECT_EQ(marked, s.stuck);
    }
}

// The same count on a render small enough for every device: the chains
// that became stuck are counted once each, as their marks say; 16 of them
// are held where they start, so some become stuck whatever the seed. On
// Mesa's OpenCL, a function that changed its by-value ChainValue changed
// the caller's, so a chain that became stuck looked stuck before the step
// and none was counted (cl/mlt/chain_value.cl, chain_stayed).
TEST(StuckChains, EveryChainThatBecameStuckIsCountedOnce) {
    DeviceScene ds = prepare_scene(test::scene("tiny-caustic", 16, 16));
    MltOptions opt = test::plain_mlt();
    opt.threads = 256;
    opt.large_step = 0.1f;
    opt.seed = 5;
    opt.stuck_run = 20;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    std::vector<std::uint32_t> held = test::hold_chains(mlt, 16);
    mlt.step(300);
    std::vector<ChainValue> values = chain_values(mlt);
    std::uint64_t marked = 0;
    for (const ChainValue& v : values)
        marked += (v.meta & CHAIN_STUCK_BIT) != 0;
    std::printf("%llu chains marked stuck (%zu held), %llu counted, longest run %llu\n",
                static_cast<unsigned long long>(marked), held.size(),
                static_cast<unsigned long long>(mlt.stats().stuck),
                static_cast<unsigned long long>(mlt.stats().longest_run));
    for (std::uint32_t h : held)
        ASSERT_TRUE(values[h].meta & CHAIN_STUCK_BIT) << "held chain " << h << " not marked";
    EXPECT_EQ(mlt.stats().stuck, marked);
}

// Item 5. ajar without burn-in: most chains start on black paths (the light
// comes through a slit). A chain at I(x) = 0 accepts whatever it proposes,
// so after one step every one of them has moved (its packed state changed:
// a small step always moves the film position by at least one grid unit).
TEST(ZeroContribution, ChainsOnBlackPathsAlwaysMove) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 16, 16));
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.burn_in = false;
    opt.burn_in_iters = 1;
    opt.large_step = 0.1f;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    std::vector<ChainValue> before = chain_values(mlt);
    std::vector<std::uint32_t> state_before = chain_state(mlt);
    mlt.step(1);
    std::vector<std::uint32_t> state_after = chain_state(mlt);
    const std::uint32_t chains = mlt.chains(), words = std::uint32_t(state_after.size()) / chains;
    std::uint32_t black = 0, moved = 0;
    for (std::uint32_t c = 0; c < chains; ++c) {
        if (value_luminance(before[c]) > 0) continue;
        ++black;
        bool changed = false;
        for (std::uint32_t w = 0; w < words; ++w)
            changed |= state_before[w * chains + c] != state_after[w * chains + c];
        moved += changed;
    }
    std::printf("%u of %u chains started black; %u moved\n", black, chains, moved);
    EXPECT_GT(black, chains / 2) << "ajar should start most chains black";
    EXPECT_EQ(moved, black);
    EXPECT_GE(mlt.stats().accepted, black);
}

// Item 5. From those black starts, ajar's MLT image mean converges to PT's:
// after 4 steps it is far below (black chains splat nothing), after 200 it
// is within 4 standard errors of b plus 3% (the startup bias left after 200
// steps, measured at 3-4% below, and the PT reference's noise; 2048 chains,
// large step 0.5, b from 2^19 OMC samples).
TEST(ZeroContribution, MostlyBlackSceneConvergesToThePtMean) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 32, 32));
    MltOptions opt = test::plain_mlt();
    opt.threads = 2048;
    opt.burn_in = false;
    opt.burn_in_iters = 256;
    opt.large_step = 0.5f;
    opt.seed = 9;
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    mlt.step(4);
    // Not b: without burn-in, a chain on a black path whose proposal is black
    // too splats nothing, so the mean measures how many chains found light.
    double early = mlt.image().mean_luminance(), r = reference("ajar").mean_luminance();
    mlt.step(196);
    double late = mlt.image().mean_luminance();
    std::printf("ajar without burn-in: mean after 4 steps %.5f, after 200 %.5f, PT %.5f, "
                "b +-%.2f%%\n",
                early, late, r, 100 * mlt.b_rel_error());
    EXPECT_LT(early, 0.7 * r) << "the start should be visibly biased";
    EXPECT_LT(std::abs(late / r - 1), 4 * mlt.b_rel_error() + 0.03);
}

namespace {

// Every emissive triangle of `scene` cut into n x n triangles of equal area
// (a barycentric grid): the same light, from n^2 times as many triangles.
void subdivide_lights(Scene& scene, int n) {
    std::vector<SceneTriangle> out;
    for (const SceneTriangle& t : scene.triangles) {
        if (!scene.materials[t.material].emissive) {
            out.push_back(t);
            continue;
        }
        Vec3 e1 = (t.v[1] - t.v[0]) * (1.0f / n), e2 = (t.v[2] - t.v[0]) * (1.0f / n);
        auto at = [&](int i, int j) { return t.v[0] + e1 * float(i) + e2 * float(j); };
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                out.push_back(
                    SceneTriangle::flat(at(i, j), at(i + 1, j), at(i, j + 1), t.material));
                if (i + j + 1 < n)
                    out.push_back(SceneTriangle::flat(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1),
                                                      t.material));
            }
    }
    scene.triangles = out;
}

} // namespace

// The cornell MLT render these tests compare with PT: 16,384 threads, b
// from 2^18 OMC samples, 24 steps (384 mutations per pixel). Quadrant shares
// of such renders scatter by up to 7% over seeds at K = 1 and 16% at
// K = 8, 16 (measured on 3 seeds each; the light itself, a few bright pixels
// in the top quadrants, dominates), hence the 15% and 25% tolerances: these
// catch light going to the wrong place, not fine bias. The chi-square tests
// of test_mlt.cpp check the sampler itself at every K.
MltOptions cornell_options(std::uint32_t proposals, std::uint64_t seed) {
    MltOptions opt = test::plain_mlt();
    opt.threads = 16384;
    opt.proposals = proposals;
    opt.burn_in_iters = 16;
    opt.seed = seed;
    return opt;
}

// Item 6. cornell's light cut into 66,248 triangles: more than a 16-bit
// light-pick slot can address, so the layout widens it to 24 bits; PT and
// MLT of that scene give the image of the two-triangle light (PT at 512
// samples per pixel: mean within 1%, shares within 2%).
TEST(ManyLights, WidenedLightPickKeepsTheImage) {
    Scene scene = test::scene("cornell", 32, 32);
    subdivide_lights(scene, 182);
    DeviceScene ds = prepare_scene(scene);
    ASSERT_EQ(ds.lights.size(), 2u * 182 * 182);
    EXPECT_EQ(ds.layout.bits[kLightPick], kMaxLightPickBits);
    const Image& pt = reference("cornell");
    Image many = test::render_pt(ds, 77, 512);
    double m = many.mean_luminance(), r = pt.mean_luminance();
    // PT against PT: a real comparison of means (no b involved).
    std::printf("PT, %zu lights: mean %.5f, 2 lights %.5f\n", ds.lights.size(), m, r);
    EXPECT_NEAR(m, r, 0.01 * r);
    auto q = test::quadrant_shares(many), qr = test::quadrant_shares(pt);
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(q[k], qr[k], 0.02 * qr[k]) << "quadrant " << k;
    std::printf("MLT, %zu lights:", ds.lights.size());
    expect_tracks_pt(run_mlt(ds, cornell_options(1, 13), 24), pt, 0.15);
}

// Item 7. Split transitions with K = 8 and 16 proposals per chain (2048 and
// 1024 chains) still give PT's image.
TEST(LargeK, ManyProposalsPerChainKeepTheImage) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 32, 32));
    for (std::uint32_t k : {8u, 16u}) {
        std::printf("K = %u:", k);
        expect_tracks_pt(run_mlt(ds, cornell_options(k, 40 + k), 24), reference("cornell"), 0.25);
    }
}

// Item 8. 256 threads and the most threads that fit a 64 MiB device (any
// count, here not a power of two) give PT's image at the same number of
// mutations (about 400 per pixel): 1,600 steps of few chains against 4 steps
// of many. b from 2^18 OMC samples or more in both.
TEST(ThreadCounts, FewestAndMostThreadsGiveTheSameImage) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 32, 32));
    DeviceBudget budget = device_budget(test::cl().device(), std::uint64_t(64) << 20);
    ChainShape shape;
    shape.threads = 1u << 24;
    std::uint32_t most = max_threads(ds, shape, budget);
    ASSERT_GT(most, 1u << 16);
    ASSERT_LT(most, 1u << 24);
    shape.threads = most + 1;
    EXPECT_FALSE(plan_fits(plan_mlt(ds, shape), budget));
    const std::uint64_t mutations = 400 * 1024;
    for (std::uint32_t n : {256u, most}) {
        MltOptions opt = cornell_options(1, 3);
        opt.threads = n;
        opt.burn_in_iters = std::max(1u, (1u << 18) / n);
        std::uint32_t steps = std::uint32_t((mutations + n - 1) / n);
        std::printf("%u threads x %u steps:", n, steps);
        expect_tracks_pt(run_mlt(ds, opt, steps), reference("cornell"), 0.15);
    }
}

// Item 8. Fewer threads than a work-group (10 of 64; 5 chains at K = 2):
// the group's other work-items idle, and every thread's mutations count.
TEST(ThreadCounts, FewerThreadsThanAWorkGroupRun) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 8, 8));
    for (std::uint32_t k : {1u, 2u}) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 10;
        opt.proposals = k;
        MltRun run = run_mlt(ds, opt, 50);
        EXPECT_EQ(run.stats.mutations, 500u);
        EXPECT_GT(run.stats.accepted, 0u);
        EXPECT_LE(run.stats.accepted, 50u * 10 / k);
        EXPECT_GT(run.image.mean_luminance(), 0.0);
    }
}

// Item 9. Paths cut at the maximum depth: with depth 1, 2 and 3, where the
// image still brightens with depth by more than 5% a bounce, MLT gives PT's
// image at the same depth: the truncation is one estimator for both.
TEST(Depth, MltAndPtAgreeAtTheSameMaximumDepth) {
    double previous = 0;
    for (int depth : {1, 2, 3}) {
        DeviceScene ds = prepare_scene(test::scene("cornell", 32, 32, depth));
        const Image& pt = reference("cornell", depth);
        EXPECT_GT(pt.mean_luminance(), 1.05 * previous) << "depth " << depth;
        previous = pt.mean_luminance();
        std::printf("depth %d:", depth);
        expect_tracks_pt(run_mlt(ds, cornell_options(1, 60 + depth), 24), pt, 0.15);
    }
}
