// Primary-sample-space MLT: packed storage is exact, lazy proposals are the
// eager ones, the sampler reproduces a known target, and storage precision
// does not bias renders (renders against path tracing: test_render_blocks.cpp;
// restarts and the strata of --strata piles: test_piles.cpp).
#include "render/mlt.hpp"
#include "scene/sample_layout.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace smallmlt;

namespace {

const char* kProbeFile = "test/cl/probe_mlt.cl";

std::uint32_t bits_of(const SampleLayout& l, std::uint32_t d) {
    if (d < std::uint32_t(kCameraDims)) return kHighBits;
    std::uint32_t slot_index = (d - kCameraDims) % l.bounce_dims;
    for (int s = 0; s < kSlotCount; ++s)
        if (l.index[s] == int(slot_index)) return l.bits[s];
    return 0;
}

void check_roundtrip(const SceneFeatures& f, bool float32) {
    DeviceScene ds = test::layout_only_scene(f, 4, 4);
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 16;
    hooks.float32_states = float32;
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    const std::uint32_t dims = ds.layout.vector_dims(), chains = opt.threads;
    std::vector<std::uint32_t> values(std::size_t(dims) * chains);
    std::mt19937 rng(3);
    for (std::uint32_t c = 0; c < chains; ++c)
        for (std::uint32_t d = 0; d < dims; ++d) {
            std::uint32_t max = (1u << bits_of(ds.layout, d)) - 1u;
            values[c * dims + d] = c == 0 ? 0u : c == 1 ? max : rng() & max;
        }
    ClBuffer in(test::cl(), CL_MEM_READ_ONLY, values.size() * 4, values.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, values.size() * 4);
    ClKernel k(MltInspect::program(mlt), "probe_pss_roundtrip");
    k.set_args(MltInspect::state(mlt), in, out, cl_uint(chains), cl_uint(f.depth));
    k.run(test::cl(), chains);
    std::vector<std::uint32_t> back(values.size());
    out.read(test::cl(), back.data());
    for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(back[i], values[i]) << "chain " << i / dims << " number " << i % dims;
}

} // namespace

// Every value written to every slot of every bounce reads back bit-exactly,
// including 0 and the largest value below 1 (chains 0 and 1), with slots of
// 24, 16 and a widened 17 bits packed across word boundaries.
TEST(MltPacking, RoundTripIsBitExact) {
    using test::features;
    check_roundtrip(features({MAT_DIFFUSE, MAT_DIELECTRIC}, 2, 24), false); // 4 x 24 + 3 x 16 bits
    check_roundtrip(features({MAT_DIFFUSE, MAT_CONDUCTOR, MAT_DIELECTRIC}, 300, 24),
                    false);                                  // light pick widened to 17 bits
    check_roundtrip(features({MAT_CONDUCTOR}, 1, 5), false); // roulette only: 16 bits a bounce
    check_roundtrip(features({MAT_DIFFUSE, MAT_DIELECTRIC}, 300, 24), true); // the float32 build
}

TEST(MltPacking, StateSizeFollowsTheLayout) {
    SampleLayout water = make_layout(test::features({MAT_DIFFUSE, MAT_DIELECTRIC}, 2, 24));
    EXPECT_EQ(water.vector_bits(), 2 * 24 + 24 * (4 * 24 + 3 * 16));
    EXPECT_EQ(water.chain_words(false), std::uint32_t((water.vector_bits() + 31) / 32));
    EXPECT_EQ(water.chain_words(true), std::uint32_t(water.vector_dims()));
}

// For fixed keys, the path traced from a lazily evaluated proposal equals the
// path traced from the same proposal materialized number by number (same F,
// bit for bit), and committing the proposal stores exactly that path.
TEST(MltLazy, LazyProposalEqualsEagerAndCommitStoresIt) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 32, 32));
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 1024;
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    mlt.prepare();
    std::vector<cl_float4> f = test::lazy_eager_committed(mlt, ds, opt.threads);
    int lit = 0;
    for (std::uint32_t c = 0; c < opt.threads; ++c) {
        const cl_float4 &lazy = f[3 * c], &eager_f = f[3 * c + 1], &stored = f[3 * c + 2];
        EXPECT_EQ(std::memcmp(lazy.s, eager_f.s, 12), 0) << "chain " << c;
        EXPECT_EQ(std::memcmp(lazy.s, stored.s, 16), 0) << "chain " << c;
        lit += lazy.s[0] + lazy.s[1] + lazy.s[2] > 0;
    }
    EXPECT_GT(lit, int(opt.threads) / 10) << "too few lit paths to test anything";
}

// f(x, y) = (1 + 3x)(1 + sin^2(2 pi y)), zero where x, y < 1/4 (test/cl/eval_target.cl):
// its integral over bin (bx, by) of a 16 x 16 grid (bins never straddle the
// zero region's edges).
double target_bin_integral(int bx, int by) {
    double x0 = bx / 16.0, x1 = (bx + 1) / 16.0, y0 = by / 16.0, y1 = (by + 1) / 16.0;
    if (x1 <= 0.25 && y1 <= 0.25) return 0.0;
    auto fx = [](double x) { return x + 1.5 * x * x; };
    auto fy = [](double y) { return 1.5 * y - std::sin(4.0 * M_PI * y) / (8.0 * M_PI); };
    return (fx(x1) - fx(x0)) * (fy(y1) - fy(y0));
}

double target_integral() {
    double sum = 0;
    for (int by = 0; by < 16; ++by)
        for (int bx = 0; bx < 16; ++bx)
            sum += target_bin_integral(bx, by);
    return sum;
}

// The chains' states after many steps are independent draws from the target:
// their histogram over 16 x 16 bins passes a chi-square test at significance
// 0.001, and no chain sits where the target is zero. With K proposals per
// chain (split transitions) as without: 16,384 chains for K = 1, 2, 4 and
// 4,096 (16 per bin on average) for K = 8, 16.
class MltSampler : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(MltSampler, ChainStatesFollowAKnownTarget) {
    const int bins = 16;
    DeviceScene ds = test::layout_only_scene({}, bins, bins);
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.proposals = GetParam();
    opt.threads = (opt.proposals <= 4 ? 16384 : 4096) * opt.proposals;
    opt.large_step = 0.3f;
    opt.seed = 5;
    hooks.evaluator = "test/cl/eval_target.cl";
    hooks.extra_files = {kProbeFile};
    opt.burn_in = false; // chains start uniform: the steps alone must reach the target
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    mlt.prepare();
    mlt.step(300);
    const std::uint32_t chains = mlt.chains();
    std::vector<cl_uint> pixel = test::chain_pixels(mlt, ds.frame);
    std::vector<double> count(bins * bins, 0.0);
    for (cl_uint p : pixel)
        count[p] += 1;

    double total = target_integral(), chi2 = 0;
    int df = -1;
    for (int by = 0; by < bins; ++by)
        for (int bx = 0; bx < bins; ++bx) {
            double p = target_bin_integral(bx, by) / total;
            double n = count[by * bins + bx];
            if (p == 0) {
                EXPECT_EQ(n, 0) << "a chain sits where the target is zero";
                continue;
            }
            double e = p * chains;
            chi2 += (n - e) * (n - e) / e;
            ++df;
        }
    EXPECT_LT(chi2, test::chi2_critical_001(df)) << "df " << df;
}

INSTANTIATE_TEST_SUITE_P(Proposals, MltSampler, ::testing::Values(1u, 2u, 4u, 8u, 16u));

// Stratified MLT (src/render/strata.hpp) on the known target, 16 tiles of
// 4 x 4 bins and 4,096 chains (64 work-groups, 48 of them dealt by
// brightness), after 200 steps:
// - every chain's state splats to a pixel of its own tile;
// - each tile's chains follow the target restricted to the tile: their
//   histogram over its bins, against the closed-form bin integrals, by one
//   chi-square over all lit tiles at significance 0.001 (the dark tile,
//   x, y < 1/4, has no target to follow);
// - each tile's B (the burn-in's samples in it and its large steps) is the
//   tile's mean of g: z against the standard error from g's variance over
//   the tile (numeric, 256 x 256 midpoints), |z| < 3.40 (two-sided 0.01
//   over the 15 lit tiles, Bonferroni; the burn-in's samples are
//   stratified by pixel, so the error is smaller than this).
TEST(MltStrata, ChainsStayInTheirTilesFollowTheTargetAndEachTileHasItsB) {
    const int bins = 16, side = 4, per_row = bins / side;
    DeviceScene ds = test::layout_only_scene({}, bins, bins);
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 4096;
    opt.large_step = 0.3f;
    opt.seed = 77;
    opt.strata = side;
    hooks.evaluator = "test/cl/eval_target.cl";
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    mlt.prepare();
    mlt.step(200);
    ASSERT_EQ(mlt.strata_grid().count(), 16u);
    const std::vector<std::uint32_t>& group_tile = mlt.group_tiles();
    const std::uint32_t group_chains = std::uint32_t(kDefaultWorkGroup) / opt.proposals;
    std::vector<cl_uint> pixel = test::chain_pixels(mlt, ds.frame);
    std::vector<double> count(bins * bins, 0.0), chains(16, 0.0);
    for (std::uint32_t c = 0; c < mlt.chains(); ++c) {
        const std::uint32_t tile = group_tile[c / group_chains];
        ASSERT_EQ(mlt.strata_grid().pixel_tile[pixel[c]], tile)
            << "chain " << c << " left its tile for pixel " << pixel[c];
        count[pixel[c]] += 1;
        chains[tile] += 1;
    }
    std::vector<double> b = mlt.tile_b();
    const MltTally tally = mlt.mlt_tally();
    double chi2 = 0;
    int df = 0, lit = 0;
    for (int t = 0; t < 16; ++t) {
        const int tx = t % per_row, ty = t / per_row;
        double integral = 0, moment2 = 0;
        for (int by = ty * side; by < (ty + 1) * side; ++by)
            for (int bx = tx * side; bx < (tx + 1) * side; ++bx)
                integral += target_bin_integral(bx, by);
        if (integral == 0) {
            EXPECT_EQ(b[t], 0.0) << "tile " << t << " has no light";
            continue;
        }
        ++lit;
        for (int by = ty * side; by < (ty + 1) * side; ++by)
            for (int bx = tx * side; bx < (tx + 1) * side; ++bx) {
                const double p = target_bin_integral(bx, by) / integral;
                const double n = count[by * bins + bx], e = p * chains[t];
                ASSERT_GT(p, 0.0);
                chi2 += (n - e) * (n - e) / e;
                ++df;
            }
        --df; // the tile's chains are fixed in number
        const double area = double(side * side) / (bins * bins);
        const double want = integral / area; // the tile's mean of g
        const int m = 256;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const double x = (tx + (i + 0.5) / m) / per_row, y = (ty + (j + 0.5) / m) / per_row;
                const double sn = std::sin(2 * M_PI * y);
                const double g = (x < 0.25 && y < 0.25) ? 0 : (1 + 3 * x) * (1 + sn * sn);
                moment2 += g * g / (m * m);
            }
        const double n = double(tally.burn_in_samples) * area + double(tally.large[t]);
        const double z = (b[t] - want) / std::sqrt((moment2 - want * want) / n);
        EXPECT_LT(std::abs(z), 3.40) << "tile " << t << ": B " << b[t] << ", closed form " << want;
    }
    EXPECT_EQ(lit, 15);
    EXPECT_LT(chi2, test::chi2_critical_001(df)) << "df " << df;
}

// The splatted image of the known target matches its bin means. Each of R
// independent renders (own seed, own b) gives every bin a value; with the
// replicas' mean m_b and standard error s_b, z_b = (m_b - truth_b) / s_b is
// t-distributed with R - 1 degrees of freedom, so T = sum z_b^2 over the
// B bins has mean B (R-1)/(R-3) and variance B Var(t^2). T must stay below
// its mean plus 3.3 standard deviations (about 0.001 one-sided), and bins
// where the target is zero get exactly nothing.
void check_splat_image(Target target, bool kelemen = false, double b0_scale = 1,
                       std::uint32_t strata = 0, std::uint32_t restart = 0) {
    const int bins = 16, replicas = 16;
    DeviceScene ds = test::layout_only_scene({}, bins, bins);
    std::vector<double> sum(bins * bins, 0.0), sum2(bins * bins, 0.0);
    for (int r = 0; r < replicas; ++r) {
        MltOptions opt = test::plain_mlt();
        MltTestHooks hooks;
        opt.threads = 1024;
        opt.large_step = 0.3f;
        opt.seed = 100 + r;
        opt.burn_in_iters = 64; // b from 2^16 samples
        hooks.evaluator = "test/cl/eval_target.cl";
        hooks.b0_scale = b0_scale;
        opt.target = target;
        opt.kelemen = kelemen;
        opt.strata = strata;
        opt.restart = restart;
        if (restart) opt.burn_in_iters = 4; // b also from every restart's rounds
        if (strata) opt.threads = 2048;     // 32 work-groups: 16 dealt by brightness
        MltRenderer mlt(test::cl(), ds, opt, hooks);
        mlt.prepare();
        mlt.step(400);
        Image img = mlt.image();
        for (int i = 0; i < bins * bins; ++i) {
            sum[i] += img.rgb[3 * i];
            sum2[i] += double(img.rgb[3 * i]) * img.rgb[3 * i];
        }
    }
    const double nu = replicas - 1;
    double t_stat = 0;
    int used = 0;
    for (int by = 0; by < bins; ++by)
        for (int bx = 0; bx < bins; ++bx) {
            int i = by * bins + bx;
            double truth = target_bin_integral(bx, by) * bins * bins;
            double mean = sum[i] / replicas;
            if (truth == 0) {
                EXPECT_EQ(sum[i], 0.0) << "splats where the target is zero";
                continue;
            }
            double var = (sum2[i] - replicas * mean * mean) / (replicas - 1);
            double se = std::sqrt(std::max(var, 0.0) / replicas);
            ASSERT_GT(se, 0.0);
            double z = (mean - truth) / se;
            t_stat += z * z;
            ++used;
        }
    double mean_t2 = nu / (nu - 2);
    double var_t2 = 2 * nu * nu * (nu - 1) / ((nu - 2) * (nu - 2) * (nu - 4));
    double limit = used * mean_t2 + 3.3 * std::sqrt(used * var_t2);
    std::printf("T = %.1f, expected %.1f, limit %.1f\n", t_stat, used * mean_t2, limit);
    EXPECT_LT(t_stat, limit) << "sum of squared z over " << used << " bins";
}

TEST(MltSplat, SplatImageMatchesTheTarget) {
    check_splat_image(Target::Luminance);
}

// The two-stage target (src/render/target.hpp) changes where the chains go,
// not the image: its weights here range over 16 cells of 4 x 4 bins, one of
// them (where g = 0) at the floor.
TEST(MltSplat, TwoStageImageMatchesTheTarget) {
    check_splat_image(Target::TwoStage);
}

// Kelemen's weights (cl/mlt/mlt_step.cl) split each splat between the chain's
// estimate and the large steps' independent one: the image is the same.
TEST(MltSplat, KelemenImageMatchesTheTarget) {
    check_splat_image(Target::Luminance, true);
}

// Any b0 makes the balance heuristic's weights sum to 1, so only the scale
// of the large steps' estimate depends on it: with b0 three times b (as a
// few threads' burn-in can make it), the image is still the target's. Were
// the large steps' layer scaled by b, a bin of g = 1 would come out at
// (1 + p b) / (1 + 3 p b), about 0.6 of its value here.
TEST(MltSplat, KelemenImageMatchesTheTargetWithAWrongB0) {
    check_splat_image(Target::Luminance, true, 3);
}

// M, the chain's mutations that Kelemen's weights count as one sample,
// scales the weights' c b0 and nothing before it: at one seed, M = 1 and
// M = 3 burn in alike and weigh with c b0 and 3 c b0. Given none, M is 3
// where the chains restart and 1 where they do not. That the image stays
// the target's with M = 3 is MltSplat.RestartedImageMatchesTheTarget's.
TEST(MltSplat, KelemenWeightsCountMMutationsAsOneSample) {
    DeviceScene ds = test::layout_only_scene({}, 16, 16);
    MltTestHooks hooks;
    hooks.evaluator = "test/cl/eval_target.cl";
    MltOptions opt = test::plain_mlt();
    opt.kelemen = true;
    opt.large_step = 0.3f;
    opt.threads = 1024;
    opt.burn_in_iters = 4;
    opt.restart = 4;
    std::vector<MltReport> r;
    std::vector<double> b;
    for (std::optional<double> m :
         {std::optional<double>(1.0), std::optional<double>(3.0), std::optional<double>()}) {
        opt.mutations_per_sample = m;
        MltRenderer mlt(test::cl(), ds, opt, hooks);
        mlt.prepare();
        mlt.step(4);
        r.push_back(mlt.report());
        b.push_back(mlt.b());
    }
    EXPECT_EQ(b[0], b[1]) << "M changed the burn-in";
    EXPECT_GT(r[0].kelemen_pb, 0.0f);
    EXPECT_NEAR(r[1].kelemen_pb, 3 * r[0].kelemen_pb, 1e-6 * r[1].kelemen_pb);
    EXPECT_EQ(r[2].kelemen_pb, r[1].kelemen_pb) << "restarting chains' default M";
    EXPECT_EQ(r[2].mutations_per_sample, kDefaultMutationsPerSampleRestart);
    opt.mutations_per_sample.reset();
    opt.restart = 0;
    EXPECT_EQ(mutations_per_sample_of(opt), 1.0) << "chains that do not restart";
}

// Stratified MLT (src/render/strata.hpp): 16 tiles of 4 x 4 bins, each
// normalized by its own B, with the chains dealt by brightness; the image is
// the same, with expected values and with Kelemen's weights (a B0 per tile).
TEST(MltSplat, StratifiedImageMatchesTheTarget) {
    check_splat_image(Target::Luminance, false, 1, 4);
}

TEST(MltSplat, StratifiedKelemenImageMatchesTheTarget) {
    check_splat_image(Target::Luminance, true, 1, 4);
}

// --restart (MltBurnIn::restart): every 4 of the 400 steps each chain
// splats what it owes and starts again at a pick of 4 fresh burn-in rounds,
// whose samples also count in b (400K of them over the render); the image
// is the same, with Kelemen's weights (the default) and with expected
// values, and in tiles; Kelemen's weights then count 3 of a chain's
// mutations as one sample (M's default). So short a chain owes a good part of its weight
// when it restarts: a restart that dropped it would darken every bin.
TEST(MltSplat, RestartedImageMatchesTheTarget) {
    check_splat_image(Target::Luminance, false, 1, 0, 4);
    check_splat_image(Target::Luminance, true, 1, 0, 4);
}

TEST(MltSplat, RestartedStratifiedImageMatchesTheTarget) {
    check_splat_image(Target::Luminance, true, 1, 4, 4);
}

// The restarts' rounds go on along each pixel's Sobol sequence, under one
// scramble for all restarts (MltRenderer::restart_film): a pixel's restart
// samples are consecutive points of one sequence, and together a net. Here
// 100 restarts of 4 rounds put 1,600 of them in each of 256 pixels of the
// known target, smooth within every pixel; their mean luminance (the burn-in
// sums' growth over the steps) must lie within 1.5e-6 of the closed form, as
// root mean square over seeds 1-4. One sequence reads 6.1e-7; a fresh
// scramble per restart, 100 independent nets of 16 points a pixel, read
// 6.0e-6 (the mutant restart-rounds-rescrambled).
TEST(MltRestart, RoundsGoOnAlongEachPixelsSequence) {
    DeviceScene ds = test::layout_only_scene({}, 16, 16);
    const double truth = target_integral(), unit = double(1ull << MLT_B_FRAC_BITS);
    double squares = 0;
    const std::uint64_t seeds[] = {1, 2, 3, 4};
    for (std::uint64_t seed : seeds) {
        MltOptions opt = test::plain_mlt();
        MltTestHooks hooks;
        hooks.evaluator = "test/cl/eval_target.cl";
        opt.threads = 1024;
        opt.large_step = 0.0f;
        opt.seed = seed;
        opt.burn_in_iters = 4;
        opt.restart = 4;
        MltRenderer mlt(test::cl(), ds, opt, hooks);
        mlt.prepare();
        const MltTally first = mlt.mlt_tally();
        mlt.step(400);
        const MltTally all = mlt.mlt_tally();
        ASSERT_EQ(all.restart_samples, 100u * 4 * 1024);
        const double sum = double(all.burn_in_lum.at(0) - first.burn_in_lum.at(0)) / unit;
        const double error = sum / double(all.restart_samples) / truth - 1;
        std::printf("seed %llu: the restarts' mean %.8f, closed form %.8f, relative error %.2e\n",
                    (unsigned long long)seed, sum / double(all.restart_samples), truth, error);
        squares += error * error;
    }
    const double rms = std::sqrt(squares / 4);
    std::printf("root mean square relative error %.2e\n", rms);
    EXPECT_LT(rms, 1.5e-6);
}

// MLT renders against PT, block by block, and b against PT's mean:
// test_render_blocks.cpp.

// Storage precision does not bias: renders with packed 24/16-bit states and
// with unpacked float32 states (same kernel, PSS_FLOAT32) differ only by
// noise. Six replicas of each (own seeds) give per-quadrant shares of the
// splats (image / b, so that b's own noise, common to a whole image, does not
// hide a difference in where the chains go); Welch's t for each of the 4
// quadrants must stay below 3.6 (two-sided 0.0025 at about 10 degrees of
// freedom: 0.01 over the four, Bonferroni).
TEST(MltPrecision, PackedAndFloat32StatesAgreeWithinNoise) {
    DeviceScene ds = prepare_scene(test::scene("cornell-glass", 32, 32));
    const int replicas = 6;
    double sum[2][4] = {}, sum2[2][4] = {};
    for (int build = 0; build < 2; ++build)
        for (int r = 0; r < replicas; ++r) {
            MltOptions opt = test::plain_mlt();
            MltTestHooks hooks;
            opt.threads = 2048;
            opt.seed = 300 + r + 50 * build;
            opt.burn_in_iters = 8;
            hooks.float32_states = build == 1;
            MltRenderer mlt(test::cl(), ds, opt, hooks);
            mlt.prepare();
            mlt.step(64);
            Image img = mlt.image();
            double q[4] = {};
            for (int y = 0; y < 32; ++y)
                for (int x = 0; x < 32; ++x) {
                    std::size_t p = std::size_t(y) * 32 + x;
                    q[(y / 16) * 2 + x / 16] += img.luminance(p) / 256.0 / mlt.b();
                }
            for (int k = 0; k < 4; ++k) {
                sum[build][k] += q[k];
                sum2[build][k] += q[k] * q[k];
            }
        }
    for (int k = 0; k < 4; ++k) {
        double m[2], v[2];
        for (int b = 0; b < 2; ++b) {
            m[b] = sum[b][k] / replicas;
            v[b] = (sum2[b][k] - replicas * m[b] * m[b]) / (replicas - 1);
        }
        double t = (m[0] - m[1]) / std::sqrt(v[0] / replicas + v[1] / replicas);
        std::printf("quadrant %d: packed %.5f, float32 %.5f, t %.2f\n", k, m[0], m[1], t);
        EXPECT_LT(std::fabs(t), 3.6) << "quadrant " << k;
    }
}

// Splats are summed in fixed point and rounded with the step's numbers, so
// an MLT image depends only on the seed (and the device), not on the order
// in which work-items finish; the film is drained every 2 steps here.
TEST(MltDeterminism, SameSeedSameImage) {
    DeviceScene ds = prepare_scene(test::scene("cornell-glass", 24, 24));
    for (std::uint32_t restart : {0u, 4u}) {
        std::vector<float> images[2];
        for (auto& img : images) {
            MltOptions opt = test::plain_mlt();
            opt.threads = 2048;
            opt.film_pass_mutations = 4096;
            opt.seed = 77;
            opt.burn_in_iters = 8;
            opt.restart = restart;
            MltRenderer mlt(test::cl(), ds, opt);
            mlt.prepare();
            mlt.step(16);
            img = mlt.image().rgb;
        }
        EXPECT_EQ(images[0], images[1]) << "--restart " << restart;
    }
}

// A chain splats its gathered stay weight once, when it moves away (or at
// MLT_STAY_FLUSH = 128), instead of at every step; the reference build
// (eager_stay) splats it at every step. Same seed, same chains: the images
// differ only by fixed-point rounding. Per splat the film rounds each
// channel to 2^-24 and the weight is kept to 2^-24, so a pixel that received
// n stay splats differs by at most (n + 1) units of 2^-24 times
// F/I <= 1/0.0722 per unit weight: over these renders (< 2^16 splats a pixel)
// far below 1e-5 of any lit pixel. One chain in 32 is held where it starts
// (test::hold_chains): it stays all 600 steps, gathering 600 at K = 1, past
// the 128 at which the weight is flushed, and 9,600 at K = 16 (16 a step),
// past the 256 at which a weight not flushed would wrap 32 bits; whatever
// the seed. The other chains move as the scene makes them: tiny-caustic
// holds some for a while, cornell moves them often.
// Reading the image mid-render changes nothing: the weights still pending
// are added to the film for the read and taken out again (mlt_owed). Both
// renders use the 64-bit reference film, whose rounding is 2^-24.
TEST(MltStaySplat, GatheredStaysEqualEagerSplatsWithinRounding) {
    SKIP_WITHOUT_INT64_ATOMICS();
    const std::uint32_t steps = 600;
    struct Case {
        const char* name;
        std::uint32_t proposals;
    };
    for (Case c : {Case{"tiny-caustic", 1}, Case{"tiny-caustic", 16}, Case{"cornell", 1}}) {
        const char* name = c.name;
        DeviceScene ds = prepare_scene(test::scene(name, 32, 32));
        Image img[2];
        MltStats stats[2];
        for (int eager = 0; eager < 2; ++eager) {
            MltOptions opt = test::plain_mlt();
            MltTestHooks hooks;
            opt.threads = 1024;
            opt.large_step = 0.1f;
            opt.seed = 7;
            opt.proposals = c.proposals;
            hooks.eager_stay = eager;
            opt.film_atomics64 = true;
            MltRenderer mlt(test::cl(), ds, opt, hooks);
            mlt.prepare();
            std::vector<std::uint32_t> held = test::hold_chains(mlt, 32);
            mlt.step(150);
            Image mid = mlt.image(); // must not disturb what follows
            mlt.step(steps - 150);
            img[eager] = mlt.image();
            stats[eager] = mlt.stats();
            EXPECT_GT(img[eager].mean_luminance(), mid.mean_luminance() * 0.5);
            // The precondition, by construction: the held chains never moved.
            std::vector<std::uint32_t> runs = test::chain_runs(mlt);
            for (std::uint32_t h : held)
                ASSERT_EQ(runs[h], steps) << name << ", K = " << c.proposals << ": chain " << h;
        }
        double worst = 0;
        for (std::size_t i = 0; i < img[0].rgb.size(); ++i) {
            double a = img[0].rgb[i], b = img[1].rgb[i];
            if (b > 0)
                worst = std::max(worst, std::fabs(a - b) / b);
            else
                EXPECT_EQ(a, 0.0) << "pixel value " << i;
        }
        double per[2] = {double(stats[0].atomics) / double(stats[0].mutations),
                         double(stats[1].atomics) / double(stats[1].mutations)};
        std::printf("%s, K = %u: largest relative difference %.3g; global atomics per mutation "
                    "%.2f (gathered) against %.2f (every step)\n",
                    name, c.proposals, worst, per[0], per[1]);
        EXPECT_LT(worst, 1e-5);
        EXPECT_LT(per[0], per[1]);
        EXPECT_EQ(stats[0].accepted, stats[1].accepted) << "the chains took other paths";
    }
}

// Reading the image mid-render leaves the render as it was, bit for bit,
// between drains of the film (every 3 steps here) and right after one.
TEST(MltStaySplat, ReadingTheImageChangesNothing) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 24, 24));
    std::vector<float> images[2];
    for (int reads = 0; reads < 2; ++reads) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 1024;
        opt.film_pass_mutations = 3072;
        opt.seed = 8;
        opt.burn_in_iters = 4;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        for (int k = 0; k < 8; ++k) {
            mlt.step(k % 2 ? 2 : 4);
            if (reads) mlt.image();
        }
        images[reads] = mlt.image().rgb;
    }
    EXPECT_EQ(images[0], images[1]);
}
