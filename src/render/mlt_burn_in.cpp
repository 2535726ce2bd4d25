#include "render/mlt_burn_in.hpp"

#include "fixed_point.h"
#include "render/mlt_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace smallmlt {

double mlt_b(std::uint64_t lum_fixed, std::uint64_t samples) {
    return samples ? double(lum_fixed) / double(1u << MLT_B_FRAC_BITS) / double(samples) : 0;
}

BEstimate BurnInSums::b(std::uint64_t large_lum, std::uint64_t large) const {
    BEstimate e;
    e.b = mlt_b(lum_fixed + large_lum, samples + large);
    double n = double(samples) + double(large);
    e.rel_error = e.b > 0 ? std::sqrt(variance / n) / e.b : 0;
    return e;
}

double MltBurnIn::ranks_b(RankGroup& ranks) const {
    // Whole numbers, summed exactly in double below 2^53.
    std::vector<double> sums{double(sums_.lum_fixed), double(sums_.samples)};
    ranks.sum_all(sums);
    return mlt_b(std::uint64_t(sums[0]), std::uint64_t(sums[1]));
}

MltBurnIn::MltBurnIn(const ClContext& cl, cl_program program, const MltOptions& opt,
                     std::uint64_t pixels)
    : cl_(cl), program_(program), opt_(opt), k_lum_(program, "mlt_luminance") {
    if (opt.split != Split::None || opt.target == Target::TwoStage) parts_ = BurnInParts(pixels);
}

void MltBurnIn::run(RankGroup& ranks, const MemoryPlan& plan, const SceneBuffers& scene,
                    TargetBuffer& target, const BurnInFilm& film, const Chains& chains) {
    const std::uint32_t m = opt_.threads, iters = std::max(1u, opt_.burn_in_iters);
    const bool parts = keeps_parts();
    // Rounds before `first` only measure the two-stage target's weights.
    const std::uint32_t first = opt_.target == Target::TwoStage ? iters / 2 : 0;
    ClBuffer lum(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::Luminance));
    ClBuffer scan(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::Scan));
    ClBuffer omc =
        parts ? ClBuffer(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::OmcSamples)) : ClBuffer();
    BurnInPicker picker(cl_, program_, m);
    std::vector<float> host(m), host_omc(parts ? 8 * m : 0);
    BurnInSums s;
    const std::uint64_t omc_seed = mlt_seed(opt_.seed, MltStream::Omc);
    const std::uint64_t pick_seed = mlt_seed(opt_.seed, MltStream::Pick);
    for (std::uint32_t it = 0; it < iters; ++it) {
        if (it == first && first > 0)
            target.fix(ranks, scene.frame.width, scene.frame.height, parts_.rest,
                       std::accumulate(parts_.count.begin(), parts_.count.end(), std::uint64_t(0)));
        k_lum_.set_args(scene, target, film, chains.state, cl_ulong(omc_round_seed(omc_seed, it)),
                        cl_uint(it), cl_uint(m), lum, parts ? omc : lum, chains.stats);
        k_lum_.run(cl_, m);
        lum.read(cl_, host.data());
        if (parts) {
            omc.read(cl_, host_omc.data());
            parts_.add(host_omc);
        }
        if (it < first) continue;
        for (float y : host) {
            s.lum_fixed += fixed_b_sample(y);
            s.lum2 += double(y) * y;
        }
        if (opt_.burn_in)
            picker.add_round(lum, host, m, scan, pick_seed, it, chains.count, chains.picks);
    }
    if (!opt_.burn_in) {
        // Fresh samples: round iters, after those that estimated b.
        std::vector<cl_uint2> fresh(chains.count);
        for (std::uint32_t c = 0; c < chains.count; ++c)
            fresh[c] = cl_uint2{{iters, c}};
        chains.picks.write(cl_, fresh.data());
    }
    s.samples = std::uint64_t(m) * (iters - first);
    const double n = double(s.samples), mean = mlt_b(s.lum_fixed, s.samples);
    s.variance = n > 1 ? std::max(0.0, (s.lum2 / n - mean * mean) * n / (n - 1)) : 0;
    sums_ = s;
    if (parts) {
        mlt_part_b_ = parts_.mean(parts_.rest);
        omc_variance_ = parts_.variance(parts_.omc, parts_.omc_y2);
        mlt_variance_ = parts_.variance(parts_.rest, parts_.rest_y2);
    }
}

} // namespace smallmlt
