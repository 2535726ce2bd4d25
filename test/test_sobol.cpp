// The path tracer's low-discrepancy sample source (cl/sampling/sobol.cl,
// cl/sampling/sample_sobol.cl): every pair of numbers is a (0,m,2)-net in each aligned block of 2^m
// samples (exact checks), every number is stratified on its own, different
// pairs and pixels are independent (chi-square at 1e-3 per test), and the
// image it gives is PT's image per pixel block (Welch, Holm at 0.01).
#include "render/programs.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace smallmlt;

namespace {

constexpr std::uint32_t kFilm = ~0u; // "bounce" of the film pair

class SobolProbe {
  public:
    explicit SobolProbe(const DeviceScene& ds)
        : program_(test::cl().build(program_files({Program::PathTracer,
                                                   "cl/sampling/sample_sobol.cl",
                                                   "",
                                                   {"test/cl/probe_sobol.cl"}},
                                                  Stage::Sampling),
                                    ds.layout.defines())) {}

    // Slots `slot` and `slot` + 1 of `bounce` (or the film position) for
    // samples first .. first + n - 1 of `pixel`.
    std::vector<cl_float2> points(std::uint32_t pixel, std::uint32_t first, std::uint32_t n,
                                  std::uint32_t bounce, std::uint32_t slot = 0,
                                  std::uint64_t seed = 7) const {
        ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float2));
        ClKernel k(program_.p, "probe_sobol");
        k.set_args(cl_ulong(seed), cl_uint(pixel), cl_uint(first), cl_uint(n), cl_uint(bounce),
                   cl_uint(slot), out);
        k.run(test::cl(), n);
        std::vector<cl_float2> v(n);
        out.read(test::cl(), v.data());
        return v;
    }

  private:
    ClProgram program_;
};

// cornell at depth 8: BSDF (0, 1), light sample (2, 3), light pick and
// roulette (4, 5) in every bounce.
const DeviceScene& cornell() {
    static DeviceScene ds = prepare_scene(test::scene("cornell", 32, 32, 8));
    return ds;
}

// Empty if the 2^m points form a (0,m,2)-net: for every a = 0..m, each
// box [i/2^a, (i+1)/2^a) x [j/2^(m-a), (j+1)/2^(m-a)) holds one point.
std::string net_failure(const std::vector<cl_float2>& p, int m) {
    for (int a = 0; a <= m; ++a) {
        std::vector<int> count(std::size_t(1) << m, 0);
        for (const cl_float2& q : p) {
            auto i = std::size_t(std::ldexp(double(q.s[0]), a));
            auto j = std::size_t(std::ldexp(double(q.s[1]), m - a));
            ++count[(i << (m - a)) | j];
        }
        for (std::size_t b = 0; b < count.size(); ++b)
            if (count[b] != 1)
                return "box " + std::to_string(b) + " of 2^-" + std::to_string(a) + " x 2^-" +
                       std::to_string(m - a) + " holds " + std::to_string(count[b]) + " points";
    }
    return "";
}

// Pearson's statistic of independence of the two coordinates' 16 x 16
// contingency table (n points, margins from the data).
double independence_chi2(const std::vector<float>& x, const std::vector<float>& y) {
    const int k = 16;
    std::vector<double> cell(k * k, 0), row(k, 0), col(k, 0);
    for (std::size_t i = 0; i < x.size(); ++i) {
        int a = int(x[i] * k), b = int(y[i] * k);
        ++cell[a * k + b], ++row[a], ++col[b];
    }
    double n = double(x.size()), t = 0;
    for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b) {
            double e = row[a] * col[b] / n;
            t += (cell[a * k + b] - e) * (cell[a * k + b] - e) / e;
        }
    return t;
}

std::vector<float> coordinate(const std::vector<cl_float2>& p, int c) {
    std::vector<float> v;
    for (const cl_float2& q : p)
        v.push_back(q.s[c]);
    return v;
}

} // namespace

TEST(SobolSampler, EveryPairIsANetInEveryAlignedBlock) {
    const DeviceScene& ds = cornell();
    ASSERT_EQ(ds.layout.bounce_dims, 6);
    SobolProbe probe(ds);
    const std::uint32_t last = std::uint32_t(ds.layout.depth - 1);
    struct Pair {
        std::uint32_t bounce, slot;
    };
    // The film, the first bounce's pairs, and the last bounce's (a padded
    // high dimension: number 2 + 7 * 6 + 2 = 46 of the path).
    for (Pair pr :
         {Pair{kFilm, 0}, Pair{0, 0}, Pair{0, 2}, Pair{0, 4}, Pair{last, 0}, Pair{last, 2}})
        for (std::uint32_t pixel : {0u, 1u, 517u})
            for (int m : {1, 4, 8, 11})
                for (std::uint32_t block : {0u, 1u, 5u}) {
                    std::uint32_t n = 1u << m;
                    std::string why =
                        net_failure(probe.points(pixel, block * n, n, pr.bounce, pr.slot), m);
                    EXPECT_EQ(why, "") << "bounce " << int(pr.bounce) << " slots " << pr.slot << ","
                                       << pr.slot + 1 << ", pixel " << pixel << ", samples "
                                       << block * n << ".." << (block + 1) * n - 1;
                }
}

TEST(SobolSampler, EveryNumberIsStratified) {
    const DeviceScene& ds = cornell();
    SobolProbe probe(ds);
    const int m = 8;
    for (std::uint32_t bounce = 0; bounce < std::uint32_t(ds.layout.depth); ++bounce)
        for (std::uint32_t slot = 0; slot < 6; slot += 2) {
            std::vector<cl_float2> p = probe.points(3, 0, 1u << m, bounce, slot);
            for (int c = 0; c < 2; ++c) {
                std::vector<int> count(1u << m, 0);
                for (const cl_float2& q : p)
                    ++count[std::size_t(std::ldexp(double(q.s[c]), m))];
                for (std::size_t i = 0; i < count.size(); ++i)
                    ASSERT_EQ(count[i], 1) << "bounce " << bounce << " slot " << slot + c
                                           << ": interval " << i << " of 2^" << m;
            }
        }
}

// Padding: a pair's points must not predict another pair's, nor a pixel's
// another pixel's. Each case is a chi-square test of independence of two
// numbers over 4,096 samples (16 x 16 cells, 225 degrees of freedom) at
// significance 1e-3. Feeding every pair the same shuffle makes the film's x
// and the BSDF's u equal, and fails.
TEST(SobolSampler, PairsAndPixelsAreIndependent) {
    const DeviceScene& ds = cornell();
    SobolProbe probe(ds);
    const std::uint32_t n = 4096;
    auto film = probe.points(9, 0, n, kFilm), bsdf0 = probe.points(9, 0, n, 0, 0),
         light0 = probe.points(9, 0, n, 0, 2), bsdf1 = probe.points(9, 0, n, 1, 0),
         rr7 = probe.points(9, 0, n, 7, 4), film_next = probe.points(10, 0, n, kFilm);
    struct Case {
        const char* what;
        std::vector<float> x, y;
    };
    std::vector<Case> cases = {
        {"film x, bounce 0 BSDF u", coordinate(film, 0), coordinate(bsdf0, 0)},
        {"film y, bounce 0 BSDF v", coordinate(film, 1), coordinate(bsdf0, 1)},
        {"bounce 0 BSDF u, bounce 0 light u", coordinate(bsdf0, 0), coordinate(light0, 0)},
        {"bounce 0 BSDF v, bounce 1 BSDF v", coordinate(bsdf0, 1), coordinate(bsdf1, 1)},
        {"bounce 0 light v, bounce 7 roulette", coordinate(light0, 1), coordinate(rr7, 1)},
        {"film x of pixels 9 and 10", coordinate(film, 0), coordinate(film_next, 0)},
    };
    const double critical = test::chi2_critical_001(15 * 15);
    for (const Case& c : cases) {
        double t = independence_chi2(c.x, c.y);
        EXPECT_LT(t, critical) << c.what;
        std::printf("%-40s chi2 %.1f (critical %.1f)\n", c.what, t, critical);
    }
}

// With an odd number of slots a bounce (cornell-water: BSDF, light, pick,
// Fresnel, roulette: 7), a bounce's last number fills the first half of
// its last pair and the next bounce starts a new one: the two must not
// predict each other. Chi-square of independence as above (4,096 samples,
// 225 degrees of freedom) at 1e-3 each, for bounces 0 and 1 and 5 and 6,
// against the next bounce's u and v. Counting a bounce's pairs as
// LAYOUT_BOUNCE_DIMS / 2 makes the roulette number the next BSDF's u.
TEST(SobolSampler, ABouncesLastNumberIsIndependentOfTheNextsFirst) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 32, 32, 8));
    ASSERT_EQ(ds.layout.bounce_dims, 7);
    ASSERT_EQ(ds.layout.index[kRoulette], 6);
    SobolProbe probe(ds);
    const std::uint32_t n = 4096;
    const double critical = test::chi2_critical_001(15 * 15);
    for (std::uint32_t bounce : {0u, 5u}) {
        // Slots 5 and 6 (Fresnel, roulette), and the next bounce's 0 and 1.
        std::vector<float> last = coordinate(probe.points(9, 0, n, bounce, 5), 1);
        std::vector<cl_float2> next = probe.points(9, 0, n, bounce + 1, 0);
        for (int c = 0; c < 2; ++c) {
            double t = independence_chi2(last, coordinate(next, c));
            EXPECT_LT(t, critical)
                << "bounce " << bounce << " roulette, bounce " << bounce + 1 << " BSDF "
                << "uv"[c];
            std::printf("bounce %u roulette, bounce %u BSDF %c: chi2 %.1f (critical %.1f)\n",
                        bounce, bounce + 1, "uv"[c], t, critical);
        }
    }
}

TEST(SobolSampler, SameSeedSameImageWhateverThePassSplit) {
    const DeviceScene& ds = cornell();
    PathTracer a(test::cl(), ds, 5, PtSampler::Sobol), b(test::cl(), ds, 5, PtSampler::Sobol);
    a.add_samples(8);
    b.add_samples(3);
    b.add_samples(5);
    EXPECT_EQ(a.image().rgb, b.image().rgb);
    PathTracer other(test::cl(), ds, 6, PtSampler::Sobol);
    other.add_samples(8);
    EXPECT_NE(other.image().rgb, a.image().rgb);
}

// Unbiased: 16 Sobol renders (independent scrambles: one seed each) of 32
// spp against the random sampler's 1,024 spp in 32 batches, per 8 x 8 block
// of luminance sums, Welch's t with Holm at family-wise 0.01.
TEST(SobolSampler, ImageIsPathTracingsImagePerBlock) {
    for (const char* name : {"cornell", "cornell-water"}) {
        DeviceScene ds = prepare_scene(test::scene(name, 32, 32));
        test::Replicas sobol, random;
        for (std::uint64_t seed = 1; seed <= 16; ++seed)
            sobol.add(test::block_sums(test::render_pt(ds, 1000 + seed, 32, PtSampler::Sobol), 8));
        for (const Image& img : test::render_pt_batches(ds, 77, 1024, 32))
            random.add(test::block_sums(img, 8));
        test::BlockComparison c = test::welch_compare(sobol, random, 0.01);
        std::printf("%s: smallest Holm-adjusted p %.3g (block %zu, Sobol - random %+.2f%%)\n", name,
                    c.min_p_adjusted, c.worst, 100 * c.diff[c.worst] / random.mean(c.worst));
        EXPECT_FALSE(c.any_reject()) << name << ": block " << c.worst << " differs";
    }
}
