#include "render/mlt_burn_in.hpp"

#include "fixed_point.h"
#include "render/emission_seen.hpp"
#include "render/mlt_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

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

// The round's luminances read back (and its parts added, where `parts`),
// added to b's sums, and the luminance sum of each tile to round_lum_. The
// kernel writes the parts wherever they are kept (MLT_BURN_IN_SAMPLES), so
// r.omc then exists.
void MltBurnIn::sample_round(const Round& r, std::uint32_t it, Parts parts, BurnInSums& s) {
    const std::uint32_t m = opt_.threads, pixels = std::uint32_t(r.grid.pixel_tile.size());
    k_lum_.set_args(r.scene, r.target, r.film, r.chains.state, cl_uint(it), cl_uint(m), r.lum,
                    keeps_parts() ? r.omc : r.lum, r.chains.stats, r.strata, r.image,
                    cl_ulong(mlt_seed(opt_.seed, MltStream::RestartSplat)), cl_uint(r.splat));
    k_lum_.run(cl_, m);
    r.lum.read(cl_, host_.data());
    if (parts != Parts::None) {
        r.omc.read(cl_, host_omc_.data());
        parts_.add(host_omc_, parts == Parts::Cells ? &cell_pixels_ : nullptr);
    }
    round_lum_.assign(r.grid.count(), 0.0);
    for (std::uint32_t i = 0; i < m; ++i) {
        const float y = host_[i];
        const std::uint64_t fixed = fixed_b_sample(y);
        const std::uint32_t pixel =
            burn_in_film_sample(r.film, pixels, std::uint64_t(it) * r.film.per_round + i).first;
        const std::uint32_t t = r.grid.pixel_tile[pixel];
        s.tile_lum[t] += fixed;
        s.lum_fixed += fixed;
        s.lum2 += double(y) * y;
        round_lum_[t] += double(fixed);
    }
}

void MltBurnIn::allocate_rounds(const MemoryPlan& plan) {
    if (lum_.get()) return;
    lum_ = ClBuffer(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::Luminance));
    if (keeps_parts()) omc_ = ClBuffer(cl_, CL_MEM_READ_WRITE, plan.bytes(Buffer::OmcSamples));
}

void MltBurnIn::run(RankGroup& ranks, const MemoryPlan& plan, const SceneBuffers& scene,
                    TargetBuffer& target, const BurnInFilm& film, const Chains& chains,
                    const StrataGrid& grid, StrataBuffer& strata, MltFilm& image) {
    const std::uint32_t m = opt_.threads, iters = burn_in_rounds(opt_);
    const bool parts = keeps_parts();
    // The rounds before `first` fix the target (the two-stage target's
    // weights, the OMC part's cells); where it changes, b and the chains'
    // starts take only the rounds after them. The two-stage target takes
    // half of --burn-in-iters; the cells take half as many more, so that as
    // many rounds as without them give b and the starts (on veach-mis, half
    // as many tripled the error).
    const bool two_stage = opt_.target == Target::TwoStage, omc = omc_cells_in_force(opt_);
    const std::uint32_t first = omc ? omc_cell_rounds(opt_) : two_stage ? iters / 2 : 0;
    allocate_rounds(plan);
    const Round r{scene, target, film, chains, grid, strata, image, false, lum_, omc_};
    const std::uint32_t tiles = grid.count();
    picks_.emplace(film, scene.frame.width, scene.frame.height, grid);
    host_.resize(m);
    host_omc_.resize(parts ? 8 * m : 0);
    BurnInSums s;
    s.tile_lum.assign(tiles, 0);
    std::uint32_t counted = 0; // the first round of b's sums and of the picks
    for (std::uint32_t it = 0; it < iters; ++it) {
        if (it == first && first > 0 && fix_target(ranks, scene, target, two_stage, omc)) {
            // The target changed: b and the starts take the rounds after it.
            s = BurnInSums();
            s.tile_lum.assign(tiles, 0);
            picks_.emplace(film, scene.frame.width, scene.frame.height, grid);
            counted = it;
        }
        sample_round(r, it, parts ? Parts::All : Parts::None, s);
        if (it == counted) deal_lum_ = round_lum_;
        if (opt_.burn_in) picks_->add_round(it, host_);
    }
    rounds_ = iters;
    if (opt_.burn_in)
        largest_start_share_ = picks_->largest_share();
    else
        picks_.reset();
    s.samples = std::uint64_t(m) * (iters - counted);
    sums_ = s;
    sums_.update_variance();
    if (parts) {
        mlt_part_b_ = parts_.mean(parts_.rest);
        // V_o of the film but the OMC part's cells, and V_c of those.
        PixelVariance film, cells;
        const std::uint32_t w = scene.frame.width;
        auto in_cell = [&](std::uint32_t p) { return target.omc_pixel(p % w, p / w); };
        for (std::size_t p = 0; p < parts_.count.size(); ++p)
            (in_cell(std::uint32_t(p)) ? cells : film)
                .add(parts_.luminance(parts_.omc, p), parts_.omc_y2[p], parts_.count[p]);
        // With an OMC part, at least what the lights the camera sees give.
        EmissionSeenParts seen;
        if (opt_.split != Split::None)
            seen = emission_seen(cl_, program_, scene, omc_,
                                 mlt_seed(opt_.seed, MltStream::EmissionSeen), in_cell);
        omc_variance_ = variance_with_emission_seen(film, seen.film);
        cell_variance_ = variance_with_emission_seen(cells, seen.cells);
        if (target.omc_cells() == 0) evidence_ = split_evidence(parts_);
    }
}

void MltBurnIn::regrid(const StrataGrid& from, const StrataGrid& to, std::uint32_t width) {
    std::vector<std::uint64_t> tile_lum(to.count(), 0);
    std::vector<double> deal_lum(to.count(), 0.0);
    for (std::uint32_t t = 0; t < from.count(); ++t) {
        const FilmTile& f = from.tiles[t];
        const std::uint32_t into = to.pixel_tile[std::uint64_t(f.y0) * width + f.x0];
        tile_lum[into] += sums_.tile_lum[t];
        deal_lum[into] += deal_lum_[t];
    }
    sums_.tile_lum = tile_lum;
    deal_lum_ = deal_lum;
    if (picks_) picks_->set_grid(to);
}

void MltBurnIn::start_chains(const Chains& chains, StrataBuffer& strata) {
    const std::uint32_t groups = std::uint32_t(strata.group_tiles().size());
    if (deal_lum_.size() > 1)
        strata.deal(strata_group_tiles(strata_groups(deal_lum_, groups), groups));
    if (picks_)
        write_picks(*picks_, chains, strata);
    else
        fresh_picks(chains); // round iters, after those that estimated b
    picks_.reset();
}

MltBurnIn::SplitEvidence MltBurnIn::split_evidence(const BurnInParts& parts) {
    return {parts.variance(parts.rest, parts.rest_y2), parts.mean(parts.rest),
            parts.behind_specular_share()};
}

namespace {

ChainSteps chain_steps(const MltOptions& opt, std::uint32_t width) {
    return {large_step_of(opt), film_step_pixels(opt, width)};
}

} // namespace

bool MltBurnIn::fix_target(RankGroup& ranks, const SceneBuffers& scene, TargetBuffer& target,
                           bool two_stage, bool omc) {
    const std::uint32_t w = scene.frame.width, h = scene.frame.height;
    ChainsStay stay;
    target.fix(ranks, w, h, parts_, two_stage, omc, chain_steps(opt_, w), &stay);
    if (omc) chains_stay_ = stay;
    // Where the stay will make --restart auto restart (MltRenderer::prepare),
    // the cells are chosen again from the same parts, for the steps of chains
    // that restart: on veach-mis at 512x384, 8x8-block error 1.91 of path
    // tracing's with the cells of chains that do not restart, 1.15 with
    // these (doc/RESULTS.md, "Piles of chains on one path"). The stay is the
    // same on every rank (the parts are summed): every rank chooses again,
    // or none does.
    if (restart_pile_steps(opt_, 0, stay) > 0) {
        MltOptions restarting = opt_;
        restarting.restart = kRestartPileSteps;
        target.fix(ranks, w, h, parts_, two_stage, omc, chain_steps(restarting, w));
    }
    if (target.omc_cells() == 0) return two_stage;
    // The parts so far chose the cells, and their MLT parts there are the
    // chains' no more: they are the evidence for --split auto, and the image
    // and the split's costs take only the parts to come, unless no chain
    // runs (settle_cell_rounds).
    evidence_ = split_evidence(parts_);
    const std::size_t pixels = parts_.count.size();
    cell_rounds_ = BurnInWhole(parts_);
    parts_ = BurnInParts(); // its memory first
    parts_ = BurnInParts(pixels);
    return true;
}

void MltBurnIn::settle_cell_rounds(bool whole) {
    if (whole && !cell_rounds_.count.empty()) parts_.add_whole(cell_rounds_);
    cell_rounds_ = BurnInWhole();
}

void MltBurnIn::write_picks(const StartPicks& picks, const Chains& chains,
                            const StrataBuffer& strata) {
    const std::vector<cl_uint2> p = picks.draw(strata.group_tiles(), strata.group_chains(),
                                               chains.count, mlt_seed(opt_.seed, MltStream::Pick));
    chains.picks.write(cl_, p.data());
}

void MltBurnIn::fresh_picks(const Chains& chains) {
    std::vector<cl_uint2> fresh(chains.count);
    for (std::uint32_t c = 0; c < chains.count; ++c)
        fresh[c] = cl_uint2{{rounds_, c}};
    chains.picks.write(cl_, fresh.data());
    ++rounds_;
}

void MltBurnIn::restart_rounds(const MemoryPlan& plan, const SceneBuffers& scene,
                               TargetBuffer& target, const BurnInFilm& film, const Chains& chains,
                               const StrataGrid& grid, const StrataBuffer& strata,
                               std::uint32_t rounds, MltFilm& image) {
    if (!opt_.burn_in || rounds == 0) return;
    const std::uint32_t m = opt_.threads, drain_every = image.plan().steps_per_drain;
    allocate_rounds(plan);
    const Round r{scene, target, film, chains, grid, strata, image, kelemen_in_force(opt_),
                  lum_,  omc_};
    if (!pool_) pool_.emplace(film, scene.frame.width, scene.frame.height, grid);
    host_.resize(m);
    // Their paths in the OMC part's cells are whole paths, path tracing's
    // samples there. Elsewhere the OMC part keeps its own: the restarts'
    // there raised cornell-water's and cornell-glass's error (doc/RESULTS.md,
    // "The restarts' rounds in the OMC part").
    const Parts parts = keeps_parts() && target.omc_pixels() > 0 ? Parts::Cells : Parts::None;
    if (parts == Parts::Cells && cell_pixels_.empty()) { // the cells stay after the burn-in
        const std::uint32_t w = scene.frame.width, pixels = std::uint32_t(grid.pixel_tile.size());
        cell_pixels_.resize(pixels);
        for (std::uint32_t p = 0; p < pixels; ++p)
            cell_pixels_[p] = target.omc_pixel(p % w, p / w);
    }
    host_omc_.resize(parts == Parts::Cells ? 8 * std::size_t(m) : 0);
    for (std::uint32_t k = 0; k < rounds; ++k, ++rounds_) {
        sample_round(r, rounds_, parts, sums_);
        sums_.samples += m;
        sums_.restart_samples += m;
        pool_->add_round(rounds_, host_);
        // A round splats at most what a step does; the next step finds the
        // film drained.
        if (r.splat && drain_every && ((k + 1) % drain_every == 0 || k + 1 == rounds))
            image.drain();
    }
    sums_.update_variance();
}

void MltBurnIn::restart_picks(const Chains& chains, const StrataBuffer& strata) {
    if (!opt_.burn_in) return fresh_picks(chains);
    write_picks(*pool_, chains, strata);
    pool_.reset();
}

void BurnInSums::update_variance() {
    const double n = double(samples), mean = mlt_b(lum_fixed, samples);
    variance = n > 1 ? std::max(0.0, (lum2 / n - mean * mean) * n / (n - 1)) : 0;
}

} // namespace smallmlt
