#include "render/mlt.hpp"

#include "base/clock.hpp"
#include "base/color.hpp"
#include "base/error.hpp"
#include "base/rng.hpp"
#include "device/scan.hpp"
#include "render/programs.hpp"
#include "render/ranks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace smallmlt {

namespace {

// Seeds of the kinds of streams of a render.
constexpr std::uint64_t kPurposeOmc = 1, kPurposePick = 2, kPurposeStep = 3, kPurposePixel = 4,
                        kPurposeFilmOffset = 5;

std::string program_defines(const ClContext& cl, const DeviceScene& ds, const MltOptions& opt) {
    std::string d = ds.layout.defines() + scan_defines(cl.device()) + "#define MLT_GROUP " +
                    std::to_string(kDefaultWorkGroup) + "u\n";
    if (opt.test.float32_states) d += "#define PSS_FLOAT32 1\n";
    if (opt.test.eager_stay) d += "#define MLT_EAGER_STAY 1\n";
    if (opt.split != Split::None || opt.target == Target::TwoStage)
        d += "#define MLT_BURN_IN_SAMPLES 1\n";
    if (opt.film_atomics64) d += "#define FILM_ATOMICS64 1\n";
    return d + split_defines(opt.split);
}

ChainShape chain_shape(const MltOptions& opt) {
    ChainShape s{opt.threads, opt.proposals, opt.test.float32_states, opt.film_atomics64,
                 opt.split != Split::None};
    s.target_cells = opt.target == Target::TwoStage ? kTargetMaxCells : 1;
    return s;
}

const MltOptions& check_options(const MltOptions& opt) {
    check_chain_shape(chain_shape(opt));
    if (opt.stuck_run == 0) throw UsageError("--stuck-run: must be at least 1");
    return opt;
}

const DeviceScene& require_device(const ClContext& cl, const DeviceScene& ds,
                                  const MltOptions& opt) {
    mlt_require_device(cl.device(), opt);
    return ds;
}

std::uint64_t max_alloc(const ClContext& cl, const MltOptions& opt) {
    return opt.max_alloc_bytes ? opt.max_alloc_bytes : cl.device().max_alloc_bytes;
}

// Modes of the mlt_owed kernel (cl/kernels/mlt.cl).
constexpr cl_uint kOwedAdd = 0, kOwedUndo = 1, kOwedFlush = 2;

// A luminance sum in MLT_B_FRAC_BITS fixed point, as a number.
double fixed_lum(std::uint64_t v) {
    return double(v) / double(1u << MLT_B_FRAC_BITS);
}

} // namespace

void mlt_require_device(const DeviceInfo& d, const MltOptions& opt) {
    if (opt.film_atomics64 && !d.int64_atomics)
        throw InputError("device " + d.name +
                         " lacks cl_khr_int64_base_atomics, which the 64-bit film needs; "
                         "leave out --film-atomics 64");
}

std::vector<std::string> mlt_program_files(const MltOptions& opt) {
    ProgramSpec spec;
    spec.program = Program::Mlt;
    spec.evaluator = opt.test.evaluator;
    spec.extra = opt.test.extra_files;
    return program_files(spec);
}

MltRenderer::MltRenderer(const ClContext& cl, const DeviceScene& ds, const MltOptions& opt)
    : cl_(cl), ds_(require_device(cl, ds, opt)), opt_(check_options(opt)),
      plan_(plan_mlt(ds, chain_shape(opt), scan_work_group(cl.device()), max_alloc(cl, opt))),
      program_(cl.build(mlt_program_files(opt), program_defines(cl, ds, opt))),
      k_lum_(program_.p, "mlt_luminance"), k_init_(program_.p, "mlt_init"),
      k_step_(program_.p, "mlt_step"), k_owed_(program_.p, "mlt_owed"), scene_(cl, ds),
      state_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::State)),
      values_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Values)),
      stats_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Stats)),
      picks_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Picks)),
      weight_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::TargetWeights)), cells_(target_one_cell()),
      burn_in_film_(smallmlt::burn_in_film(derive_seed(opt.seed, kPurposePixel),
                                           derive_seed(opt.seed, kPurposeFilmOffset),
                                           std::uint32_t(pixels()), opt.threads)),
      film_(cl, pixels(),
            plan_mlt_film(pixels(), opt.threads, max_alloc(cl, opt), opt.film_atomics64,
                          opt.film_pass_mutations, opt.kelemen ? 2.0 : 1.0)) {
    split_ = opt.split;
    if (opt.split != Split::None || opt.target == Target::TwoStage)
        burn_in_parts_ = BurnInParts(pixels());
    if (opt.split != Split::None)
        omc_ = make_omc_part(split_ == Split::Auto ? kChainsSplit : split_);
    state_.fill_zero(cl);
    stats_.fill_zero(cl);
    picks_.fill_zero(cl);
    std::vector<float> ones(weight_.bytes() / sizeof(float), 1.0f);
    weight_.write(cl, ones.data());
}

void MltRenderer::sample_starts(RankGroup& ranks) {
    const std::uint32_t m = opt_.threads, iters = std::max(1u, opt_.burn_in_iters);
    const std::uint32_t chains = this->chains();
    // The burn-in's samples come back (pixel, OMC and MLT parts) for a split
    // and for the two-stage target.
    const bool samples = !burn_in_parts_.count.empty();
    // Rounds before `first` only measure the two-stage target's weights.
    const std::uint32_t first = opt_.target == Target::TwoStage ? iters / 2 : 0;
    ClBuffer lum(cl_, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Luminance));
    ClBuffer scan(cl_, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Scan));
    ClBuffer omc =
        samples ? ClBuffer(cl_, CL_MEM_READ_WRITE, plan_.bytes(Buffer::OmcSamples)) : ClBuffer();
    BurnInPicker picker(cl_, program_.p, m);
    std::vector<float> host(m), host_omc(samples ? 8 * m : 0);
    std::uint64_t sum = 0;
    double sum2 = 0;
    cl_ulong omc_seed = derive_seed(opt_.seed, kPurposeOmc);
    cl_ulong pick_seed = derive_seed(opt_.seed, kPurposePick);
    for (std::uint32_t it = 0; it < iters; ++it) {
        if (it == first && first > 0) fix_target(ranks);
        k_lum_.set_args(scene_, weight_, cells_, burn_in_film_, state_,
                        cl_ulong(omc_round_seed(omc_seed, it)), cl_uint(it), cl_uint(m), lum,
                        samples ? omc : lum, stats_);
        k_lum_.run(cl_, m);
        lum.read(cl_, host.data());
        if (samples) {
            omc.read(cl_, host_omc.data());
            burn_in_parts_.add(host_omc);
        }
        if (it < first) continue;
        for (float y : host) {
            sum += fixed_b_sample(y);
            sum2 += double(y) * y;
        }
        if (opt_.burn_in) picker.add_round(lum, host, m, scan, pick_seed, it, chains, picks_);
    }
    if (!opt_.burn_in) {
        // Fresh samples: round iters, after those that estimated b.
        std::vector<cl_uint2> fresh(chains);
        for (std::uint32_t c = 0; c < chains; ++c)
            fresh[c] = cl_uint2{{iters, c}};
        picks_.write(cl_, fresh.data());
    }
    double n = double(m) * (iters - first), mean = fixed_lum(sum) / n;
    burn_in_fixed_ = sum;
    burn_in_sum2_ = sum2;
    burn_in_samples_ = std::uint64_t(m) * (iters - first);
    burn_in_variance_ = n > 1 ? std::max(0.0, (sum2 / n - mean * mean) * n / (n - 1)) : 0;
    if (samples) {
        mlt_part_b_ = burn_in_parts_.mean(burn_in_parts_.rest);
        omc_variance_ = burn_in_parts_.variance(burn_in_parts_.omc, burn_in_parts_.omc_y2);
        mlt_variance_ = burn_in_parts_.variance(burn_in_parts_.rest, burn_in_parts_.rest_y2);
    }
}

void MltRenderer::fix_target(RankGroup& ranks) {
    const std::uint32_t w = ds_.frame.width, h = ds_.frame.height;
    // Every rank's sums and sample count (ranks may run different threads).
    std::vector<double> sums = burn_in_parts_.rest;
    sums.push_back(double(std::accumulate(burn_in_parts_.count.begin(), burn_in_parts_.count.end(),
                                          std::uint64_t(0))));
    ranks.sum_all(sums);
    cells_ = target_cells(w, h, std::uint64_t(sums.back()));
    sums.pop_back();
    std::vector<float> weights = target_weights(cells_, w, h, sums);
    weights.resize(weight_.bytes() / sizeof(float), 1.0f); // at most kTargetMaxCells
    weight_.write(cl_, weights.data());
}

double mlt_b(std::uint64_t lum_fixed, std::uint64_t samples) {
    return samples ? fixed_lum(lum_fixed) / double(samples) : 0;
}

MltRenderer::BEstimate MltRenderer::b_estimate(const MltStats& s) const {
    double n = double(burn_in_samples_) + double(s.large);
    BEstimate e;
    e.b = mlt_b(burn_in_fixed_ + s.large_lum, burn_in_samples_ + s.large);
    e.rel_error = e.b > 0 ? std::sqrt(burn_in_variance_ / n) / e.b : 0;
    return e;
}

double MltRenderer::b() const {
    return b_estimate(stats()).b;
}

double MltRenderer::b_rel_error() const {
    return b_estimate(stats()).rel_error;
}

void MltRenderer::prepare(RankGroup& ranks) {
    Clock::time_point t0 = Clock::now();
    sample_starts(ranks);
    if (opt_.kelemen)
        kelemen_pb_ = float(std::clamp(double(large_step_of(opt_)), 0.0, 1.0) *
                            mlt_b(burn_in_fixed_, burn_in_samples_));
    if (split_ == Split::Auto) {
        bool pay = ranks.all(chains_pay(mlt_relative_variance()));
        split_ = pay ? kChainsSplit : Split::All;
        if (!pay) {
            omc_.reset(); // its buffers first, so the memory plan's peak holds
            omc_ = make_omc_part(split_);
        }
    }
    if (split_ != Split::All) init_chains();
    prepared_ = true;
    prepare_seconds_ += seconds_since(t0);
}

double MltRenderer::mlt_relative_variance() const {
    return mlt_part_relative_variance(mlt_variance_, mlt_part_b_, double(pixels()));
}

std::unique_ptr<OmcSchedule> MltRenderer::make_omc_part(Split split) const {
    // Each pixel's Sobol sequence goes on after the burn-in's samples (and
    // the fresh starts of --burn-in none, round T).
    const std::uint32_t rounds = std::max(1u, opt_.burn_in_iters);
    std::uint64_t samples = std::uint64_t(opt_.threads) * rounds + (opt_.burn_in ? 0 : chains());
    std::uint32_t first = burn_in_film_end(burn_in_film_, std::uint32_t(pixels()), samples);
    return std::make_unique<OmcSchedule>(
        std::make_unique<OmcPartTracer>(cl_, ds_, derive_seed(opt_.seed, kPurposePixel),
                                        OmcPart{split, &scene_, first}),
        opt_.threads, opt_.omc_effort);
}

void MltRenderer::init_chains() {
    cl_ulong omc_seed = derive_seed(opt_.seed, kPurposeOmc);
    k_init_.set_args(scene_, weight_, cells_, burn_in_film_, state_, values_, cl_uint(chains()),
                     omc_seed, picks_, stats_);
    k_init_.enqueue(cl_, chains());
    cl_.finish("kernel mlt_init over " + std::to_string(chains()) + " chains");
}

void MltRenderer::owed(std::uint32_t mode) const {
    k_owed_.set_args(ds_.frame, weight_, cells_, cl_float(kelemen_pb_), state_, values_,
                     cl_uint(chains()), cl_ulong(derive_seed(opt_.seed, kPurposeStep)),
                     cl_uint(iterations_), film_, cl_uint(mode));
    k_owed_.enqueue(cl_, chains());
}

void MltRenderer::step(std::uint32_t n) {
    cl_ulong seed = derive_seed(opt_.seed, kPurposeStep);
    double p = std::clamp(double(large_step_of(opt_)), 0.0, 1.0);
    cl_uint threshold = p >= 1.0 ? 0xFFFFFFFFu : cl_uint(p * 4294967296.0);
    const std::uint32_t drain_every = film_.plan().steps_per_drain;
    Clock::time_point t0 = Clock::now();
    if (split_ == Split::Auto) split_ = kChainsSplit; // no prepare(): the chains run
    const bool chains = burn_in_fixed_ > 0 && split_ != Split::All;
    for (std::uint32_t i = 0; i < n; ++i) {
        cl_uint iteration = ++iterations_;
        if (chains) {
            ++steps_run_;
            k_step_.set_args(scene_, weight_, cells_, state_, values_, cl_uint(opt_.threads),
                             cl_uint(opt_.proposals), seed, iteration, threshold,
                             cl_float(kelemen_pb_), film_, stats_, cl_uint(opt_.stuck_run));
            k_step_.enqueue(cl_, opt_.threads);
            // The pass ends: every chain splats what it owes, and the film's
            // words go to the host before the next pass could overflow them.
            if (drain_every && iteration % drain_every == 0) {
                owed(kOwedFlush);
                film_.drain();
            }
        }
        if (omc_) omc_->after_step(chains, [this] { return split_costs(); });
    }
    cl_.finish("kernel mlt_step over " + std::to_string(opt_.threads) + " threads");
    step_seconds_ += seconds_since(t0);
}

SplitCosts MltRenderer::split_costs() const {
    SplitCosts c;
    c.omc_variance = omc_variance_;
    c.b = mlt_part_b_;
    c.pixels = double(pixels());
    c.threads = double(opt_.threads);
    c.mutation_rays = double(stats().rays) / c.threads;
    return c;
}

bool MltRenderer::finished() const {
    if (!prepared_ || burn_in_fixed_ > 0) return false;
    return !omc_ || std::none_of(burn_in_parts_.omc.begin(), burn_in_parts_.omc.end(),
                                 [](double v) { return v > 0; });
}

std::uint32_t MltRenderer::state_bytes_per_chain() const {
    return ds_.layout.chain_bytes(opt_.test.float32_states);
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
    r.burn_in_lit = burn_in_fixed_ > 0;
    r.burn_in_samples = std::uint64_t(opt_.threads) * opt_.burn_in_iters;
    r.burn_in_spp = double(opt_.threads) * std::max(1u, opt_.burn_in_iters) / double(pixels());
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
    r.mlt_relative_variance = omc_ ? mlt_relative_variance() : 0;
    r.kelemen = opt_.kelemen;
    r.kelemen_pb = kelemen_pb_;
    r.two_stage = opt_.target == Target::TwoStage;
    r.target_cells = target_cell_count(cells_, ds_.frame.height);
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

MltTally MltRenderer::mlt_tally() const {
    MltTally t;
    // The film with the stay weights the chains have gathered and not yet
    // splatted, which are then taken out again.
    owed(kOwedAdd);
    t.film = film_.read();
    owed(kOwedUndo);
    cl_.finish("kernel mlt_owed over " + std::to_string(chains()) + " chains");
    const int shift = FILM64_FRAC_BITS - int(film_.plan().shape.frac_bits);
    for (std::uint64_t& w : t.film)
        w <<= shift;
    MltStats s = stats();
    t.mutations = s.mutations;
    t.burn_in_lum = burn_in_fixed_;
    t.burn_in_samples = burn_in_samples_;
    t.large_lum = s.large_lum;
    t.large = s.large;
    t.burn_in_lum2 = burn_in_sum2_;
    if (omc_) {
        Tally o = omc_->part().tally(); // spp, then sums per pixel and channel
        t.omc_spp = o.ints.at(0);
        t.omc_sums = o.reals;
        const BurnInParts& b = burn_in_parts_;
        t.burn_in_landed = b.count;
        t.burn_in_omc = b.omc;
        if (split_ == Split::All) // the burn-in's whole paths
            for (std::size_t i = 0; i < b.rest.size(); ++i)
                t.burn_in_omc[i] += b.rest[i];
    }
    return t;
}

Tally MltRenderer::tally() const {
    return mlt_tally().to_tally();
}

Image MltRenderer::image_from(const Tally& summed) const {
    return image_of(summed, true, true);
}

Image MltRenderer::part_image(Part part) const {
    return image_of(tally(), part == Part::Mlt, part == Part::Omc);
}

Image MltRenderer::image_of(const Tally& summed, bool mlt, bool omc) const {
    MltTally t = MltTally::shaped(pixels(), omc_ != nullptr);
    t.read(summed);
    Image img(int(ds_.frame.width), int(ds_.frame.height));
    const std::size_t n = 3 * pixels();
    if (mlt && t.mutations > 0) {
        double b = mlt_b(t.burn_in_lum + t.large_lum, t.burn_in_samples + t.large);
        double scale = b * double(pixels()) / double(t.mutations) / double(1u << FILM64_FRAC_BITS);
        for (std::size_t i = 0; i < n; ++i)
            img.rgb[i] = float(double(t.film[i]) * scale);
    }
    if (omc && omc_) {
        // Per-pixel samples and the burn-in's that landed in the pixel.
        for (std::size_t i = 0; i < n; ++i) {
            double spp = double(t.omc_spp) + double(t.burn_in_landed[i / 3]);
            if (spp > 0) img.rgb[i] += float((t.omc_sums[i] + t.burn_in_omc[i]) / spp);
        }
    }
    return img;
}

} // namespace smallmlt
