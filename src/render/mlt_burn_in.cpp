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

double mlt_tile_b(std::uint64_t burn_in_lum, std::uint64_t samples, double area,
                  std::uint64_t large_lum, std::uint64_t large) {
    const double n = double(samples) * area + double(large);
    return n > 0 ? double(burn_in_lum + large_lum) / double(1u << MLT_B_FRAC_BITS) / n : 0;
}

BEstimate BurnInSums::b(std::uint64_t large_lum, std::uint64_t large) const {
    BEstimate e;
    e.b = mlt_b(lum_fixed + large_lum, samples + large);
    double n = double(samples) + double(large);
    e.rel_error = e.b > 0 ? std::sqrt(variance / n) / e.b : 0;
    return e;
}

std::vector<double> MltBurnIn::ranks_b(RankGroup& ranks, const StrataGrid& grid) const {
    // Whole numbers, summed exactly in double below 2^53.
    std::vector<double> sums(sums_.tile_lum.begin(), sums_.tile_lum.end());
    sums.push_back(double(sums_.samples));
    ranks.sum_all(sums);
    const std::uint64_t pixels = grid.pixel_tile.size();
    std::vector<double> b(grid.count());
    for (std::uint32_t t = 0; t < grid.count(); ++t)
        b[t] = mlt_tile_b(std::uint64_t(sums[t]), std::uint64_t(sums.back()), grid.area(t, pixels),
                          0, 0);
    return b;
}

MltBurnIn::MltBurnIn(const ClContext& cl, cl_program program, const MltOptions& opt,
                     std::uint64_t pixels)
    : cl_(cl), program_(program), opt_(opt), k_lum_(program, "mlt_luminance") {
    if (opt.split != Split::None || opt.target == Target::TwoStage) parts_ = BurnInParts(pixels);
}

void MltBurnIn::run(RankGroup& ranks, const MemoryPlan& plan, const SceneBuffers& scene,
                    TargetBuffer& target, const BurnInFilm& film, const Chains& chains,
                    const StrataGrid& grid, StrataBuffer& strata) {
    const std::uint32_t m = opt_.threads, iters = std::max(1u, opt_.burn_in_iters);
    const bool parts = keeps_parts();
    // Rounds before `first` only measure the two-stage target's weights.
    const std::uint32_t first = opt_.target == Target::TwoStage ? iters / 2 : 0;
    ClBuffer lum(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::Luminance));
    ClBuffer scan(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::Scan));
    ClBuffer omc =
        parts ? ClBuffer(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::OmcSamples)) : ClBuffer();
    const std::uint32_t tiles = grid.count(), pixels = std::uint32_t(grid.pixel_tile.size());
    BurnInPicker picker(cl_, program_, m, tiles,
                        std::uint32_t(plan.bytes(Buffer::BurnInReplace) / sizeof(cl_ulong)));
    std::vector<float> host(m), host_omc(parts ? 8 * m : 0);
    std::vector<std::uint32_t> sample_tile(m);
    const std::uint32_t groups = std::uint32_t(strata.group_tiles().size());
    BurnInSums s;
    s.tile_lum.assign(tiles, 0);
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
        std::vector<double> round_lum(tiles, 0.0);
        for (std::uint32_t i = 0; i < m; ++i) {
            const float y = host[i];
            const std::uint64_t fixed = fixed_b_sample(y);
            const std::uint32_t pixel =
                burn_in_film_sample(film, pixels, std::uint64_t(it) * film.per_round + i).first;
            const std::uint32_t t = sample_tile[i] = grid.pixel_tile[pixel];
            s.tile_lum[t] += fixed;
            s.lum_fixed += fixed;
            s.lum2 += double(y) * y;
            round_lum[t] += double(fixed);
        }
        if (it == first && tiles > 1)
            strata.deal(strata_group_tiles(strata_groups(round_lum, groups), groups));
        if (opt_.burn_in)
            picker.add_round(lum, host, m, scan, pick_seed, it, chains.count, chains.picks,
                             PickStrata{&sample_tile, &strata.group_tile(), strata.group_chains()});
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
