// Primary-sample-space MLT on the device (cl/kernels/mlt.cl): N chains, one
// per work-item, with packed states and lazy proposals. The host estimates
// the normalization b, starts the chains, runs steps and assembles the image.
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"
#include "device/scan.hpp"
#include "device/scene_buffers.hpp"
#include "fixed_point.h"
#include "image/image.hpp"
#include "render/burn_in.hpp"
#include "render/integrator.hpp"
#include "render/mlt_film.hpp"
#include "render/mlt_report.hpp"
#include "render/mlt_stats.hpp"
#include "render/mlt_tally.hpp"
#include "render/omc_part_tracer.hpp"
#include "render/omc_schedule.hpp"
#include "render/split.hpp"
#include "render/target.hpp"
#include "scene/device_scene.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

constexpr std::uint32_t kDefaultStuckRun = 1000;
// Defaults chosen by the benches of doc/RESULTS.md: Kelemen's weights, with
// which large steps pay more often than with expected values alone.
constexpr bool kDefaultKelemen = true;
constexpr float kDefaultLargeStepKelemen = 0.3f;  // with burn-in and Kelemen's weights
constexpr float kDefaultLargeStepBurnIn = 0.1f;   // with burn-in and expected values
constexpr float kDefaultLargeStepNoBurnIn = 0.5f; // the paper's baseline without

// What tests change in an MLT render besides its options: reference builds
// to compare against, and the program's evaluator and probes.
struct MltTestHooks {
    bool float32_states = false; // unpacked float32 states
    bool eager_stay = false;     // splat x's stay weight at every step
    // The file that defines eval_state: cl/path/eval_path.cl renders the
    // scene; the sampler tests use test/cl/eval_target.cl, a known target
    // (2D, or with bounces on a layout that has bounce slots).
    std::string evaluator = "cl/path/eval_path.cl";
    std::vector<std::string> extra_files; // appended to the program (test probes)
};

// An MLT render's options. The defaults are the command line's: `render`
// fills these fields from its flags (src/app/options.cpp), and
// test/test_options.cpp checks that an empty command line leaves them as
// they are. Only threads and max_alloc_bytes differ: the command line fits
// them to the device.
struct MltOptions {
    std::uint32_t threads = 1u << 16; // N work-items
    std::uint32_t proposals = 1;      // K proposals per chain: N / K chains (a power of two <= 64)
    // Probability that a step is large; unset: default_large_step (large_step_of).
    std::optional<float> large_step;
    std::uint64_t seed = 1;
    // Burn-in by OMC (Frolov and Galaktionov, section 3.1): burn_in_iters
    // rounds of one OMC sample per thread; each chain starts at a sample
    // drawn from all rounds' samples in proportion to luminance (a weighted
    // reservoir over rounds, BurnInPicker). All threads x iters samples
    // estimate b. Without burn-in, chains start at fresh OMC samples.
    bool burn_in = true;
    std::uint32_t burn_in_iters = 32; // chosen by measurement (doc/RESULTS.md)
    // The 64-bit film of 64-bit atomics (reference build; needs
    // cl_khr_int64_base_atomics); the default needs only 32-bit ones.
    bool film_atomics64 = false;
    // The largest allocation the film's bands must fit (0: the device's).
    std::uint64_t max_alloc_bytes = 0;
    // Mutations between drains of the 32-bit film (src/render/mlt_film.hpp).
    std::uint64_t film_pass_mutations = kFilmPassMutations;
    // A chain that rejects this many proposals in a row counts as stuck
    // (reported, not acted on; doc/stability.md).
    std::uint32_t stuck_run = kDefaultStuckRun;
    // What the chains render (src/render/split.hpp): with a split, the OMC
    // part is rendered by per-pixel samples beside them, omc_effort times
    // the time the rule of split.hpp gives it, and by the burn-in's paths.
    Split split = kDefaultSplit;
    double omc_effort = 1.0;
    // The chains' target (src/render/target.hpp).
    Target target = kDefaultTarget;
    // Kelemen's weights (Kelemen et al. 2002, section 5; cl/mlt/mlt_step.cl):
    // large steps also count as independent samples, combined with the
    // chains' expected values by the balance heuristic. Off: expected values
    // alone, and the image's mean is b.
    bool kelemen = kDefaultKelemen;
    // Not the user's: the tests' reference builds and probes (the command
    // line never sets these).
    MltTestHooks test;
};

// The large step's probability where none is given: it depends on burn-in
// and the weights.
constexpr float default_large_step(bool burn_in, bool kelemen) {
    return !burn_in  ? kDefaultLargeStepNoBurnIn
           : kelemen ? kDefaultLargeStepKelemen
                     : kDefaultLargeStepBurnIn;
}
// The large step's probability of a render of `opt`.
inline float large_step_of(const MltOptions& opt) {
    return opt.large_step.value_or(default_large_step(opt.burn_in, opt.kelemen));
}

// Throws InputError naming the device if it lacks what the options need:
// 64-bit atomics for the 64-bit reference film.
void mlt_require_device(const DeviceInfo& d, const MltOptions& opt);

// Kernel files of the MLT program, in build order.
std::vector<std::string> mlt_program_files(const MltOptions& opt);

// b from the fixed-point sum of `samples` luminances.
double mlt_b(std::uint64_t lum_fixed, std::uint64_t samples);

class MltRenderer : public Integrator {
  public:
    MltRenderer(const ClContext& cl, const DeviceScene& ds, const MltOptions& opt);

    // Burn-in, the split (Split::Auto decides here, every rank alike) and
    // the chains' starts.
    void prepare(RankGroup& ranks) override;
    void prepare() {
        SingleRank one;
        prepare(one);
    }
    void advance(std::uint32_t units) override { step(units); }
    // Steps that make the rank's share of spp x pixels mutations.
    std::uint64_t units_for_spp(std::uint32_t spp, int rank, int ranks) const override;
    double spp_done() const override {
        return double(iterations_) * opt_.threads / double(pixels());
    }
    std::string summary(double seconds) const override;
    // No OMC sample of burn-in carried light: the image is black whatever the
    // chains do (and, with a split, the OMC part had none either).
    bool finished() const override;
    std::vector<std::string> notes() const override;
    // The account its summary and notes are made from.
    MltReport report() const;

    // Runs the OMC samples of burn-in: the first estimate of b, and the
    // chains' starting samples (burn-in or fresh). With the two-stage target,
    // its first half fixes the target's weights (the same on every rank) and
    // only the second half estimates b and picks the starts.
    void sample_starts(RankGroup& ranks);
    void sample_starts() {
        SingleRank one;
        sample_starts(one);
    }
    // b, the mean luminance I of the OMC samples drawn so far: the burn-in's
    // and every large step's (each an OMC sample of I), so b keeps converging
    // as the render goes on; and its relative standard error, from the
    // burn-in's per-sample variance over all of them.
    double b() const;
    double b_rel_error() const;

    // Starts every chain at its starting sample's path.
    void init_chains();
    // n Metropolis steps of every chain.
    void step(std::uint32_t n);

    std::uint32_t iterations() const { return iterations_; }
    std::uint32_t chains() const { return opt_.threads / opt_.proposals; }
    std::uint64_t pixels() const { return std::uint64_t(ds_.frame.width) * ds_.frame.height; }
    MltStats stats() const;
    // Packed numbers plus the ChainValue (F(x), live bounces).
    std::uint32_t state_bytes_per_chain() const;
    // What the render has rendered (src/render/mlt_tally.hpp), as a Tally.
    Tally tally() const override;
    MltTally mlt_tally() const;
    // b * splats * pixels / mutations, b from the summed samples, plus the
    // OMC part of a split: per pixel, the sum of its per-pixel samples and
    // of the burn-in's that landed in it, over spp + their count. Given the
    // count, those are uniform in the pixel, so this is unbiased (dividing by
    // the expected count M / P instead adds the count's noise: for the light
    // seen directly, where every sample is the same, most of the error).
    Image image_from(const Tally& summed) const override;
    // One part of the image: the chains' (MLT) or the OMC part (black
    // without a split; the whole image with Split::All).
    enum class Part { Mlt, Omc };
    Image part_image(Part part) const;
    // The OMC part's per-pixel samples per MLT step (split.hpp's rule), once
    // the first step has measured a mutation's rays; 0 before.
    double omc_rate() const { return omc_ ? omc_->rate() : 0; }
    std::uint32_t omc_spp() const { return omc_ ? omc_->part().spp() : 0; }
    // The split in force: opt.split, with Auto decided by prepare().
    Split split() const { return split_; }
    // r of chains_pay (src/render/split.hpp), from the burn-in.
    double mlt_relative_variance() const;
    const MltFilm& film() const { return film_; }
    // Where the burn-in's samples lie on the film, what they left per pixel,
    // and the OMC part's first Sobol sample number (after the burn-in's).
    const BurnInFilm& burn_in_film() const { return burn_in_film_; }
    const BurnInParts& burn_in_parts() const { return burn_in_parts_; }
    std::uint32_t omc_first_sample() const { return omc_ ? omc_->part().first_sample() : 0; }

    // For tests: the raw buffers.
    const ClBuffer& state() const { return state_; }
    const ClBuffer& values() const { return values_; }
    const ClBuffer& picks() const { return picks_; }    // (round, index) per chain
    const ClBuffer& weights() const { return weight_; } // the target's w per cell
    cl_program program() const { return program_.p; }

  private:
    const ClContext& cl_;
    const DeviceScene& ds_;
    MltOptions opt_;
    MemoryPlan plan_; // sizes of every buffer below (src/device/memory_plan.cpp)
    ClProgram program_;
    ClKernel k_lum_, k_init_, k_step_;
    mutable ClKernel k_owed_; // run by image(), which leaves the film as it was
    SceneBuffers scene_;
    ClBuffer state_, values_, stats_, picks_;
    ClBuffer weight_;         // the target's weight per cell
    TargetCells cells_;       // in force: one cell of weight 1 until two-stage fixes them
    BurnInFilm burn_in_film_; // where the burn-in's samples lie on the film
    MltFilm film_;
    Split split_;
    std::unique_ptr<OmcSchedule> omc_; // the OMC part's per-pixel samples (a split)
    // The burn-in's OMC and MLT parts, summed per pixel and channel.
    BurnInParts burn_in_parts_;                  // with a split or the two-stage target
    double omc_variance_ = 0, mlt_variance_ = 0; // V_o and V_m of split.hpp, from the burn-in
    double mlt_part_b_ = 0;       // the MLT part's mean luminance, from the whole burn-in
    std::uint32_t steps_run_ = 0; // steps of the chains (none with Split::All)
    // Fixes the two-stage target's weights from the burn-in's MLT parts so far.
    void fix_target(RankGroup& ranks);
    // The OMC part's path tracer for `split`.
    std::unique_ptr<OmcSchedule> make_omc_part(Split split) const;
    float kelemen_pb_ = 0; // p b0 of Kelemen's weights, b0 from the burn-in; 0 without
    // What the split's rule weighs, from the burn-in and the first step.
    SplitCosts split_costs() const;
    Image image_of(const Tally& summed, bool mlt, bool omc) const;
    // Runs mlt_owed in `mode` (MLT_OWED_* of cl/kernels/mlt.cl).
    void owed(std::uint32_t mode) const;
    struct BEstimate {
        double b = 0, rel_error = 0;
    };
    BEstimate b_estimate(const MltStats& s) const;
    std::uint64_t burn_in_fixed_ = 0; // sum of I over the burn-in's samples, MLT_B_FRAC_BITS
    double burn_in_sum2_ = 0, burn_in_variance_ = 0; // of I over the burn-in's samples
    std::uint64_t burn_in_samples_ = 0;
    bool prepared_ = false;
    std::uint32_t iterations_ = 0;
    double prepare_seconds_ = 0, step_seconds_ = 0; // wall time of b + chain start, of steps
};

} // namespace smallmlt
