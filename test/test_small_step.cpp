// The small step of a packed number (cl/sampling/sample_chain.cl) is integer-only: it
// follows the exponential law of Kelemen et al. within one grid step, is
// symmetric, and the number a lazy evaluation reads is the number a commit
// stores, for every slot width (24, 16 and a widened 17-bit light pick).
#include "render/mlt.hpp"
#include "scene/sample_layout.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <utility>

using namespace smallmlt;

namespace {

const char* kProbeFile = "test/cl/probe_mlt.cl";

// Features whose layout has 24-bit (film, BSDF, light) and 16-bit (lobe
// choice, roulette) slots, and a light pick of 16 bits (<= 256 lights) or 17 (300).
SceneFeatures features(std::uint32_t lights) {
    SceneFeatures f;
    f.with(MAT_DIFFUSE).with(MAT_DIELECTRIC);
    f.num_lights = lights;
    f.depth = 6;
    return f;
}

// Exact small step in grid steps of a `bits`-wide slot at `scale`:
// 2^(bits - scale - 4u), u = (r & 0x7FFFFFFF) / 2^31.
double reference_delta(std::uint32_t r, int bits, int scale) {
    double u = double(r & 0x7FFFFFFFu) / 2147483648.0;
    return std::ldexp(std::exp2(-4.0 * u), bits - scale);
}

} // namespace

// Over 2^20 random stream numbers (and the ends of the range), for each slot
// width at Kelemen's scale (largest step 2^-6) and at the ends of --path-step's
// range (2^-4 and 2^-10): the step is within one grid step of the exact exponential, at least
// one step, its size does not depend on the sign bit, and the move with the
// sign bit flipped is the mirror image (v + d and v - d, modulo 2^bits).
TEST(SmallStep, IntegerDeltaFollowsTheExponentialAndIsSymmetric) {
    DeviceScene ds = test::layout_only_scene(features(300));
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 64;
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    const std::uint32_t n = 1u << 20;
    std::vector<cl_uint> r(2 * n), v(2 * n);
    std::mt19937 rng(17);
    for (std::uint32_t i = 0; i < n; ++i) {
        r[2 * i] = rng();
        r[2 * i + 1] = r[2 * i] ^ 0x80000000u; // the mirror move
        v[2 * i] = v[2 * i + 1] = rng();
    }
    const std::uint32_t ends[] = {0u, 1u, 0x1FFFFFFFu, 0x20000000u, 0x7FFFFFFEu, 0x7FFFFFFFu};
    for (std::uint32_t i = 0; i < 6; ++i) {
        r[2 * i] = ends[i];
        r[2 * i + 1] = ends[i] | 0x80000000u;
    }
    ClBuffer rb(test::cl(), CL_MEM_READ_ONLY, r.size() * 4, r.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, r.size() * 4);
    const std::pair<int, int> widths[] = {{24, 6}, {16, 6}, {17, 6}, {24, 4}, {24, 10}, {16, 10}};
    for (auto [bits, scale] : widths) {
        const std::uint32_t mask = (1u << bits) - 1u;
        std::vector<cl_uint> vb(v.size());
        for (std::size_t i = 0; i < v.size(); ++i)
            vb[i] = v[i] & mask;
        ClBuffer vbuf(test::cl(), CL_MEM_READ_ONLY, vb.size() * 4, vb.data());
        ClKernel k(MltInspect::program(mlt), "probe_small_step");
        k.set_args(rb, vbuf, cl_uint(bits), cl_uint(scale), cl_uint(r.size()), out);
        k.run(test::cl(), r.size());
        std::vector<cl_uint> moved(r.size());
        out.read(test::cl(), moved.data());
        double worst = 0, lo = 1e30, hi = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            std::uint32_t a = 2 * i, b = a + 1, up = r[a] >> 31 ? a : b, down = up ^ 1u;
            std::uint32_t d_up = (moved[up] - vb[up]) & mask;
            std::uint32_t d_down = (vb[down] - moved[down]) & mask;
            ASSERT_EQ(d_up, d_down) << "bits " << bits << " r " << r[a];
            ASSERT_GE(d_up, 1u);
            double exact = reference_delta(r[a], bits, scale);
            double err = std::abs(double(d_up) - exact);
            worst = std::max(worst, err);
            ASSERT_LE(err, 1.0) << "bits " << bits << " scale " << scale << " r " << r[a]
                                << ": step " << d_up << ", exact " << exact;
            lo = std::min(lo, double(d_up));
            hi = std::max(hi, double(d_up));
        }
        std::printf("bits %d, scale %d: steps %g..%g grid steps, largest distance from the "
                    "exact exponential %.3f steps\n",
                    bits, scale, lo, hi, worst);
        EXPECT_EQ(lo, std::ldexp(1.0, bits - scale - 4));
        EXPECT_EQ(hi, std::ldexp(1.0, bits - scale));
    }
}

namespace {

// Random packed states; chain c proposes (small or large, some bounces dead)
// and commits (3c) % (depth + 1) bounces (probe_commit_agrees).
struct CommitRun {
    SampleLayout layout;
    std::uint32_t chains = 4096, dims = 0;
    std::vector<cl_uint> before, after;       // the state's words
    std::vector<cl_uint> prior, lazy, stored; // number d of chain c at c * dims + d
    std::uint32_t committed(std::uint32_t c) const { return (3 * c) % (layout.depth + 1); }
};

CommitRun run_commit(std::uint32_t lights, std::uint32_t path_step = kDefaultPathStep) {
    CommitRun run;
    DeviceScene ds = test::layout_only_scene(features(lights));
    run.layout = ds.layout;
    run.dims = std::uint32_t(ds.layout.vector_dims());
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = run.chains;
    opt.path_step = path_step;
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    run.before.resize(MltInspect::state(mlt).bytes() / 4);
    std::mt19937 rng(lights);
    for (cl_uint& w : run.before)
        w = rng();
    MltInspect::state(mlt).write(test::cl(), run.before.data());
    std::size_t numbers = std::size_t(run.chains) * run.dims;
    ClBuffer prior(test::cl(), CL_MEM_WRITE_ONLY, numbers * 4);
    ClBuffer lazy(test::cl(), CL_MEM_WRITE_ONLY, numbers * 4);
    ClBuffer stored(test::cl(), CL_MEM_WRITE_ONLY, numbers * 4);
    ClKernel k(MltInspect::program(mlt), "probe_commit_agrees");
    k.set_args(MltInspect::state(mlt), cl_uint(run.chains), cl_uint(ds.layout.depth), cl_ulong(7),
               prior, lazy, stored);
    k.run(test::cl(), run.chains);
    run.prior.resize(numbers);
    prior.read(test::cl(), run.prior.data());
    run.lazy.resize(numbers);
    run.stored.resize(numbers);
    run.after.resize(run.before.size());
    lazy.read(test::cl(), run.lazy.data());
    stored.read(test::cl(), run.stored.data());
    MltInspect::state(mlt).read(test::cl(), run.after.data());
    return run;
}

} // namespace

// Every committed number equals the number the path read, for layouts with
// 24-, 16- and 17-bit slots.
TEST(SmallStep, LazyEvaluationAndCommitAgreeOnEveryNumber) {
    for (std::uint32_t lights : {2u, 300u}) {
        CommitRun run = run_commit(lights);
        std::uint64_t compared = 0;
        for (std::uint32_t c = 0; c < run.chains; ++c) {
            std::uint32_t live = kCameraDims + run.committed(c) * run.layout.bounce_dims;
            for (std::uint32_t d = 0; d < live; ++d, ++compared)
                ASSERT_EQ(run.lazy[c * run.dims + d], run.stored[c * run.dims + d])
                    << lights << " lights, chain " << c << ", number " << d;
        }
        EXPECT_GT(compared, std::uint64_t(run.chains) * run.dims / 3);
    }
}

// The commit writes a chain's words whole, in bit-stream order (PssWriter,
// cl/sampling/pss.cl): the bits after the last committed number in its word are
// zero (dead numbers, never read), and the words after it are not touched.
TEST(SmallStep, CommitWritesWholeWordsUpToTheLastCommittedNumber) {
    CommitRun run = run_commit(300);
    const std::uint32_t words = std::uint32_t(run.before.size() / run.chains);
    int partial = 0;
    for (std::uint32_t c = 0; c < run.chains; ++c) {
        std::uint32_t bits = kCameraDims * kHighBits + run.committed(c) * run.layout.bounce_bits;
        std::uint32_t last = (bits - 1) / 32, used = bits - 32 * last;
        cl_uint tail = run.after[last * run.chains + c] >> (used % 32);
        if (used < 32) {
            ++partial;
            EXPECT_EQ(tail, 0u) << "chain " << c << ": dead bits of word " << last << " kept";
        }
        for (std::uint32_t w = last + 1; w < words; ++w)
            ASSERT_EQ(run.after[w * run.chains + c], run.before[w * run.chains + c])
                << "chain " << c << ": word " << w << " after the committed numbers changed";
    }
    EXPECT_GT(partial, int(run.chains) / 2);
}

// --path-step N reaches the path's numbers and only them: over the small
// steps of chains with live bounces, a path number moves at most 1/N of its
// unit interval (and one grid step of rounding), at least 1/(16 N) (less
// one), and the largest moves come within 5% of 1/N (a step's chance to
// exceed 0.95/N is 1.8%, over some 10^4 moves per N). The film numbers, on a
// 64x64 film (probe_commit_agrees), keep their step of 4 pixels: a 16th.
TEST(SmallStep, PathNumbersStepAtMostTheAskedShareOfTheirInterval) {
    for (std::uint32_t n : {16u, 128u, 1024u}) {
        CommitRun run = run_commit(300, n);
        const SampleLayout& l = run.layout;
        std::vector<int> bits_of(kCameraDims, kHighBits);
        bits_of.resize(kCameraDims + l.bounce_dims);
        for (int s = 0; s < kSlotCount; ++s)
            if (l.has(Slot(s))) bits_of[kCameraDims + l.index[s]] = l.bits[s];
        double lo[2] = {1, 1}, hi[2] = {0, 0}; // film, path: moves times their largest
        std::uint64_t moves = 0;
        for (std::uint32_t c = 0; c < run.chains; c += 2) {
            const std::uint32_t alive = c % (l.depth + 1);
            for (std::uint32_t d = 0; d < kCameraDims + alive * l.bounce_dims; ++d) {
                const bool path = d >= kCameraDims;
                const int bits =
                    bits_of[path ? kCameraDims + (d - kCameraDims) % l.bounce_dims : d];
                const std::uint32_t mask = (1u << bits) - 1u, i = c * run.dims + d;
                const std::uint32_t up = (run.lazy[i] - run.prior[i]) & mask;
                const std::uint32_t steps = std::min(up, (0u - up) & mask);
                const double grid = std::ldexp(1.0, -bits), largest = path ? 1.0 / n : 1.0 / 16;
                const double moved = steps * grid;
                ASSERT_LE(moved, largest + grid)
                    << "N " << n << ", chain " << c << ", number " << d;
                ASSERT_GE(moved, largest / 16 - grid)
                    << "N " << n << ", chain " << c << ", number " << d;
                lo[path] = std::min(lo[path], moved / largest);
                hi[path] = std::max(hi[path], moved / largest);
                moves += path;
            }
        }
        std::printf("--path-step %u: %llu path moves, %.4f..%.4f of 1/N; film %.4f..%.4f of "
                    "1/16\n",
                    n, (unsigned long long)moves, lo[1], hi[1], lo[0], hi[0]);
        EXPECT_GT(moves, 10000u);
        for (int path : {0, 1}) {
            EXPECT_GE(hi[path], 0.95) << "N " << n << (path ? ", path" : ", film");
            EXPECT_LE(lo[path], 1.0 / 16 * 1.05) << "N " << n << (path ? ", path" : ", film");
        }
    }
}

namespace {

// A furnace box (scenes/furnace) whose six walls are cut into 6 x 6 x 2
// emissive triangles each: 432 lights, so the light pick is 17 bits wide.
Scene many_light_furnace() {
    std::string dir = test::scratch_dir("many-light-furnace");
    std::string obj = "mtllib f.mtl\nusemtl wall\n";
    int v = 0;
    const int cells = 6;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2)
            for (int i = 0; i < cells; ++i)
                for (int j = 0; j < cells; ++j) {
                    double a0 = -1 + 2.0 * i / cells, a1 = -1 + 2.0 * (i + 1) / cells;
                    double b0 = -1 + 2.0 * j / cells, b1 = -1 + 2.0 * (j + 1) / cells;
                    double corner[4][2] = {{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}};
                    for (auto& q : corner) {
                        double p[3];
                        p[axis] = side;
                        p[(axis + 1) % 3] = q[0];
                        p[(axis + 2) % 3] = q[1];
                        obj += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " +
                               std::to_string(p[2]) + "\n";
                    }
                    obj += "f " + std::to_string(v + 1) + " " + std::to_string(v + 2) + " " +
                           std::to_string(v + 3) + "\nf " + std::to_string(v + 1) + " " +
                           std::to_string(v + 3) + " " + std::to_string(v + 4) + "\n";
                    v += 4;
                }
    test::write_file(dir + "/f.obj", obj);
    test::write_file(dir + "/f.mtl", "newmtl wall\nKd 0.5 0.5 0.5\nKe 1 1 1\n");
    test::write_file(dir + "/f.scene", "film 32 32\ncamera 0 0 0.5  0 0 -1  0 1 0  60\n"
                                       "depth 6\nmesh f.obj\n");
    return load_scene(dir + "/f.scene");
}

} // namespace

// Whole paths: on cornell-water (24- and 16-bit slots) and on a furnace with
// a 17-bit light pick, the lazily evaluated proposal and the state it leaves
// after the commit give the same F and bounces, bit for bit.
TEST(SmallStep, LazyPathEqualsCommittedPath) {
    DeviceScene water = prepare_scene(test::scene("cornell-water", 32, 32));
    DeviceScene furnace = prepare_scene(many_light_furnace());
    ASSERT_EQ(furnace.layout.bits[kLightPick], 17);
    for (const DeviceScene* ds : {&water, &furnace}) {
        MltOptions opt = test::plain_mlt();
        MltTestHooks hooks;
        opt.threads = 1024;
        hooks.extra_files = {kProbeFile};
        MltRenderer mlt(test::cl(), *ds, opt, hooks);
        mlt.prepare();
        ClBuffer eager(test::cl(), CL_MEM_READ_WRITE, MltInspect::state(mlt).bytes());
        ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY,
                     std::size_t(opt.threads) * 3 * sizeof(cl_float4));
        SceneBuffers sb(test::cl(), *ds);
        ClKernel k(MltInspect::program(mlt), "probe_lazy_eager");
        k.set_args(sb, MltInspect::state(mlt), MltInspect::values(mlt), eager, cl_uint(opt.threads),
                   cl_ulong(101), out);
        k.run(test::cl(), opt.threads);
        std::vector<cl_float4> f(std::size_t(opt.threads) * 3);
        out.read(test::cl(), f.data());
        int lit = 0;
        for (std::uint32_t c = 0; c < opt.threads; ++c) {
            ASSERT_EQ(std::memcmp(f[3 * c].s, f[3 * c + 2].s, 16), 0) << "chain " << c;
            lit += f[3 * c].s[0] + f[3 * c].s[1] + f[3 * c].s[2] > 0;
        }
        EXPECT_GT(lit, int(opt.threads) / 10) << "too few lit paths to test anything";
    }
}

namespace {

// The stretch of the film numbers' small step (probe_film_stretch) in each
// tile of `grids`, x then y, for --film-step `film_step`.
std::vector<cl_uint> film_stretch(std::uint32_t film_step, const std::vector<StrataGrid>& grids) {
    DeviceScene ds = test::layout_only_scene(features(1));
    MltOptions opt = test::plain_mlt();
    MltTestHooks hooks;
    opt.threads = 64;
    opt.film_step = film_step;
    hooks.extra_files = {kProbeFile};
    MltRenderer mlt(test::cl(), ds, opt, hooks);
    std::vector<FilmTile> tiles;
    for (const StrataGrid& g : grids)
        tiles.push_back(g.tiles.front());
    ClBuffer tb(test::cl(), CL_MEM_READ_ONLY, tiles.size() * sizeof(FilmTile), tiles.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, tiles.size() * 8);
    ClKernel k(MltInspect::program(mlt), "probe_film_stretch");
    k.set_args(tb, cl_uint(tiles.size()), out);
    k.run(test::cl(), tiles.size());
    std::vector<cl_uint> s(2 * tiles.size());
    out.read(test::cl(), s.data());
    return s;
}

} // namespace

// A film number's largest small step is 2^-6 of its unit square times the
// stretch, so stretch * n / 64 pixels in a tile of n pixels. With --film-step
// film it is a 64th of the film, in a tile as on the whole film; with
// PIXELS, the step asked for, rounded to a multiple of n / 64 (at least
// one); with auto (the default), the larger of twice film's and the
// stretch for 4 pixels. Grids:
// whole films of 128x128, 512x512 and 160x90, and the first tile of 16
// pixels of a 128x128 film.
TEST(SmallStep, FilmStepIsAFilmsSixtyFourthOrTheAskedPixels) {
    const std::vector<StrataGrid> grids = {strata_grid(128, 128, 0), strata_grid(512, 512, 0),
                                           strata_grid(160, 90, 0), strata_grid(128, 128, 16)};
    EXPECT_EQ(film_stretch(0, grids), (std::vector<cl_uint>{1, 1, 1, 1, 1, 1, 8, 8}));
    // auto: 4 pixels is 4 * 64 / n rounded, 2 on 128 and 2.1 and 3.3 on
    // 160x90; on 512 less than a 32nd of the film (stretch 2), which stays;
    // in a tile of 16 of a 128 film, 16 (a 32nd of the film's 8 tiles).
    EXPECT_EQ(film_stretch(kFilmStepAuto, grids), (std::vector<cl_uint>{2, 2, 2, 2, 2, 3, 16, 16}));
    // 8 pixels: 8 * 64 / n, rounded: 4 on 128, 1 on 512, 3.2 and 5.7 on
    // 160x90, 32 in a tile of 16.
    EXPECT_EQ(film_stretch(8, grids), (std::vector<cl_uint>{4, 4, 1, 1, 3, 6, 32, 32}));
    // 2 pixels on 512: less than one stretch (8 pixels); one it is.
    EXPECT_EQ(film_stretch(2, grids), (std::vector<cl_uint>{1, 1, 1, 1, 1, 1, 8, 8}));
}

// The host's largest film step on the whole film (the reach of the OMC
// part's cells, src/render/omc_cells.hpp) is the kernels' stretch in pixels,
// n x stretch / 64 rounded: auto is 4 pixels at 128 (stretch 2), a 32nd of
// 512 (16), and 5 at 160 (stretch 2 of 2.5 pixels); film is 2 at 128 and 8
// at 512; 8 pixels asked are 8 at 128 and 160 (stretch 4 and 3).
TEST(SmallStep, HostFilmStepIsTheKernelsStretchInPixels) {
    MltOptions opt = test::plain_mlt();
    opt.film_step = kFilmStepAuto;
    EXPECT_EQ(film_step_pixels(opt, 128), 4u);
    EXPECT_EQ(film_step_pixels(opt, 512), 16u);
    EXPECT_EQ(film_step_pixels(opt, 160), 5u);
    opt.film_step = 0;
    EXPECT_EQ(film_step_pixels(opt, 128), 2u);
    EXPECT_EQ(film_step_pixels(opt, 512), 8u);
    opt.film_step = 8;
    EXPECT_EQ(film_step_pixels(opt, 128), 8u);
    EXPECT_EQ(film_step_pixels(opt, 160), 8u);
}
