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
#include <memory>

using namespace smallmlt;

namespace {

// Rank `rank` of `size`, for building a rank's method; its collectives are
// never called here.
class FakeRank : public RankGroup {
  public:
    FakeRank(int rank, int size) : rank_(rank), size_(size) {}
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    int local_rank() const override { return rank_; }
    std::string host() const override { return "test"; }
    bool any(bool mine) override { return mine; }
    bool all(bool mine) override { return mine; }
    void sum_to_root(std::vector<std::uint64_t>&) override {}
    void sum_to_root(std::vector<double>&) override {}
    void sum_all(std::vector<double>&) override {}
    std::vector<std::string> gather(const std::string& mine) override { return {mine}; }

  private:
    int rank_, size_;
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

// The image of `ranks` ranks rebuilt here, and b of the union of their
// samples (MLT only; 0 for PT).
struct Rebuilt {
    Image image;
    double b_union = 0;
};

Rebuilt rebuild(const std::string& args, int ranks) {
    RenderOptions o = parse_render(args + " --quiet");
    Scene scene = load_scene(o.scene);
    scene.width = *o.width;
    scene.height = *o.height;
    DeviceScene ds = prepare_scene(scene);
    Tally sum;
    std::unique_ptr<Integrator> first;
    double b_sum = 0, b_n = 0;
    for (int r = 0; r < ranks; ++r) {
        FakeRank me(r, ranks);
        std::unique_ptr<Integrator> m = make_integrator(o, test::cl(), ds, me);
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
    Rebuilt out;
    out.image = first->image_from(sum);
    out.b_union = b_n > 0 ? b_sum / b_n : 0;
    return out;
}

Image run_job(const std::string& args, int ranks, const std::string& out) {
    std::string cmd = std::string(kMpirun) + std::to_string(ranks) + " " + mpi_bin() + " render " +
                      args + " --quiet --out " + out + " < /dev/null > " + out + ".log 2>&1";
    int rc = std::system(cmd.c_str());
    EXPECT_EQ(rc, 0) << cmd;
    return read_image(out);
}

} // namespace

// MLT on 2 and 3 ranks (chains of each rank's seed, the work shared
// evenly), and PT on 3 (rank r renders samples r, r + 3, ...).
TEST(MpiRender, RanksGiveTheImageOfTheirKeys) {
    std::string dir = test::scratch_dir("mpi");
    struct Case {
        std::string args;
        int ranks;
        bool mean_is_b; // no split: the image's mean is b
    };
    const std::string mlt = "scenes/cornell.scene --width 24 --height 24 --threads 256 --spp 6 "
                            "--burn-in-iters 4 --seed 9";
    const std::string pt = "scenes/cornell-water.scene --method pt --width 24 --height 24 --spp 7";
    // The split's OMC part and the burn-in's sums go into the tallies too.
    for (const Case& c : {Case{mlt + " --split none --weights expected", 2, true},
                          Case{mlt + " --split direct", 3, false}, Case{pt, 3, false}}) {
        std::string out = dir + "/np" + std::to_string(c.ranks) + ".pfm";
        Image job = run_job(c.args, c.ranks, out);
        Rebuilt here = rebuild(c.args, c.ranks);
        EXPECT_EQ(job.rgb, here.image.rgb) << c.args << " on " << c.ranks << " ranks";
        if (c.mean_is_b) {
            // The image's mean is b of the summed samples: the union's.
            std::printf("%d ranks: image mean %.7f, b of the union %.7f\n", c.ranks,
                        job.mean_luminance(), here.b_union);
            EXPECT_NEAR(job.mean_luminance(), here.b_union, 1e-3 * here.b_union);
        }
    }
}

// One rank renders what smallmlt does, bit for bit.
TEST(MpiRender, OneRankIsSmallmlt) {
    std::string dir = test::scratch_dir("mpi1");
    const std::string args = "scenes/cornell.scene --width 16 --height 16 --threads 256 --spp 4 "
                             "--burn-in-iters 4 --seed 4";
    Image job = run_job(args, 1, dir + "/np1.pfm");
    std::string cmd = smallmlt_bin() + " render " + args + " --quiet --out " + dir + "/one.pfm";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(job.rgb, read_image(dir + "/one.pfm").rgb);
}

// PT's ranks render every sample of one process once: the 3-rank image is
// the single process's within the float rounding of its per-pixel sums.
TEST(MpiRender, PtRanksRenderEverySampleOnce) {
    std::string dir = test::scratch_dir("mpi-pt");
    const std::string args =
        "scenes/cornell-water.scene --method pt --width 24 --height 24 --spp 7";
    Image job = run_job(args, 3, dir + "/np3.pfm");
    std::string cmd = smallmlt_bin() + " render " + args + " --quiet --out " + dir + "/one.pfm";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    Image one = read_image(dir + "/one.pfm");
    double worst = 0;
    for (std::size_t i = 0; i < one.rgb.size(); ++i)
        worst = std::max(worst, std::fabs(double(job.rgb[i]) - one.rgb[i]) /
                                    std::max(1e-3, double(one.rgb[i])));
    std::printf("largest relative difference to one process: %.3g\n", worst);
    EXPECT_LT(worst, 1e-5);
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
