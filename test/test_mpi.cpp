// smallmlt-mpi (src/mpi/) against the same ranks rebuilt in this process:
// `mpirun -np R` must write the image that the R ranks' methods, run here
// one after another with the keys the job gave them, make when their
// tallies are summed. MLT's tallies are integers and PT's are sums of
// floats (exact in double for these few ranks), so the images must agree
// bit for bit. Also: b of the job is b of the union of the ranks' samples,
// and one rank is what smallmlt renders.
#include "app/cli.hpp"
#include "app/commands.hpp"
#include "image/image.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <memory>

using namespace smallmlt;

namespace {

// What the collectives of R ranks rebuilt one after another give: each
// rank's input to each call, and every call's answer once all R inputs are
// known. A rank rebuilt before the others gave theirs (or after a call it
// could not be answered) gets its own input back, and the replay is then
// not complete: rebuilding again answers one call more.
struct Exchange {
    explicit Exchange(int ranks) : ranks(ranks) {}
    int ranks;
    std::vector<std::vector<std::vector<double>>> inputs; // [call][rank]; empty: not given
    bool complete = true;
};

// Rank `rank` of the exchange's ranks, for building a rank's method: any
// and all are the OR and AND over ranks, sum_all their sum in rank order
// (exact for two ranks, as MPI's is); sum_to_root and gather are never
// called here.
class ReplayRank : public RankGroup {
  public:
    ReplayRank(int rank, Exchange& ex) : rank_(rank), ex_(ex) {}
    int rank() const override { return rank_; }
    int size() const override { return ex_.ranks; }
    int local_rank() const override { return rank_; }
    std::string host() const override { return "test"; }
    bool any(bool mine) override { return combine({double(mine)}, true)[0] > 0; }
    bool all(bool mine) override { return combine({double(mine)}, false)[0] > 0; }
    void sum_to_root(std::vector<std::uint64_t>&) override {}
    void sum_to_root(std::vector<double>&) override {}
    void sum_all(std::vector<double>& v) override { v = combine(v, true); }
    std::vector<std::string> gather(const std::string& mine) override { return {mine}; }

  private:
    // The sum (or, for `sum` false, the minimum) over ranks of call `calls_`.
    std::vector<double> combine(const std::vector<double>& mine, bool sum) {
        std::size_t call = calls_++;
        if (ex_.inputs.size() <= call) ex_.inputs.resize(call + 1);
        std::vector<std::vector<double>>& in = ex_.inputs[call];
        in.resize(std::size_t(ex_.ranks));
        if (answered_) in[std::size_t(rank_)] = mine; // computed from answers only
        bool known = std::all_of(in.begin(), in.end(), [](const auto& v) { return !v.empty(); });
        answered_ = answered_ && known;
        if (!answered_) {
            ex_.complete = false;
            return mine;
        }
        std::vector<double> out = in[0];
        for (std::size_t r = 1; r < in.size(); ++r)
            for (std::size_t k = 0; k < out.size(); ++k)
                out[k] = sum ? out[k] + in[r][k] : std::min(out[k], in[r][k]);
        return out;
    }
    int rank_;
    Exchange& ex_;
    std::size_t calls_ = 0;
    bool answered_ = true;
};

const char* kMpirun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 120 "
                      "mpirun --oversubscribe -np ";

// The smallmlt binary under test (SMALLMLT_BIN, as test/run_all.sh sets
// it), and smallmlt-mpi beside it.
std::string smallmlt_bin() {
    const char* b = std::getenv("SMALLMLT_BIN");
    return b ? b : "build/smallmlt";
}

std::string mpi_bin() {
    std::string b = smallmlt_bin();
    std::size_t slash = b.find_last_of('/');
    return (slash == std::string::npos ? "" : b.substr(0, slash + 1)) + "smallmlt-mpi";
}

std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at < line.size()) {
        std::size_t end = line.find(' ', at);
        if (end == std::string::npos) end = line.size();
        if (end > at) out.push_back(line.substr(at, end - at));
        at = end + 1;
    }
    return out;
}

RenderOptions parse_render(const std::string& args) {
    std::vector<std::string> w = words("smallmlt render " + args);
    std::vector<const char*> argv;
    for (const std::string& s : w)
        argv.push_back(s.c_str());
    return parse_command_line(int(argv.size()), argv.data()).render;
}

// The image of the job's ranks rebuilt here, rank r from rank_args[r], and
// b of the union of their samples (MLT only; 0 for PT). Rebuilt again until
// every collective of every rank had its answer (at most one pass more than
// the calls a rank makes).
struct Rebuilt {
    Image image;
    double b_union = 0;
};

Rebuilt rebuild(const std::vector<std::string>& rank_args) {
    const int ranks = int(rank_args.size());
    std::deque<DeviceScene> scenes; // the methods keep references to them
    std::vector<RenderOptions> opts;
    for (const std::string& args : rank_args) {
        opts.push_back(parse_render(args + " --quiet"));
        Scene scene = load_scene(opts.back().scene);
        scene.width = *opts.back().width;
        scene.height = *opts.back().height;
        if (opts.back().depth) scene.depth = *opts.back().depth;
        scene.roulette = opts.back().roulette;
        scenes.push_back(prepare_scene(scene));
    }
    Exchange ex(ranks);
    for (int pass = 0;; ++pass) {
        ex.complete = true;
        Tally sum;
        std::unique_ptr<Integrator> first;
        double b_sum = 0, b_n = 0;
        for (int r = 0; r < ranks; ++r) {
            const RenderOptions& o = opts[std::size_t(r)];
            ReplayRank me(r, ex);
            std::unique_ptr<Integrator> m =
                make_integrator(o, test::cl(), scenes[std::size_t(r)], me);
            m->prepare(me);
            std::uint64_t units = m->units_for_spp(*o.spp, r, ranks);
            for (std::uint64_t done = 0; done < units; done += 7)
                m->advance(std::uint32_t(std::min<std::uint64_t>(7, units - done)));
            Tally t = m->tally();
            if (r == 0) sum = t;
            for (std::size_t i = 0; r > 0 && i < t.ints.size(); ++i)
                sum.ints[i] += t.ints[i];
            for (std::size_t i = 0; r > 0 && i < t.reals.size(); ++i)
                sum.reals[i] += t.reals[i];
            if (auto* mlt = dynamic_cast<MltRenderer*>(m.get())) {
                // b of this rank's own samples, weighted by their number.
                MltStats s = mlt->stats();
                double n = double(std::uint64_t(mlt->chains()) * o.mlt.burn_in_iters + s.large);
                b_sum += mlt->b() * n;
                b_n += n;
            }
            if (r == 0) first = std::move(m);
        }
        if (!ex.complete && pass < 4) continue;
        EXPECT_TRUE(ex.complete) << "collectives left without an answer";
        Rebuilt out;
        out.image = first->image_from(sum);
        out.b_union = b_n > 0 ? b_sum / b_n : 0;
        return out;
    }
}

// The job: `mpirun` with rank r running `smallmlt-mpi render rank_args[r]`.
Image run_job(const std::vector<std::string>& rank_args, const std::string& out) {
    std::string cmd = kMpirun;
    for (std::size_t r = 0; r < rank_args.size(); ++r)
        cmd += (r ? " : -np 1 " : "1 ") + mpi_bin() + " render " + rank_args[r] +
               " --quiet --out " + out;
    cmd += " < /dev/null > " + out + ".log 2>&1";
    int rc = std::system(cmd.c_str());
    EXPECT_EQ(rc, 0) << cmd;
    return read_image(out);
}

} // namespace

// Every option whose data goes through a collective, on 2 or 3 ranks:
// - MLT (chains of each rank's seed, the work shared evenly): the film and
//   b's sums in the tallies' integers, the burn-in's squares in its reals;
//   with Kelemen's weights and a split, the OMC part's samples and the
//   burn-in's in both;
// - --split auto, rank 0 on the furnace (its vote: no chains) and rank 1 on
//   cornell-water (yes): every rank takes the AND (all), renders by
//   path tracing alone and adds the burn-in's whole paths to its reals;
// - --target two-stage: the first half of every rank's burn-in, summed over
//   ranks (sum_all), fixes one set of cells and weights: 4 cells from 4,096
//   samples, where one rank's 2,048 would give 1 (2 ranks, whose sum is
//   exact in either order);
// - --strata 12: 4 tiles, 8 work-groups each rank deals by its own burn-in;
//   the tiles' counts and sums add up over ranks, and B0 per tile is the
//   union's (sum_all);
// - PT (rank r renders samples r, r + R, ...): the per-pixel sums in the
//   reals, the samples in the integers, with Sobol and random samples.
TEST(MpiRender, RanksGiveTheImageOfTheirKeys) {
    std::string dir = test::scratch_dir("mpi");
    struct Case {
        std::vector<std::string> rank_args;
        bool mean_is_b; // no split, expected values, luminance target: the image's mean is b
    };
    auto ranks = [](const std::string& args, int n) { return std::vector<std::string>(n, args); };
    const std::string film = " --width 24 --height 24 --threads 256 --spp 6 --seed 9",
                      mlt = "scenes/cornell.scene" + film + " --burn-in-iters 4";
    const std::string pt = "scenes/cornell-water.scene --method pt --width 24 --height 24 --spp 7";
    const std::string vote = film + " --burn-in-iters 4 --split auto";
    const Case cases[] = {
        {ranks(mlt + " --split none --weights expected", 2), true},
        {ranks(mlt + " --split direct --weights kelemen", 3), false},
        {{"scenes/furnace.scene --depth 4" + vote, "scenes/cornell-water.scene" + vote}, false},
        {ranks("scenes/cornell.scene" + film +
                   " --burn-in-iters 16 --split none --target two-stage",
               2),
         false},
        {ranks("scenes/cornell-water.scene --width 24 --height 24 --threads 512 --spp 6 --seed 9 "
               "--burn-in-iters 4 --split none --strata 12",
               2),
         false},
        {ranks(pt, 3), false},
        {ranks(pt + " --sampler random", 2), false},
    };
    int k = 0;
    for (const Case& c : cases) {
        std::string out = dir + "/case" + std::to_string(k++) + ".pfm", what = c.rank_args.back();
        Image job = run_job(c.rank_args, out);
        Rebuilt here = rebuild(c.rank_args);
        EXPECT_EQ(job.rgb, here.image.rgb) << what << " on " << c.rank_args.size() << " ranks";
        if (c.mean_is_b) {
            // The image's mean is b of the summed samples: the union's.
            std::printf("%zu ranks: image mean %.7f, b of the union %.7f\n", c.rank_args.size(),
                        job.mean_luminance(), here.b_union);
            EXPECT_NEAR(job.mean_luminance(), here.b_union, 1e-3 * here.b_union);
        }
    }
}

// The two-stage target of 2 ranks rebuilt here: every rank's cells and
// weights are those of the union of the ranks' samples that fix it (the
// first half of each burn-in), not of its own: 4 cells from 2 x 2,048
// samples, where 2,048 would make 1.
TEST(MpiRender, TwoStageRanksFixOneTargetFromAllTheirSamples) {
    const std::uint32_t w = 24, h = 24;
    DeviceScene ds = prepare_scene(test::scene("cornell", int(w), int(h)));
    MltOptions opt;
    opt.threads = 256;
    opt.burn_in_iters = 16;
    opt.target = Target::TwoStage;
    opt.omc_cells = false; // the two-stage weights alone
    Exchange ex(2);
    std::vector<std::vector<float>> weights;
    for (int pass = 0; pass < 2; ++pass) { // the second has every rank's sums
        ex.complete = true;
        weights.clear();
        for (int r = 0; r < 2; ++r) {
            ReplayRank me(r, ex);
            opt.seed = rank_seed(9, r);
            MltRenderer mlt(test::cl(), ds, opt);
            mlt.sample_starts(me);
            weights.push_back(MltInspect::weights(mlt));
        }
    }
    ASSERT_TRUE(ex.complete);
    // The first sum fixes the target; the second decides the tiles of
    // --strata piles (MpiStrata.PileTilesAgreeOverRanks).
    ASSERT_EQ(ex.inputs.size(), 2u) << "one sum over ranks fixes the target";
    // The parts summed (TargetBuffer::fix): per pixel and channel the MLT
    // part's sums, then per pixel its squares, its light behind glass and
    // its samples.
    std::vector<double> sums = ex.inputs[0][0];
    for (std::size_t k = 0; k < sums.size(); ++k)
        sums[k] += ex.inputs[0][1][k];
    ASSERT_EQ(sums.size(), 6u * w * h);
    double samples = 0;
    for (std::size_t p = 0; p < w * h; ++p)
        samples += sums[5 * w * h + p];
    ASSERT_EQ(samples, 2.0 * opt.threads * opt.burn_in_iters / 2) << "samples that fix it";
    TargetCells cells = target_cells(w, h, std::uint64_t(samples));
    ASSERT_EQ(target_cell_count(cells, h), 4u);
    sums.resize(3 * w * h);
    std::vector<float> expected = target_weights(cells, w, h, sums);
    expected.resize(weights[0].size(), 1.0f);
    std::printf("weights of the 4 cells: %.3f %.3f %.3f %.3f\n", expected[0], expected[1],
                expected[2], expected[3]);
    for (int r = 0; r < 2; ++r)
        EXPECT_EQ(weights[std::size_t(r)], expected) << "rank " << r;
}

// --strata piles on 2 ranks rebuilt here, tiny-caustic at 64x64: rank 0 at
// seed 4, whose burn-in piles the chains on one path, rank 1 at seed 3,
// whose does not. With 4,096 threads on each rank both keep auto's 16
// tiles (one rank's pile is enough); where rank 1's threads give it other
// tiles (1,024 threads: 4; 256: one) both keep one tile, since their
// per-tile sums could not be added. Either way the ranks make the same
// collectives, each with inputs of one length.
TEST(MpiStrata, PileTilesAgreeOverRanks) {
    DeviceScene ds = prepare_scene(test::scene("tiny-caustic", 64, 64));
    for (std::uint32_t other : {4096u, 1024u, 256u}) {
        Exchange ex(2);
        std::vector<std::uint32_t> tiles;
        for (int pass = 0; pass < 4; ++pass) {
            ex.complete = true;
            tiles.clear();
            for (int r = 0; r < 2; ++r) {
                ReplayRank me(r, ex);
                MltOptions o;
                o.threads = r == 0 ? 4096 : other;
                o.burn_in_iters = 16;
                o.seed = r == 0 ? 4 : 3;
                MltRenderer mlt(test::cl(), ds, o);
                mlt.sample_starts(me);
                tiles.push_back(mlt.strata_grid().count());
            }
            if (ex.complete) break;
        }
        ASSERT_TRUE(ex.complete) << other;
        for (std::size_t call = 0; call < ex.inputs.size(); ++call)
            EXPECT_EQ(ex.inputs[call][0].size(), ex.inputs[call][1].size())
                << "call " << call << ", " << other << " threads";
        EXPECT_EQ(tiles[0], other == 4096 ? 16u : 1u) << other << " threads";
        EXPECT_EQ(tiles[1], tiles[0]) << other << " threads";
    }
}

// Kelemen's weights of 2 ranks rebuilt here: both weigh with one b0, that
// of the union of their burn-ins (the image scales the large steps' layer,
// summed over ranks, by rank 0's b0, which must then be every rank's).
TEST(MpiRender, KelemenRanksWeighWithOneB0) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 16, 16));
    MltOptions opt;
    opt.threads = 256;
    opt.burn_in_iters = 2; // few samples: the ranks' own b differ
    opt.omc_cells = false; // cornell's one cell would go to the OMC part whole: no b0
    opt.restart = kRestartAuto;
    Exchange ex(2);
    std::vector<float> pb;
    std::uint64_t lum = 0, samples = 0;
    for (int pass = 0; pass < 6; ++pass) { // a pass more than the calls a rank makes
        ex.complete = true;
        pb.clear();
        lum = samples = 0;
        for (int r = 0; r < 2; ++r) {
            ReplayRank me(r, ex);
            opt.seed = rank_seed(5, r);
            MltRenderer mlt(test::cl(), ds, opt);
            mlt.prepare(me);
            pb.push_back(mlt.report().kelemen_pb);
            MltTally t = mlt.mlt_tally();
            lum += t.burn_in_lum.at(0);
            samples += t.burn_in_samples;
        }
        if (ex.complete) break;
    }
    ASSERT_TRUE(ex.complete);
    // With --restart auto, 256 chains on 256 pixels restart every
    // kRestartAutoSteps steps from 2 rounds: c is p (a restarting render's)
    // and 2 / kRestartAutoSteps restart samples per mutation; the weights
    // take M c b0, M a restarting render's mutations per sample.
    MltOptions restarting = opt;
    restarting.restart = kRestartAutoSteps;
    const double c =
        double(large_step_of(restarting)) + double(opt.burn_in_iters) / kRestartAutoSteps;
    const float want = float(c * mlt_b(lum, samples) * mutations_per_sample_of(restarting));
    std::printf("M c b0: rank 0 %.6g, rank 1 %.6g, of the union %.6g\n", pb[0], pb[1], want);
    EXPECT_GT(want, 0.0f);
    EXPECT_EQ(pb[0], want);
    EXPECT_EQ(pb[1], want);
}

// One rank renders what smallmlt does, bit for bit.
TEST(MpiRender, OneRankIsSmallmlt) {
    std::string dir = test::scratch_dir("mpi1");
    const std::string args = "scenes/cornell.scene --width 16 --height 16 --threads 256 --spp 4 "
                             "--burn-in-iters 4 --seed 4";
    Image job = run_job({args}, dir + "/np1.pfm");
    std::string cmd = smallmlt_bin() + " render " + args + " --quiet --out " + dir + "/one.pfm";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(job.rgb, read_image(dir + "/one.pfm").rgb);
}

// PT's ranks render every sample of one process once, with either sampler:
// the 3-rank image is the single process's within the float rounding of
// its per-pixel sums.
TEST(MpiRender, PtRanksRenderEverySampleOnce) {
    std::string dir = test::scratch_dir("mpi-pt");
    for (const char* sampler : {"sobol", "random"}) {
        const std::string args = "scenes/cornell-water.scene --method pt --width 24 --height 24 "
                                 "--spp 7 --sampler " +
                                 std::string(sampler);
        Image job = run_job(std::vector<std::string>(3, args), dir + "/np3.pfm");
        std::string cmd = smallmlt_bin() + " render " + args + " --quiet --out " + dir + "/one.pfm";
        ASSERT_EQ(std::system(cmd.c_str()), 0);
        Image one = read_image(dir + "/one.pfm");
        double worst = 0;
        for (std::size_t i = 0; i < one.rgb.size(); ++i)
            worst = std::max(worst, std::fabs(double(job.rgb[i]) - one.rgb[i]) /
                                        std::max(1e-3, double(one.rgb[i])));
        std::printf("%s: largest relative difference to one process: %.3g\n", sampler, worst);
        EXPECT_LT(worst, 1e-5) << sampler;
    }
}

// Keys: rank 0 keeps the seed, every rank's is its own; work is shared to
// within one unit and adds up.
TEST(MpiRender, RanksHaveTheirOwnKeysAndShares) {
    std::vector<std::uint64_t> seeds;
    for (int r = 0; r < 64; ++r)
        seeds.push_back(rank_seed(77, r));
    EXPECT_EQ(seeds[0], 77u);
    std::sort(seeds.begin(), seeds.end());
    EXPECT_EQ(std::unique(seeds.begin(), seeds.end()), seeds.end());
    for (std::uint64_t total : {0ull, 1ull, 7ull, 1000003ull})
        for (int n : {1, 2, 3, 64}) {
            std::uint64_t sum = 0;
            for (int r = 0; r < n; ++r) {
                sum += rank_share(total, r, n);
                EXPECT_LE(rank_share(total, r, n), total / n + 1);
                EXPECT_GE(rank_share(total, r, n), total / n);
            }
            EXPECT_EQ(sum, total);
        }
}
