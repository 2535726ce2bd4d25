#include "render/mlt.hpp"

#include "base/bits.hpp"
#include "base/clock.hpp"
#include "base/color.hpp"
#include "base/error.hpp"
#include "render/mlt_seeds.hpp"
#include "render/programs.hpp"
#include "render/ranks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace smallmlt {

namespace {

std::string program_defines(const DeviceScene& ds, const MltOptions& opt,
                            const MltTestHooks& hooks) {
    std::string d =
        ds.layout.defines() + "#define MLT_GROUP " + std::to_string(kDefaultWorkGroup) + "u\n";
    if (hooks.float32_states) d += "#define PSS_FLOAT32 1\n";
    if (hooks.eager_stay) d += "#define MLT_EAGER_STAY 1\n";
    if (opt.split != Split::None || opt.target == Target::TwoStage)
        d += "#define MLT_BURN_IN_SAMPLES 1\n";
    if (opt.film_atomics64) d += "#define FILM_ATOMICS64 1\n";
    d += "#define MLT_FILM_STEP " + std::to_string(film_step_asked(opt)) + "u\n";
    d += "#define MLT_FILM_STEP_SHARE " + std::to_string(film_step_share(opt)) + "u\n";
    d += "#define MLT_FILM_STEP_FLOOR " + std::to_string(film_step_floor(opt)) + "u\n";
    d += "#define MLT_PATH_STEP_LOG2 " + std::to_string(log2_of(opt.path_step)) + "u\n";
    return d + split_defines(opt.split);
}

const MltOptions& check_options(const MltOptions& opt, const MltTestHooks& hooks) {
    check_chain_shape(mlt_chain_shape(opt, hooks));
    if (opt.stuck_run == 0) throw UsageError("--stuck-run: must be at least 1");
    if (!is_power_of_two(opt.path_step) || opt.path_step < kPathStepMin ||
        opt.path_step > kPathStepMax)
        throw UsageError("--path-step: " + std::to_string(opt.path_step) +
                         " is not a power of two from " + std::to_string(kPathStepMin) + " to " +
                         std::to_string(kPathStepMax));
    if (opt.mutations_per_sample &&
        !(*opt.mutations_per_sample > 0 && std::isfinite(*opt.mutations_per_sample)))
        throw UsageError("--mutations-per-sample: must be a finite number above 0");
    return opt;
}

const DeviceScene& require_device(const ClContext& cl, const DeviceScene& ds,
                                  const MltOptions& opt) {
    mlt_require_device(cl.device(), opt);
    return ds;
}

std::uint32_t group_chains(const MltOptions& opt) {
    return std::uint32_t(kDefaultWorkGroup) / opt.proposals;
}

StrataGrid grid_of(const DeviceScene& ds, const MltOptions& opt) {
    const std::uint32_t groups =
        std::uint32_t((opt.threads + kDefaultWorkGroup - 1) / kDefaultWorkGroup);
    const std::uint32_t w = ds.frame.width, h = ds.frame.height;
    return strata_grid(w, h, opt.strata ? strata_side(opt.strata, w, h, groups) : 0);
}

std::uint64_t max_alloc(const ClContext& cl, const MltOptions& opt) {
    return opt.max_alloc_bytes ? opt.max_alloc_bytes : cl.device().max_alloc_bytes;
}

} // namespace

void mlt_require_device(const DeviceInfo& d, const MltOptions& opt) {
    if (opt.film_atomics64 && !d.int64_atomics)
        throw InputError("device " + d.name +
                         " lacks cl_khr_int64_base_atomics, which the 64-bit film needs; "
                         "leave out --film-atomics 64");
}

std::vector<std::string> mlt_program_files(const MltTestHooks& hooks) {
    ProgramSpec spec;
    spec.program = Program::Mlt;
    spec.evaluator = hooks.evaluator;
    spec.extra = hooks.extra_files;
    return program_files(spec);
}

MltRenderer::MltRenderer(const ClContext& cl, const DeviceScene& ds, const MltOptions& opt,
                         const MltTestHooks& hooks)
    : cl_(cl), ds_(require_device(cl, ds, opt)), opt_(check_options(opt, hooks)), hooks_(hooks),
      plan_(plan_mlt(ds, mlt_chain_shape(opt, hooks), max_alloc(cl, opt))),
      program_(cl.build(mlt_program_files(hooks), program_defines(ds, opt, hooks))),
      k_init_(program_.p, "mlt_init"), k_step_(program_.p, "mlt_step"),
      k_owed_(program_.p, "mlt_owed"), scene_(cl, ds),
      state_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::State)),
      values_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Values)),
      stats_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Stats)),
      picks_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Picks)),
      target_(cl, plan_.bytes(Buffer::TargetWeights)), grid_(grid_of(ds, opt)),
      strata_(cl, plan_, grid_, group_chains(opt)),
      burn_in_film_(smallmlt::burn_in_film(mlt_seed(opt.seed, MltStream::Pixel),
                                           mlt_seed(opt.seed, MltStream::FilmOffset),
                                           std::uint32_t(pixels()), opt.threads)),
      burn_in_(cl, program_.p, opt_, pixels()),
      film_(cl, pixels(),
            plan_mlt_film(pixels(), opt.threads, max_alloc(cl, opt), opt.film_atomics64,
                          opt.film_pass_mutations, mlt_chain_shape(opt).film_layers)) {
    kelemen_pb_.assign(grid_.count(), 0.0f);
    kelemen_b0_.assign(grid_.count(), 0.0);
    kelemen_large_.assign(grid_.count(), 0.0);
    kelemen_rate_.assign(grid_.count(), 0.0);
    split_ = opt.split;
    if (opt.split != Split::None)
        omc_ = make_omc_part(split_ == Split::Auto ? kChainsSplit : split_);
    state_.fill_zero(cl);
    stats_.fill_zero(cl);
    picks_.fill_zero(cl);
}

void MltRenderer::sample_starts(RankGroup& ranks) {
    if (!hooks_.zero_cells.empty())
        target_.set(hooks_.cells, ds_.frame.width, ds_.frame.height,
                    std::vector<float>(hooks_.zero_cells.size(), 1.0f), hooks_.zero_cells);
    const MltBurnIn::Chains chains{state_, stats_, picks_, this->chains()};
    burn_in_.run(ranks, plan_, scene_, target_, burn_in_film_, chains, grid_, strata_, film_);
    if (opt_.strata == kStrataPiles && !piles_keep_tiles(ranks))
        set_grid(smallmlt::strata_grid(ds_.frame.width, ds_.frame.height, 0));
    burn_in_.start_chains(chains, strata_);
}

bool MltRenderer::piles_keep_tiles(RankGroup& ranks) const {
    // One sum over ranks, made by every rank, whose answer is the same on
    // every rank: the ranks that piled, and the ranks' tile counts n (a
    // rank's threads give its own), the same on all where R sum n^2 =
    // (sum n)^2. Where they differ their per-tile sums could not be added.
    const double n = grid_.count();
    std::vector<double> s{strata_for_piles(opt_, burn_in_.largest_start_share()) ? 1.0 : 0.0, n,
                          n * n, 1.0};
    ranks.sum_all(s);
    const bool same = s[3] * s[2] == s[1] * s[1];
    return s[0] > 0 && same && n > 1;
}

void MltRenderer::set_grid(StrataGrid grid) {
    burn_in_.regrid(grid_, grid, ds_.frame.width);
    grid_ = std::move(grid);
    strata_.set_grid(grid_);
    for (std::vector<double>* v : {&kelemen_b0_, &kelemen_large_, &kelemen_rate_})
        v->assign(grid_.count(), 0.0);
    kelemen_pb_.assign(grid_.count(), 0.0f);
}

BEstimate MltRenderer::b_estimate(const MltStats& s) const {
    BEstimate e = burn_in_.sums().b(s.large_lum, s.large);
    if (grid_.count() > 1) { // the tiles' B by their areas; the error as of one tile
        const std::vector<double> b = tile_b();
        double sum = 0;
        for (std::uint32_t t = 0; t < grid_.count(); ++t)
            sum += b[t] * grid_.area(t, pixels());
        e.rel_error = sum > 0 ? e.rel_error * e.b / sum : 0;
        e.b = sum;
    }
    return e;
}

double MltRenderer::b() const {
    return b_estimate(stats()).b;
}

double MltRenderer::b_rel_error() const {
    return b_estimate(stats()).rel_error;
}

void MltRenderer::set_stratum_weights(RankGroup& ranks) {
    std::vector<StratumWeights> w(grid_.count());
    std::vector<double> density(grid_.count());
    for (std::uint32_t t = 0; t < grid_.count(); ++t) {
        density[t] = strata_large_density(target_.chains_share(grid_.tiles[t]));
        w[t] = StratumWeights{0.0f, float(density[t])};
    }
    if (kelemen_in_force(opt_)) {
        const double p = std::clamp(double(large_step_of(opt_)), 0.0, 1.0);
        const std::vector<double> b0 = burn_in_.ranks_b(ranks, grid_);
        const std::vector<double> q = restart_rate(ranks);
        for (std::uint32_t t = 0; t < grid_.count(); ++t) {
            kelemen_large_[t] = p * density[t];
            kelemen_rate_[t] = kelemen_large_[t] + q[t];
            kelemen_pb_[t] =
                float(kelemen_rate_[t] * b0[t] * hooks_.b0_scale * mutations_per_sample_of(opt_));
            // the large steps' layer by the b0 of the weights, as they have it
            // (M b0 for M mutations per sample)
            kelemen_b0_[t] = double(kelemen_pb_[t]) / kelemen_rate_[t];
            w[t].kelemen_pb = kelemen_pb_[t];
        }
    }
    strata_.set_weights(w);
}

std::vector<double> MltRenderer::restart_rate(RankGroup& ranks) const {
    const std::uint32_t tiles = grid_.count();
    std::vector<double> q(tiles, 0.0);
    const double rounds = restart_rounds_per_step(opt_);
    if (rounds == 0) return q;
    // Each tile's threads (its work-groups', as tile_counts counts them) and
    // all threads, over every rank, so that every rank weighs with one c.
    std::vector<double> threads(tiles + 1, 0.0);
    const std::vector<std::uint32_t>& group_tile = strata_.group_tiles();
    for (std::size_t g = 0; g < group_tile.size(); ++g)
        threads[group_tile[g]] += double(group_threads(g));
    threads[tiles] = opt_.threads;
    ranks.sum_all(threads);
    for (std::uint32_t t = 0; t < tiles; ++t)
        if (threads[t] > 0) q[t] = rounds * threads[tiles] * grid_.area(t, pixels()) / threads[t];
    return q;
}

void MltRenderer::prepare(RankGroup& ranks) {
    Clock::time_point t0 = Clock::now();
    // Every rank restarts alike, or none does: where the chains cover the
    // film, before the burn-in (whose cells' rule takes the large steps of
    // restarts); else after it, by its piles (whose cells were chosen for
    // restarts where the stay restarts, MltBurnIn::fix_target).
    if (opt_.restart == kRestartAuto && ranks.all(restart_steps(opt_, chains(), pixels()) > 0))
        opt_.restart = kRestartAutoSteps;
    sample_starts(ranks);
    if (opt_.restart == kRestartAuto) {
        const ChainsStay stay = burn_in_.chains_stay().value_or(ChainsStay{}); // none: 0
        opt_.restart =
            ranks.all(restart_pile_steps(opt_, burn_in_.largest_start_share(), stay) == 0)
                ? 0
                : kRestartPileSteps;
    }
    set_stratum_weights(ranks);
    if (split_ == Split::Auto) {
        bool pay = ranks.all(
            chains_pay(mlt_relative_variance(), behind_specular_share(), opt_.restart != 0));
        split_ = pay ? kChainsSplit : Split::All;
        if (!pay) {
            omc_.reset(); // its buffers first, so the memory plan's peak holds
            omc_ = make_omc_part(split_);
        }
    }
    // Path tracing alone takes every burn-in round's paths: each pixel's
    // Sobol numbers from the first.
    burn_in_.settle_cell_rounds(split_ == Split::All);
    if (split_ != Split::All) init_chains();
    prepared_ = true;
    prepare_seconds_ += seconds_since(t0);
}

double MltRenderer::mlt_relative_variance() const {
    const MltBurnIn::SplitEvidence& e = burn_in_.split_evidence();
    return mlt_part_relative_variance(e.mlt_variance, e.mlt_part_b, double(pixels()));
}

std::unique_ptr<OmcSchedule> MltRenderer::make_omc_part(Split split) const {
    // Each pixel's Sobol sequence goes on after the burn-in's samples (and
    // the fresh starts of --burn-in none, round T).
    const std::uint32_t rounds = burn_in_rounds(opt_);
    std::uint64_t samples = std::uint64_t(opt_.threads) * rounds + (opt_.burn_in ? 0 : chains());
    SequenceStart start = burn_in_omc_start(burn_in_film_, std::uint32_t(pixels()), samples);
    return std::make_unique<OmcSchedule>(
        std::make_unique<OmcPartTracer>(cl_, ds_, mlt_seed(opt_.seed, MltStream::Pixel),
                                        OmcPart{split, &scene_, start, &target_}),
        opt_.threads, opt_.omc_effort);
}

void MltRenderer::restart_work(bool restart) {
    // The next restart's rounds spread over the steps before it, B j / R of
    // them by its j-th step, on the restarts' film (restart_film): not the
    // Sobol points the OMC part goes on with.
    const std::uint64_t every = opt_.restart, rounds = opt_.burn_in_iters,
                        j = (steps_run_ - 1) % every + 1;
    const BurnInFilm film = restart_film();
    const MltBurnIn::Chains chains{state_, stats_, picks_, this->chains()};
    burn_in_.restart_rounds(plan_, scene_, target_, film, chains, grid_, strata_,
                            std::uint32_t(rounds * j / every - rounds * (j - 1) / every), film_);
    if (!restart) return;
    ++restarts_;
    burn_in_.restart_picks(chains, strata_);
    init_chains(film);
}

BurnInFilm MltRenderer::restart_film() const {
    // One scramble for every restart: the rounds are numbered on, so each
    // pixel's restart samples are the consecutive points of one Sobol
    // sequence, and all restarts' pools together stay a net. A fresh
    // scramble per restart made them independent nets of a few points a
    // pixel, and where chains stay on a small bright area each restart's
    // pool sets their count there: veach-mis's 8x8-block error at 512x384
    // fell from 1.06 to 0.73 times path tracing's with one sequence
    // (doc/RESULTS.md, "Restarts along one sequence").
    return smallmlt::burn_in_film(derive_seed(mlt_seed(opt_.seed, MltStream::Pixel), 1),
                                  derive_seed(mlt_seed(opt_.seed, MltStream::FilmOffset), 1),
                                  std::uint32_t(pixels()), opt_.threads);
}

void MltRenderer::init_chains(const BurnInFilm& film) {
    k_init_.set_args(scene_, target_, film, strata_, state_, values_, cl_uint(chains()), picks_,
                     stats_);
    k_init_.enqueue(cl_, chains());
    cl_.finish("kernel mlt_init over " + std::to_string(chains()) + " chains");
}

void MltRenderer::owed(std::uint32_t mode) const {
    k_owed_.set_args(ds_.frame, target_, strata_, state_, values_, cl_uint(chains()),
                     cl_ulong(mlt_seed(opt_.seed, MltStream::Step)), cl_uint(iterations_), film_,
                     cl_uint(mode));
    k_owed_.enqueue(cl_, chains());
}

void MltRenderer::step(std::uint32_t n) {
    cl_ulong seed = mlt_seed(opt_.seed, MltStream::Step);
    double p = std::clamp(double(large_step_of(opt_)), 0.0, 1.0);
    cl_uint threshold = p >= 1.0 ? 0xFFFFFFFFu : cl_uint(p * 4294967296.0);
    const std::uint32_t drain_every = film_.plan().steps_per_drain;
    Clock::time_point t0 = Clock::now();
    if (split_ == Split::Auto) split_ = kChainsSplit; // no prepare(): the chains run
    const bool chains = burn_in_.sums().lum_fixed > 0 && split_ != Split::All;
    for (std::uint32_t i = 0; i < n; ++i) {
        cl_uint iteration = ++iterations_;
        if (chains) {
            ++steps_run_;
            k_step_.set_args(scene_, target_, strata_, state_, values_, cl_uint(opt_.threads),
                             cl_uint(opt_.proposals), seed, iteration, threshold, film_, stats_,
                             cl_uint(opt_.stuck_run));
            k_step_.enqueue(cl_, opt_.threads);
            // The pass ends: every chain splats what it owes, and the film's
            // words go to the host before the next pass could overflow them.
            // So it does before the chains start again.
            const bool restart = opt_.restart && steps_run_ % opt_.restart == 0;
            if (restart || (drain_every && iteration % drain_every == 0)) {
                owed(MLT_OWED_FLUSH);
                film_.drain();
            }
            if (opt_.restart) restart_work(restart);
        }
        if (omc_) omc_->after_step(chains, [this] { return split_costs(); });
    }
    cl_.finish("kernel mlt_step over " + std::to_string(opt_.threads) + " threads");
    step_seconds_ += seconds_since(t0);
}

SplitCosts MltRenderer::split_costs() const {
    SplitCosts c;
    c.omc_variance = burn_in_.omc_variance();
    c.cell_variance = burn_in_.cell_variance();
    c.b = burn_in_.mlt_part_b();
    c.pixels = double(pixels());
    c.threads = double(opt_.threads);
    // A mutation's share of the restarts' rounds is the chains' time too;
    // their paths cost about what a mutation does.
    c.mutation_rays = double(stats().rays) / c.threads * (1 + restart_rounds_per_step(opt_));
    return c;
}

bool MltRenderer::finished() const {
    if (!prepared_ || burn_in_.sums().lum_fixed > 0) return false;
    const BurnInParts& parts = burn_in_.parts();
    return !omc_ ||
           std::none_of(parts.omc.begin(), parts.omc.end(), [](double v) { return v > 0; });
}

std::uint32_t MltRenderer::state_bytes_per_chain() const {
    return ds_.layout.chain_bytes(hooks_.float32_states);
}

MltStats MltRenderer::stats() const {
    std::vector<std::uint64_t> rows(stats_.bytes() / sizeof(cl_ulong));
    stats_.read(cl_, rows.data());
    MltStats out = mlt_join_rows(rows);
    out.mutations = std::uint64_t(steps_run_) * opt_.threads;
    return out;
}

MltReport MltRenderer::report() const {
    MltReport r;
    r.stats = stats();
    BEstimate be = b_estimate(r.stats);
    r.b = be.b;
    r.b_rel_error = be.rel_error;
    r.prepared = prepared_;
    r.finished = finished();
    r.split = split_;
    r.split_asked = opt_.split;
    r.burn_in_lit = burn_in_.sums().lum_fixed > 0;
    r.burn_in_samples = std::uint64_t(opt_.threads) * burn_in_rounds(opt_);
    const std::vector<std::uint64_t>& landed = burn_in_.parts().count; // those the image takes
    r.burn_in_spp = burn_in_.keeps_parts()
                        ? double(std::accumulate(landed.begin(), landed.end(), std::uint64_t(0))) /
                              double(pixels())
                        : double(opt_.threads) * burn_in_rounds(opt_) / double(pixels());
    r.chains = chains();
    r.proposals = opt_.proposals;
    r.steps = steps_run_;
    r.iterations = iterations_;
    r.state_bytes = state_bytes_per_chain();
    r.stuck_run = opt_.stuck_run;
    r.prepare_seconds = prepare_seconds_;
    r.step_seconds = step_seconds_;
    r.omc_part = omc_ != nullptr;
    r.omc_spp = omc_spp();
    r.omc_rate = omc_rate();
    r.omc_cell_spp = omc_cell_spp();
    r.omc_cell_rate = omc_cell_rate();
    r.mlt_relative_variance = omc_ ? mlt_relative_variance() : 0;
    r.behind_specular_share = omc_ ? behind_specular_share() : 0;
    r.kelemen = opt_.kelemen;
    r.mutations_per_sample = mutations_per_sample_of(opt_);
    r.strata = grid_.count();
    r.strata_piles = opt_.strata == kStrataPiles;
    r.restart_every = opt_.restart;
    r.restart_samples = opt_.restart && opt_.burn_in && kelemen_in_force(opt_);
    r.restarts = restarts_;
    r.chains_stay = burn_in_.chains_stay();
    if (!kelemen_pb_.empty()) {
        double pb = 0; // c b0 of the whole film: the tiles' c B0 by their areas
        for (std::uint32_t t = 0; t < grid_.count(); ++t)
            pb += double(kelemen_pb_[t]) * grid_.area(t, pixels());
        r.kelemen_pb = grid_.count() == 1 ? kelemen_pb_[0] : float(pb);
    }
    r.two_stage = opt_.target == Target::TwoStage;
    r.target_cells = target_cell_count(target_.cells(), ds_.frame.height);
    r.omc_cells = target_.omc_cells();
    r.omc_cell_share = double(target_.omc_pixels()) / double(pixels());
    return r;
}

std::vector<std::string> MltRenderer::notes() const {
    return mlt_notes(report());
}

std::string MltRenderer::summary(double) const {
    return mlt_summary(report());
}

std::uint64_t MltRenderer::units_for_spp(std::uint32_t spp, int rank, int ranks) const {
    std::uint64_t mutations = rank_share(std::uint64_t(spp) * pixels(), rank, ranks);
    return (mutations + opt_.threads - 1) / opt_.threads;
}

} // namespace smallmlt
