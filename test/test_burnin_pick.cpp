// Burn-in by OMC: the chains' starting picks (BurnInPicker, cl/mlt/burnin.cl)
// are proportional to luminance, exactly and in frequency, pooled over rounds
// by the weighted reservoir, and uniform while no round has light.
#include "device/scan.hpp"
#include "render/mlt.hpp"
#include "stats.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

using namespace smallmlt;

namespace {

// The burn-in's program: rng, the 64-bit scan and the picks.
cl_program build_burnin() {
    const ClContext& cl = test::cl();
    return cl.build(
        {"cl/core/shared_types.h", "cl/core/rng.h", "cl/core/scan.cl", "cl/mlt/burnin.cl"},
        scan_defines(cl.device()));
}

// Picks `count` indices from luminances w as the burn-in's first round does
// (BurnInPicker: fixed-point weights, scan, binary search; the first round
// replaces every pick); *scan_out receives the scan.
std::vector<cl_uint> pick(const std::vector<float>& w, std::uint32_t count,
                          std::vector<cl_ulong>* scan_out = nullptr) {
    const ClContext& cl = test::cl();
    ClProgram prog(build_burnin());
    BurnInPicker picker(cl, prog.p, std::uint32_t(w.size()));
    ClBuffer lum(cl, CL_MEM_READ_ONLY, w.size() * sizeof(float), w.data());
    ClBuffer scan(cl, CL_MEM_READ_WRITE, w.size() * sizeof(cl_ulong));
    std::vector<cl_uint2> none(count, cl_uint2{{~0u, ~0u}});
    ClBuffer picks(cl, CL_MEM_READ_WRITE, count * sizeof(cl_uint2), none.data());
    picker.add_round(lum, w, std::uint32_t(w.size()), scan, 12345, 0, count, picks);
    std::vector<cl_uint2> got(count);
    picks.read(cl, got.data());
    std::vector<cl_uint> out(count);
    for (std::uint32_t j = 0; j < count; ++j) {
        EXPECT_EQ(got[j].s[0], 0u) << "pick " << j << " not of round 0";
        out[j] = got[j].s[1];
    }
    if (scan_out) {
        scan_out->resize(w.size());
        scan.read(cl, scan_out->data());
    }
    return out;
}

// Chi-square of pick counts against weights, over consecutive indices pooled
// until each pool expects at least 5 picks; zero weights must get nothing.
void check_proportional(const std::vector<float>& w, std::uint32_t count) {
    std::vector<cl_uint> picks = pick(w, count);
    std::vector<double> n(w.size(), 0.0);
    for (cl_uint i : picks) {
        ASSERT_LT(i, w.size());
        n[i] += 1;
    }
    double total = 0;
    for (float x : w)
        total += x;
    double chi2 = 0, pool_e = 0, pool_n = 0;
    int pools = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (w[i] == 0) {
            EXPECT_EQ(n[i], 0) << "zero-weight sample " << i << " picked";
            continue;
        }
        pool_e += count * w[i] / total;
        pool_n += n[i];
        if (pool_e >= 5 || i + 1 == w.size()) {
            chi2 += (pool_n - pool_e) * (pool_n - pool_e) / pool_e;
            ++pools;
            pool_e = pool_n = 0;
        }
    }
    ASSERT_GE(pools, 2);
    EXPECT_LT(chi2, test::chi2_critical_001(pools - 1)) << pools << " pools";
}

} // namespace

TEST(BurnInPick, ProportionalToLuminance) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> mixed(1000);
    for (float& x : mixed)
        x = u(rng) < 0.3f ? 0.0f : u(rng) * u(rng) * 10;
    check_proportional(mixed, 200000);
}

TEST(BurnInPick, AllEqual) {
    check_proportional(std::vector<float>(777, 0.25f), 100000);
}

TEST(BurnInPick, OneHugeValue) {
    std::vector<float> w(1000, 1.0f);
    for (std::size_t i = 0; i < w.size(); i += 7)
        w[i] = 0.0f;
    w[500] = 1e5f;
    check_proportional(w, 100000);
}

TEST(BurnInPick, OnlyZerosPicksUniformly) {
    std::vector<cl_uint> picks = pick(std::vector<float>(100, 0.0f), 20000);
    std::vector<int> n(100, 0);
    for (cl_uint i : picks)
        ++n[i];
    double chi2 = 0;
    for (int c : n)
        chi2 += (c - 200.0) * (c - 200.0) / 200.0;
    EXPECT_LT(chi2, test::chi2_critical_001(99));
}

namespace {

// 2^20 luminances of very different sizes, ~5.6e5 in all: 8 huge ones
// (2^16), 2^19 - 8 pairs of a small one and its complement (2^-6 and
// 3 x 2^-6, the small ones carrying 1.5% of the light), pairs of zeros and of
// 5e-7 (1e-6 of the mean), and 2^16 log-uniform ones in [1e-4, 4]. In a
// float32 prefix sum around 5e5 (spacing 2^-4), each small one falls below
// half a spacing and is rounded away.
std::vector<float> million_samples() {
    const std::uint32_t n = 1u << 20;
    std::vector<float> w(n);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(std::log(1e-4), std::log(4.0));
    for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t pair = i / 2;
        if (i % (1u << 17) == 0)
            w[i] = 65536.0f;
        else if (i >= n - (1u << 16))
            w[i] = float(std::exp(u(rng)));
        else if (pair % 89 == 0)
            w[i] = 0.0f;
        else if (pair % 97 == 0)
            w[i] = 5e-7f;
        else
            w[i] = i % 2 ? 3.0f / 64 : 1.0f / 64;
    }
    return w;
}

} // namespace

// Every sample's exact pick probability, from the weights' scan: u =
// floor(r T / 2^64) for uniform 64-bit r (cl/mlt/burnin.cl), so sample i gets
// ceil(S_i 2^64 / T) - ceil(S_(i-1) 2^64 / T) of the 2^64 values of r. It is
// its share of the luminance within a relative 1e-6 for every positive
// sample (the smallest are 1e-12 of the total), and 0 for every zero one.
TEST(BurnInPick, ExactProbabilitiesOfAMillionSamplesOfVeryDifferentSizes) {
    std::vector<float> w = million_samples();
    std::vector<cl_ulong> scan;
    pick(w, 1, &scan);
    long double total_lum = 0;
    for (float x : w)
        total_lum += x;
    const unsigned __int128 total = scan.back();
    auto first_r = [&](cl_ulong s) {
        return ((unsigned __int128)s << 64) / total + (((unsigned __int128)s << 64) % total != 0);
    };
    double worst = 0;
    std::size_t off = 0;
    unsigned __int128 prev = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        unsigned __int128 next = first_r(scan[i]);
        long double p = (long double)(next - prev) / 18446744073709551616.0L;
        prev = next;
        if (w[i] == 0) {
            EXPECT_EQ(p, 0.0L) << "zero-luminance sample " << i;
            continue;
        }
        double rel = double(std::fabs(p / (w[i] / total_lum) - 1));
        worst = std::max(worst, rel);
        off += rel > 1e-6;
    }
    std::printf("largest relative error of a pick probability: %.3g (%zu samples above 1e-6)\n",
                worst, off);
    EXPECT_EQ(off, 0u);
}

// Pick frequencies of 2^20 picks from the same samples (fixed seed), by
// luminance binade (the huge ones, the small 2^-6 ones, their complements,
// the log-uniform ones, adjacent binades pooled until each expects 5 picks):
// chi-square at significance 0.001; zero-luminance samples never picked.
TEST(BurnInPick, MillionSamplesFollowTheirLuminanceByBinade) {
    std::vector<float> w = million_samples();
    const std::uint32_t count = 1u << 20;
    std::vector<cl_uint> picks = pick(w, count);
    std::map<int, double> expected, seen;
    double total = 0;
    for (float x : w)
        total += x;
    auto binade = [](float x) {
        int e;
        std::frexp(x, &e);
        return e;
    };
    for (float x : w)
        if (x > 0) expected[binade(x)] += count * x / total;
    for (cl_uint i : picks) {
        ASSERT_LT(i, w.size());
        ASSERT_GT(w[i], 0.0f) << "zero-luminance sample " << i << " picked";
        seen[binade(w[i])] += 1;
    }
    double chi2 = 0, pool_e = 0, pool_n = 0, small_e = 0, small_n = 0;
    int pools = 0;
    for (auto it = expected.begin(); it != expected.end(); ++it) {
        pool_e += it->second;
        pool_n += seen[it->first];
        if (it->first == binade(1.0f / 64)) small_e = it->second, small_n = seen[it->first];
        if (pool_e >= 5 || std::next(it) == expected.end()) {
            chi2 += (pool_n - pool_e) * (pool_n - pool_e) / pool_e;
            ++pools;
            pool_e = pool_n = 0;
        }
    }
    std::printf("chi-square %.4g over %d pools (critical %.4g); the 2^-6 samples: %.0f picks, "
                "%.0f expected\n",
                chi2, pools, test::chi2_critical_001(pools - 1), small_n, small_e);
    ASSERT_GE(pools, 2);
    EXPECT_LT(chi2, test::chi2_critical_001(pools - 1));
}

namespace {

// Runs the reservoir over `rounds` (the luminances of each, all of one size
// n) for `count` chains; returns each chain's pick (round, index).
std::vector<cl_uint2> reservoir(const std::vector<std::vector<float>>& rounds, std::uint32_t count,
                                std::uint64_t seed) {
    const ClContext& cl = test::cl();
    ClProgram prog(build_burnin());
    std::uint32_t n = std::uint32_t(rounds[0].size());
    BurnInPicker picker(cl, prog.p, n);
    ClBuffer lum(cl, CL_MEM_READ_WRITE, n * sizeof(float));
    ClBuffer scan(cl, CL_MEM_READ_WRITE, n * sizeof(cl_ulong));
    std::vector<cl_uint2> none(count, cl_uint2{{~0u, ~0u}});
    ClBuffer picks(cl, CL_MEM_READ_WRITE, count * sizeof(cl_uint2), none.data());
    for (std::uint32_t r = 0; r < rounds.size(); ++r) {
        lum.write(cl, rounds[r].data());
        picker.add_round(lum, rounds[r], n, scan, seed, r, count, picks);
    }
    std::vector<cl_uint2> out(count);
    picks.read(cl, out.data());
    return out;
}

} // namespace

// The starts are pooled over rounds: with 8 rounds of 1000 samples whose
// luminance sums differ by up to 10^4 (the first round dark, another dark
// one later, one round a single bright sample), 2^18 chains start in round r
// with frequency s_r / sum s and at sample i of it in proportion to its
// luminance. Chi-square at significance 0.001 (fixed seed) over the rounds,
// and over all samples pooled until each pool expects 5 picks; samples
// without light are never picked. Per-round picks (each round keeping 1/8 of
// the chains) give the rounds equal shares and fail the first check.
TEST(BurnInPick, ReservoirPoolsTheRoundsInProportionToLuminance) {
    const std::uint32_t n = 1000, count = 1u << 18;
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<std::vector<float>> rounds(8, std::vector<float>(n, 0.0f));
    for (std::uint32_t i = 0; i < n; i += 100)
        rounds[1][i] = 0.1f; // s = 1
    for (float& x : rounds[3])
        x = u(rng) < 0.5f ? 0.0f : u(rng) * 1.2f; // s ~ 300
    for (float& x : rounds[4])
        x = u(rng) * u(rng) * 0.12f; // s ~ 30
    rounds[5][777] = 50.0f;
    for (float& x : rounds[7])
        x = u(rng) < 0.01f ? u(rng) * 0.6f : 0.0f; // s ~ 3
    std::vector<cl_uint2> picks = reservoir(rounds, count, 99);

    double total = 0;
    std::vector<double> s(rounds.size(), 0.0), seen_round(rounds.size(), 0.0);
    for (std::size_t r = 0; r < rounds.size(); ++r) {
        for (float x : rounds[r])
            s[r] += x;
        total += s[r];
    }
    std::vector<std::vector<double>> seen(rounds.size(), std::vector<double>(n, 0.0));
    for (const cl_uint2& p : picks) {
        ASSERT_LT(p.s[0], rounds.size());
        ASSERT_LT(p.s[1], n);
        ASSERT_GT(rounds[p.s[0]][p.s[1]], 0.0f)
            << "unlit sample " << p.s[1] << " of round " << p.s[0] << " picked";
        seen[p.s[0]][p.s[1]] += 1;
        seen_round[p.s[0]] += 1;
    }
    double chi2 = 0;
    int lit = 0;
    for (std::size_t r = 0; r < rounds.size(); ++r) {
        double e = count * s[r] / total;
        std::printf("round %zu: s %.4g, %.0f starts, %.1f expected\n", r, s[r], seen_round[r], e);
        if (s[r] == 0) {
            EXPECT_EQ(seen_round[r], 0) << "round " << r << " without light";
            continue;
        }
        chi2 += (seen_round[r] - e) * (seen_round[r] - e) / e;
        ++lit;
    }
    std::printf("rounds: chi-square %.4g over %d (critical %.4g)\n", chi2, lit,
                test::chi2_critical_001(lit - 1));
    EXPECT_LT(chi2, test::chi2_critical_001(lit - 1));

    double chi2s = 0, pool_e = 0, pool_n = 0;
    int pools = 0;
    for (std::size_t r = 0; r < rounds.size(); ++r)
        for (std::uint32_t i = 0; i < n; ++i) {
            if (rounds[r][i] == 0) continue;
            pool_e += count * rounds[r][i] / total;
            pool_n += seen[r][i];
            if (pool_e >= 5) {
                chi2s += (pool_n - pool_e) * (pool_n - pool_e) / pool_e;
                ++pools;
                pool_e = pool_n = 0;
            }
        }
    if (pool_e > 0) chi2s += (pool_n - pool_e) * (pool_n - pool_e) / pool_e, ++pools;
    std::printf("samples: chi-square %.4g over %d pools (critical %.4g)\n", chi2s, pools,
                test::chi2_critical_001(pools - 1));
    EXPECT_LT(chi2s, test::chi2_critical_001(pools - 1));
}

// While no round has light, the reservoir keeps picks uniform over all the
// samples so far: 5 dark rounds of 100, 50,000 chains, chi-square over the
// 500 samples at significance 0.001.
TEST(BurnInPick, DarkRoundsPickUniformlyOverAllRounds) {
    const std::uint32_t n = 100, count = 50000;
    std::vector<std::vector<float>> rounds(5, std::vector<float>(n, 0.0f));
    std::vector<cl_uint2> picks = reservoir(rounds, count, 7);
    std::vector<double> seen(rounds.size() * n, 0.0);
    for (const cl_uint2& p : picks) {
        ASSERT_LT(p.s[0], rounds.size());
        ASSERT_LT(p.s[1], n);
        seen[p.s[0] * n + p.s[1]] += 1;
    }
    double e = double(count) / seen.size(), chi2 = 0;
    for (double c : seen)
        chi2 += (c - e) * (c - e) / e;
    EXPECT_LT(chi2, test::chi2_critical_001(int(seen.size()) - 1));
}

TEST(BurnInPick, ReplaceThresholds) {
    const std::uint64_t one = 1ull << 32;
    EXPECT_EQ(burnin_replace_threshold(0, 0, 0), one);
    EXPECT_EQ(burnin_replace_threshold(0, 0, 1), one / 2);
    EXPECT_EQ(burnin_replace_threshold(0, 0, 3), one / 4);
    EXPECT_EQ(burnin_replace_threshold(2.5, 2.5, 7), one); // the first round with light
    EXPECT_EQ(burnin_replace_threshold(1, 4, 7), one / 4);
    EXPECT_EQ(burnin_replace_threshold(0, 4, 7), 0u);
}

TEST(BurnInPick, WeightExponentKeepsTheTotalBelow2To62) {
    for (double sum : {1e-40, 1e-6, 0.75, 1.0, 5.6e5, 3e38, 1e45}) {
        int e = burnin_weight_exponent(sum);
        EXPECT_LT(std::ldexp(sum, e), std::ldexp(1.0, 62)) << sum;
        EXPECT_GE(std::ldexp(sum, e), std::ldexp(1.0, 61)) << sum;
    }
    EXPECT_EQ(burnin_weight_exponent(0.0), 0);
    EXPECT_EQ(burnin_weight_exponent(INFINITY), 0);
}

// OMC sample keys are distinct across every round and thread the command
// line allows (--threads up to 2^26, --burn-in-iters up to 2^16, plus the
// round of fresh starts): a 32-bit sample number round x threads + index
// repeats once it passes 2^32 (round 64 at 2^26 threads).
