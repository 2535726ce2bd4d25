// The split of each path between an OMC part and an MLT part
// (src/render/split.hpp): the parts add up to the path tracer's estimate,
// path by path and in the furnace's closed form, and the rule that divides
// the time between them.
#include "base/error.hpp"
#include "render/mlt.hpp"
#include "render/split.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace smallmlt;

namespace {

struct Parts {
    std::vector<cl_float4> omc, rest;
};

// The parts of n OMC paths (keys rng_key(seed, i, 0)) under split s.
Parts trace_parts(const DeviceScene& ds, Split s, std::uint32_t n, std::uint64_t seed) {
    std::vector<std::string> files = pt_program_files(PtSampler::Random);
    files.push_back("test/cl/probe_split.cl");
    ClProgram program(test::cl().build(files, ds.layout.defines() + split_defines(s)));
    ClKernel k(program.p, "probe_split");
    SceneBuffers scene(test::cl(), ds);
    ClBuffer omc(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    ClBuffer rest(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float4));
    k.set_args(scene, cl_ulong(seed), cl_uint(n), omc, rest);
    k.run(test::cl(), n);
    Parts p{std::vector<cl_float4>(n), std::vector<cl_float4>(n)};
    omc.read(test::cl(), p.omc.data());
    rest.read(test::cl(), p.rest.data());
    return p;
}

} // namespace

TEST(Split, NamesAndVertices) {
    EXPECT_EQ(parse_split("--split", "direct"), Split::Direct);
    EXPECT_EQ(split_vertices(parse_split("--split", "visible")), 1u);
    EXPECT_EQ(split_vertices(Split::None), 0u);
    EXPECT_THROW(parse_split("--split", "indirect"), UsageError);
}

// Every path, traced from the same numbers under each split: the parts add
// up to the unsplit path's contribution (to float rounding: the terms are
// summed in two accumulators), the path is the same (its ray count), and
// each split moves light into the OMC part wherever the camera sees some.
// Scenes: a dielectric seen directly (cornell-water), light through a gap,
// the lamp itself out of sight (ajar).
TEST(Split, PartsAddUpToThePathTracerPathByPath) {
    const std::uint32_t n = 16384;
    for (const char* name : {"cornell-water", "ajar"}) {
        DeviceScene ds = prepare_scene(test::scene(name, 32, 32));
        Parts whole = trace_parts(ds, Split::None, n, 77);
        for (Split s : {Split::Visible, Split::Direct}) {
            Parts p = trace_parts(ds, s, n, 77);
            std::uint32_t omc_paths = 0, rest_paths = 0;
            for (std::uint32_t i = 0; i < n; ++i) {
                EXPECT_EQ(whole.omc[i].s[0], 0.0f);
                ASSERT_EQ(p.omc[i].s[3], whole.omc[i].s[3]) << name << ": path " << i;
                for (int c = 0; c < 3; ++c) {
                    float sum = p.omc[i].s[c] + p.rest[i].s[c], want = whole.rest[i].s[c];
                    ASSERT_NEAR(sum, want, 1e-5f * std::max(1.0f, want))
                        << name << " split " << split_name(s) << ": path " << i;
                }
                omc_paths += p.omc[i].s[1] > 0;
                rest_paths += p.rest[i].s[1] > 0;
            }
            if (s == Split::Visible && std::string(name) == "ajar")
                EXPECT_EQ(omc_paths, 0u) << "ajar's lamp is out of the camera's sight";
            else
                EXPECT_GT(omc_paths, n / 200) << name << " " << split_name(s);
            EXPECT_GT(rest_paths, n / 100) << name << " " << split_name(s);
        }
    }
}

// The furnace (test::furnace_sum): the OMC part of a split of L vertices is
// sum_{i<L} 0.5^i and the chains' b the rest up to the depth.
// Each part of the furnace at depth 4 against its closed form: b (the MLT
// part's mean) within 4 standard errors plus 0.2%, the OMC part's image
// mean (per-pixel samples and the burn-in's) within 0.3%, the chains'
// image mean equal to b (the film's rounding), and so the whole image.
TEST(Split, FurnacePartsAreTheClosedForm) {
    const int depth = 4;
    DeviceScene ds = prepare_scene(test::scene("furnace", 16, 16, depth));
    for (Split s : {Split::Visible, Split::Direct}) {
        MltOptions opt = test::plain_mlt();
        opt.threads = 4032; // 110.25 burn-in paths per pixel: 110 or 111 land
        opt.burn_in_iters = 7;
        opt.seed = 9;
        opt.split = s;
        opt.omc_effort = 0.1;
        opt.omc_cells = false; // the furnace's every cell would go to the OMC part whole
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(8);
        int l = int(split_vertices(s));
        double want_b = test::furnace_sum(l, depth), want_omc = test::furnace_sum(0, l - 1);
        double b = mlt.b(), omc = mlt.part_image(MltRenderer::Part::Omc).mean_luminance();
        double chains = mlt.part_image(MltRenderer::Part::Mlt).mean_luminance();
        std::printf("furnace depth %d, split %s: b %.5f (+-%.3f%%) vs %.5f; OMC part %.5f vs "
                    "%.5f (%u spp + burn-in)\n",
                    depth, split_name(s), b, 100 * mlt.b_rel_error(), want_b, omc, want_omc,
                    mlt.omc_spp());
        EXPECT_NEAR(b, want_b, (4 * mlt.b_rel_error() + 0.002) * want_b) << split_name(s);
        EXPECT_NEAR(omc, want_omc, 0.003 * want_omc) << split_name(s);
        EXPECT_NEAR(chains, b, test::film_mean_tolerance(mlt) * b) << split_name(s);
        EXPECT_GT(mlt.omc_spp(), 0u) << split_name(s);
        if (s == Split::Visible) {
            // Every OMC-part sample is exactly Ke = 1, so each pixel is 1 when
            // the burn-in's samples count in the pixels they landed in (with
            // their expected count instead, 110.25, pixels would be off 1).
            Image part = mlt.part_image(MltRenderer::Part::Omc);
            float worst = 0;
            for (float v : part.rgb)
                worst = std::max(worst, std::fabs(v - 1.0f));
            EXPECT_LT(worst, 1e-5f) << "the OMC part's pixels are not all 1";
        }
    }
}

namespace {

// A rank whose others all vote no.
class OutvotedRank : public SingleRank {
  public:
    bool all(bool) override { return false; }
};

} // namespace

// --split auto runs chains only where the MLT part's per-pixel relative
// variance says they pay: not in the furnace, whose light after the first
// vertex is smooth (every path of the same length carries the same light),
// where it renders the whole image by per-pixel samples (the burn-in's whole
// paths too) and matches the closed form; but on cornell-water, whose MLT
// part holds the caustics. Ranks agree: one rank's no is every rank's.
// The furnace with and without the OMC part's cells: with them, every cell
// goes to the OMC part before the burn-in's later rounds, which then hold
// no MLT part; without, those rounds' MLT parts are half the image's light
// after the first vertex.
TEST(Split, AutoRunsChainsOnlyWhereTheyPay) {
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.burn_in_iters = 8;
    opt.seed = 12;
    opt.split = Split::Auto;
    DeviceScene furnace = prepare_scene(test::scene("furnace", 16, 16, 4));
    for (bool cells : {true, false}) {
        opt.omc_cells = cells;
        MltRenderer f(test::cl(), furnace, opt);
        f.prepare();
        f.step(8);
        std::printf("furnace, cells %s: r %.3g, split %s, image %.5f of %.5f\n",
                    cells ? "on" : "off", f.mlt_relative_variance(), split_name(f.split()),
                    f.image().mean_luminance(), test::furnace_sum(0, 4));
        EXPECT_EQ(f.split(), Split::All);
        EXPECT_EQ(f.stats().mutations, 0u);
        EXPECT_NEAR(f.image().mean_luminance(), test::furnace_sum(0, 4),
                    0.003 * test::furnace_sum(0, 4))
            << "cells " << cells;
    }
    opt.omc_cells = true;
    std::printf("cornell-water: ");

    DeviceScene water = prepare_scene(test::scene("cornell-water", 32, 32));
    MltRenderer w(test::cl(), water, opt);
    w.prepare();
    w.step(2);
    std::printf("r %.3g, split %s\n", w.mlt_relative_variance(), split_name(w.split()));
    EXPECT_EQ(w.split(), kChainsSplit);
    EXPECT_GT(w.stats().mutations, 0u);

    OutvotedRank outvoted;
    MltRenderer o(test::cl(), water, opt);
    o.prepare(outvoted);
    EXPECT_EQ(o.split(), Split::All) << "the ranks did not agree";
}

// The OMC part's calls: chunks of a power of two, at most 16, at most
// spp / 16 and at most 2^18 paths, growing with the samples so far (so they
// do not depend on how steps are grouped into passes).
TEST(Split, OmcChunksGrowWithTheSamples) {
    const std::uint64_t p = 128 * 128;
    EXPECT_EQ(omc_chunk(0, p), 1u);
    EXPECT_EQ(omc_chunk(31, p), 1u);
    EXPECT_EQ(omc_chunk(32, p), 2u);
    EXPECT_EQ(omc_chunk(63, p), 2u);
    EXPECT_EQ(omc_chunk(127, p), 4u);
    EXPECT_EQ(omc_chunk(128, p), 8u);
    EXPECT_EQ(omc_chunk(255, p), 8u);
    EXPECT_EQ(omc_chunk(512, p), 16u);
    EXPECT_EQ(omc_chunk(1u << 30, p), 16u);
    EXPECT_EQ(omc_chunk(1u << 30, 256 * 256), 4u);
    EXPECT_EQ(omc_chunk(1u << 30, 512 * 512), 1u);
    EXPECT_EQ(omc_chunk(1u << 30, 1024 * 1024), 1u);
    for (std::uint32_t spp = 16; spp < 5000; ++spp)
        EXPECT_LE(omc_chunk(spp, p), spp / 16) << spp;
}

namespace {

// t_o / t_m of the rule's n_o: the OMC part's rays per step over the chains'.
double omc_time_ratio(const SplitCosts& c, double effort) {
    return omc_samples_per_step(c, effort).film * c.pixels * c.omc_rays /
           (c.threads * c.mutation_rays);
}

} // namespace

// The rule gives t_o / t_m = sqrt(A / C) (split.hpp), times --omc-effort,
// but at most kOmcMaxTimeRatio and at least kOmcMinTimeRatio times the
// chains' time before the effort.
// The costs are those the burn-in measured at 128x128: cornell-water's
// (V_o from its 36 cm light seen directly) lie below the cap, water-spark's
// (its 1 cm light, V_o 3.1e8) far above it.
TEST(Split, RuleGivesTheOmcPartAtMostTheChainsTime) {
    SplitCosts water;
    water.omc_variance = 19848.8;
    water.b = 0.225809;
    water.pixels = 128 * 128;
    water.omc_rays = 1;
    water.mutation_rays = 12.3588;
    water.threads = 65536;
    const double a = water.omc_variance * water.pixels * water.omc_rays;
    const double cm =
        kChainCorrelation * water.b * water.b * water.pixels * water.pixels * water.mutation_rays;
    EXPECT_NEAR(omc_time_ratio(water, 1), std::sqrt(a / cm), 1e-12);
    EXPECT_NEAR(omc_time_ratio(water, 1), 0.490, 0.001);
    EXPECT_NEAR(omc_time_ratio(water, 2), 2 * std::sqrt(a / cm), 1e-12);

    SplitCosts spark = water;
    spark.omc_variance = 3.125e8;
    spark.b = 0.236839;
    spark.mutation_rays = 8.35022;
    std::printf("water-spark: the rule's sqrt(A / C) %.1f, capped at %.1f\n",
                std::sqrt(spark.omc_variance * spark.pixels /
                          (kChainCorrelation * spark.b * spark.b * spark.pixels * spark.pixels *
                           spark.mutation_rays)),
                kOmcMaxTimeRatio);
    EXPECT_DOUBLE_EQ(omc_time_ratio(spark, 1), kOmcMaxTimeRatio);
    EXPECT_DOUBLE_EQ(omc_time_ratio(spark, 0.5), 0.5 * kOmcMaxTimeRatio);

    // A burn-in that missed the light saw no variance: the floor.
    SplitCosts missed = spark;
    missed.omc_variance = 0;
    EXPECT_DOUBLE_EQ(omc_time_ratio(missed, 1), kOmcMinTimeRatio);
    EXPECT_DOUBLE_EQ(omc_time_ratio(missed, 0), 0.0) << "--omc-effort 0";
}

// With cells the OMC part renders whole, the times of its two parts are in
// proportion to sqrt(A) and sqrt(A_c) (split.hpp), their sum capped at
// kOmcMaxTimeRatio, and the cells' at least their share of all time. Costs
// of ajar at 128x128: no light seen directly (V_o = 0: the film's floor),
// 13 cells of whole paths.
TEST(Split, RuleGivesTheCellsTheirOwnShare) {
    SplitCosts c;
    c.b = 0.067;
    c.pixels = 128 * 128;
    c.omc_rays = 1;
    c.mutation_rays = 9;
    c.threads = 16384;
    c.cell_pixels = 13 * 64;
    c.cell_rays = 6;
    c.cell_variance = 0.5 * c.cell_pixels;
    const double cm = kChainCorrelation * c.b * c.b * c.pixels * c.pixels * c.mutation_rays;
    const double want_c =
        std::sqrt(kPixelStratification * c.cell_variance * c.cell_pixels * c.cell_rays / cm);
    const OmcRates r = omc_samples_per_step(c, 1);
    const double per_time = c.threads * c.mutation_rays;
    const double film_pixels = c.pixels - c.cell_pixels;
    EXPECT_NEAR(r.film * film_pixels * c.omc_rays / per_time, kOmcMinTimeRatio, 1e-12);
    EXPECT_NEAR(r.cells * c.cell_pixels * c.cell_rays / per_time, want_c, 1e-12);
    std::printf("ajar-like cells: t_c / t_m %.3f, %.3g + %.3g spp per step\n", want_c, r.film,
                r.cells);

    // Light so smooth that the rule would give the cells less than their
    // share f of the film: f of the whole time, t_c = f (t_m + t_o + t_c).
    SplitCosts smooth = c;
    smooth.cell_variance = 1e-6;
    const double f = c.cell_pixels / c.pixels;
    const double t_smooth =
        omc_samples_per_step(smooth, 1).cells * c.cell_pixels * c.cell_rays / per_time;
    EXPECT_NEAR(t_smooth, f * (1 + kOmcMinTimeRatio + t_smooth), 1e-12);

    // Far above the cap: both parts scaled down to it together, in the
    // proportion sqrt(A) : sqrt(A_c) = 1 : 2.
    c.omc_variance = 1e6;
    c.cell_variance = 4 * c.omc_variance * film_pixels / c.cell_pixels * c.omc_rays / c.cell_rays /
                      kPixelStratification;
    const OmcRates capped = omc_samples_per_step(c, 1);
    const double t_o = capped.film * film_pixels * c.omc_rays / per_time;
    const double t_c = capped.cells * c.cell_pixels * c.cell_rays / per_time;
    EXPECT_NEAR(t_o, kOmcMaxTimeRatio / 3, 1e-12);
    EXPECT_NEAR(t_c, 2 * kOmcMaxTimeRatio / 3, 1e-12);

    // Each part below the cap, together above it (0.6 + 0.6): scaled to it.
    SplitCosts both = c;
    both.omc_variance = 0.36 * cm / (film_pixels * c.omc_rays);
    both.cell_variance = 0.36 * cm / (kPixelStratification * c.cell_pixels * c.cell_rays);
    const OmcRates half = omc_samples_per_step(both, 1);
    EXPECT_NEAR(half.film * film_pixels * c.omc_rays / per_time, kOmcMaxTimeRatio / 2, 1e-9);
    EXPECT_NEAR(half.cells * c.cell_pixels * c.cell_rays / per_time, kOmcMaxTimeRatio / 2, 1e-9);

    // No cells: the rule of one OMC part, every pixel alike.
    SplitCosts none = c;
    none.cell_pixels = 0;
    none.cell_variance = 0;
    EXPECT_EQ(omc_samples_per_step(none, 1).cells, 0.0);
    EXPECT_NEAR(omc_time_ratio(none, 1), kOmcMaxTimeRatio, 1e-12);
}

// The share of the MLT part's light that lay behind smooth transmitters
// (cl/path/path.cl, behind_specular): none in cornell, which has none;
// about a third in cornell-water, whose floor lies under the water (35.5%
// at 128x128); and none again once the water is made opaque: a blocker
// counts only where it lets light through by a Dirac lobe. With r, it
// decides whether the chains pay (chains_pay).
TEST(Split, LightBehindGlassIsWhatSmoothTransmittersBlock) {
    MltOptions opt = test::plain_mlt();
    opt.threads = 4096;
    opt.burn_in_iters = 8;
    opt.split = Split::Auto;
    auto share = [&](const Scene& scene) {
        DeviceScene ds = prepare_scene(scene);
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        return mlt.behind_specular_share();
    };
    Scene water = test::scene("cornell-water", 32, 32);
    const double in_cornell = share(test::scene("cornell", 32, 32)), in_water = share(water);
    int opaque = 0;
    for (Material& m : water.materials)
        if (m.type == MAT_DIELECTRIC) {
            m.type = MAT_DIFFUSE;
            m.kd[0] = m.kd[1] = m.kd[2] = 0.5f;
            ++opaque;
        }
    ASSERT_GT(opaque, 0) << "cornell-water has no smooth dielectric";
    const double in_opaque_water = share(water);
    std::printf("light behind glass: cornell %.3g, cornell-water %.3g, its water opaque %.3g\n",
                in_cornell, in_water, in_opaque_water);
    EXPECT_EQ(in_cornell, 0.0);
    EXPECT_GT(in_water, 0.25);
    EXPECT_LT(in_water, 0.5);
    EXPECT_EQ(in_opaque_water, 0.0);

    for (bool restarting : {false, true}) {
        const double ratio = chains_pay_ratio(restarting);
        EXPECT_FALSE(chains_pay(0.5, 0.0, restarting));
        EXPECT_TRUE(chains_pay(ratio * 1.01, 0.0, restarting));
        EXPECT_TRUE(chains_pay(0.5, kChainsPayBehindShare * 1.01, restarting));
        EXPECT_FALSE(chains_pay(ratio, kChainsPayBehindShare, restarting));
    }
    EXPECT_EQ(chains_pay_ratio(false), kChainsPayRatio);
    EXPECT_EQ(chains_pay_ratio(true), kRestartPayFactor * kChainsPayRatio);
}

// Chains that restart pay from kRestartPayFactor times kChainsPayRatio
// (split.hpp): cornell-glossy at 32x32, whose MLT part's r lies between the
// two (5.4 at seed 1, 4,096 threads), runs its chains where they do not
// restart (--restart 0) and none where --restart auto restarts them every
// 8 steps (4,096 chains on 1,024 pixels).
TEST(Split, RestartingChainsPayFromAHigherRatio) {
    DeviceScene ds = prepare_scene(test::scene("cornell-glossy", 32, 32));
    auto run = [&](std::uint32_t restart) {
        MltOptions opt; // the command line's defaults
        opt.threads = 4096;
        opt.seed = 1;
        opt.restart = restart;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(2);
        std::printf("--restart %s: r %.3g, restarts every %u steps, split %s, %llu mutations\n",
                    restart == kRestartAuto ? "auto" : std::to_string(restart).c_str(),
                    mlt.mlt_relative_variance(), mlt.report().restart_every,
                    split_name(mlt.split()),
                    static_cast<unsigned long long>(mlt.stats().mutations));
        EXPECT_GT(mlt.mlt_relative_variance(), chains_pay_ratio(false)) << "not the scene's r";
        EXPECT_LT(mlt.mlt_relative_variance(), chains_pay_ratio(true)) << "not the scene's r";
        return std::make_pair(mlt.split(), mlt.stats().mutations);
    };
    const auto free = run(0), restarting = run(kRestartAuto);
    EXPECT_EQ(free.first, kChainsSplit);
    EXPECT_GT(free.second, 0u);
    EXPECT_EQ(restarting.first, Split::All);
    EXPECT_EQ(restarting.second, 0u);
}

// The chains beside the OMC part on water-spark (a 1 cm light of radiance
// 1e5 seen directly, scenes/generate.py), with the defaults but for the
// threads, at a seed whose burn-in found none of the rare paths through the
// water to the light (at 16,384 threads seeds 3 and 4 found some, 1 and 2
// none): its MLT part's relative variance (0.52) says path tracing renders it well,
// but half of the light its paths aimed at lay behind the water, and
// --split auto runs the chains. They run, and each step's OMC part traces
// no more rays than they do, so that no step outlasts --time by more than
// the chains' own step. Before the cap, the rule gave the OMC part 169 times the chains'
// time here, and the first step alone ran past a 60-s --time.
// The light covers 3% of a pixel, so the burn-in's 2^19 paths hit it about
// once, and at this seed not at all: V_o of its paths is 0. The emission
// seen from the eye (src/render/emission_seen.hpp) still puts one sample's
// worth of it under V_o, and the cap binds: the OMC part's rays are the
// chains' times --omc-effort. Without that floor the rule gave it a 16th
// of that (kOmcMinTimeRatio), and 320-336 samples a pixel in 20 s where
// path tracing renders 1,582-1,664. Split.RuleGivesTheOmcPartAtMostTheChainsTime
// checks the cap itself.
TEST(Split, ChainsRunBesideABrightLightSeenDirectly) {
    DeviceScene ds = prepare_scene(test::scene("water-spark", 160, 90));
    MltOptions opt; // the command line's defaults
    ASSERT_EQ(opt.split, Split::Auto);
    opt.threads = 16384;
    opt.seed = 2;
    opt.omc_cells = false; // the burn-in of 32 rounds that misses
    MltRenderer mlt(test::cl(), ds, opt);
    mlt.prepare();
    std::printf("r %.3g, light behind glass %.1f%%; ", mlt.mlt_relative_variance(),
                100 * mlt.behind_specular_share());
    EXPECT_LT(mlt.mlt_relative_variance(), kChainsPayRatio) << "not the seed that misses";
    const std::vector<double>& seen = mlt.burn_in_parts().omc;
    ASSERT_EQ(*std::max_element(seen.begin(), seen.end()), 0.0)
        << "the burn-in's paths hit the light";
    mlt.step(4);
    MltStats s = mlt.stats();
    const OmcPartTracer& part = *MltInspect::omc_part(mlt);
    double omc_rays_per_step = mlt.omc_rate() * double(part.rays()) / double(part.spp());
    // The chains' time: their mutations and the restarts' rounds (--restart
    // auto restarts here: 16,384 chains on 14,400 pixels), whose paths cost
    // about a mutation's rays.
    MltOptions resolved = opt;
    resolved.restart = restart_steps(opt, mlt.chains(), mlt.pixels());
    double chain_rays_per_step = double(s.rays) / 4 * (1 + restart_rounds_per_step(resolved));
    std::printf("split %s, %llu mutations; OMC part %.1f spp per step, %.4g rays a step "
                "against the chains' %.4g\n",
                split_name(mlt.split()), static_cast<unsigned long long>(s.mutations),
                mlt.omc_rate(), omc_rays_per_step, chain_rays_per_step);
    EXPECT_EQ(mlt.split(), kChainsSplit);
    EXPECT_EQ(s.mutations, 4u * opt.threads);
    EXPECT_GT(mlt.part_image(MltRenderer::Part::Mlt).mean_luminance(), 0.0);
    EXPECT_LE(omc_rays_per_step, 1.05 * chain_rays_per_step);
    EXPECT_GE(omc_rays_per_step, 0.95 * opt.omc_effort * kOmcMaxTimeRatio * chain_rays_per_step);
}

// The restarts' rounds (--restart R, B rounds: B / R paths a mutation, each
// about a mutation's rays) are the chains' time: the rule then gives the
// OMC part sqrt(1 + B / R) times the time per mutation it gives without
// them (its optimum, split.hpp), and its floor and cap 1 + B / R times.
// Same seed and large steps, so the same burn-in and first step.
TEST(Split, RestartsCountAsTheChainsTime) {
    DeviceScene ds = prepare_scene(test::scene("ajar", 64, 64));
    auto rates = [&](std::uint32_t restart) {
        MltOptions opt;
        opt.threads = 4096;
        opt.seed = 1;
        opt.large_step = 0.1f;
        opt.restart = restart;
        MltRenderer mlt(test::cl(), ds, opt);
        mlt.prepare();
        mlt.step(1);
        return std::make_pair(mlt.omc_rate(), mlt.omc_cell_rate());
    };
    const auto without = rates(0), with = rates(16);
    const double u = 32.0 / 16;
    std::printf("OMC part per step: film %.4g against %.4g without restarts, cells %.4g "
                "against %.4g\n",
                with.first, without.first, with.second, without.second);
    ASSERT_GT(without.first, 0.0);
    EXPECT_GE(with.first / without.first, std::sqrt(1 + u) * (1 - 1e-9));
    EXPECT_LE(with.first / without.first, (1 + u) * (1 + 1e-9));
    ASSERT_GT(without.second, 0.0) << "ajar's slit goes to the OMC part's cells";
    EXPECT_GE(with.second / without.second, std::sqrt(1 + u) * (1 - 1e-9));
    EXPECT_LE(with.second / without.second, (1 + u) * (1 + 1e-9));
}
