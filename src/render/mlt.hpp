// Primary-sample-space MLT on the device (cl/kernels/mlt.cl): N chains, one
// per work-item, with packed states and lazy proposals. The host estimates
// the normalization b, starts the chains, runs steps and assembles the image.
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "image/image.hpp"
#include "render/burn_in.hpp"
#include "render/integrator.hpp"
#include "render/mlt_burn_in.hpp"
#include "render/mlt_film.hpp"
#include "render/mlt_options.hpp"
#include "render/mlt_report.hpp"
#include "render/mlt_stats.hpp"
#include "render/mlt_tally.hpp"
#include "render/omc_schedule.hpp"
#include "render/split.hpp"
#include "render/strata.hpp"
#include "render/strata_buffer.hpp"
#include "render/target_buffer.hpp"
#include "scene/device_scene.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

// Throws InputError naming the device if it lacks what the options need:
// 64-bit atomics for the 64-bit reference film.
void mlt_require_device(const DeviceInfo& d, const MltOptions& opt);

// Kernel files of the MLT program, in build order.
std::vector<std::string> mlt_program_files(const MltTestHooks& hooks = {});

class MltRenderer : public Integrator {
  public:
    MltRenderer(const ClContext& cl, const DeviceScene& ds, const MltOptions& opt,
                const MltTestHooks& hooks = {});
    MltRenderer(const MltRenderer&) = delete; // burn_in_ refers to opt_
    MltRenderer& operator=(const MltRenderer&) = delete;

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

    // Runs the OMC samples of burn-in (src/render/mlt_burn_in.hpp): the
    // first estimate of b, the tiles of --strata piles (kept or dropped),
    // and the chains' starting samples (burn-in or fresh).
    void sample_starts(RankGroup& ranks);
    void sample_starts() {
        SingleRank one;
        sample_starts(one);
    }
    // b, the mean luminance I of the OMC samples drawn so far: the burn-in's
    // and every large step's (each an OMC sample of I, weighed by its
    // density, StratumWeights), so b keeps converging
    // as the render goes on; and its relative standard error, from the
    // burn-in's per-sample variance over all of them.
    double b() const;
    double b_rel_error() const;
    // The share of the chains the burn-in started on its brightest path
    // (MltBurnIn::largest_start_share), which --restart auto reads.
    double largest_start_share() const { return burn_in_.largest_start_share(); }
    // The chains' error where they would stay over their error were they
    // free, as the OMC part's cells found it (MltBurnIn::chains_stay).
    const std::optional<ChainsStay>& chains_stay() const { return burn_in_.chains_stay(); }

    // Starts every chain at its starting sample's path.
    void init_chains() { init_chains(burn_in_film_); }
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
    // Per tile of the strata (one without), (B * chains' splats + B0 *
    // large steps' splats) * the tile's pixels / its mutations, B the tile's
    // mean of I from the summed samples (mlt_tile_b; with one tile, b) and
    // B0 that of Kelemen's weights (the
    // balance heuristic's two estimates, src/render/mlt_options.hpp: the
    // chains' is normalized by b, the large steps' by the b0 their weights
    // took; with b in place of b0 the image would tend to
    // F (I + p b) / (I + p b0), off where I is small), plus the OMC part of a
    // split: per pixel, the sum of its per-pixel samples and
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
    double omc_rate() const { return omc_ ? omc_->rate().film : 0; }
    std::uint32_t omc_spp() const { return omc_ ? omc_->part().spp() : 0; }
    // Those of the cells the OMC part renders whole.
    double omc_cell_rate() const { return omc_ ? omc_->rate().cells : 0; }
    std::uint32_t omc_cell_spp() const { return omc_ ? omc_->part().cell_spp() : 0; }
    // The split in force: opt.split, with Auto decided by prepare().
    Split split() const { return split_; }
    // r and s of chains_pay (src/render/split.hpp), from the burn-in.
    double mlt_relative_variance() const;
    double behind_specular_share() const { return burn_in_.split_evidence().behind_share; }
    const MltFilm& film() const { return film_; }
    // The strata: the tiles, and the tile of each work-group of chains.
    const StrataGrid& strata_grid() const { return grid_; }
    const std::vector<std::uint32_t>& group_tiles() const { return strata_.group_tiles(); }
    // B per tile (b with one tile), from the samples so far.
    std::vector<double> tile_b() const;
    // Where the burn-in's samples lie on the film, what they left per pixel,
    // and the numbers of the OMC part's Sobol samples (after the burn-in's;
    // none without an OMC part).
    const BurnInFilm& burn_in_film() const { return burn_in_film_; }
    const BurnInParts& burn_in_parts() const { return burn_in_.parts(); }
    const PtNumbering* omc_numbering() const { return omc_ ? &omc_->part().numbering() : nullptr; }

  private:
    // The pick's paths lie on `film`.
    void init_chains(const BurnInFilm& film);
    // The tiles of `grid` in place of grid_'s, after the burn-in's rounds
    // and before the chains start (each tile of grid_ within one of grid's).
    void set_grid(StrataGrid grid);
    // --strata piles, after the burn-in's rounds: whether the render keeps
    // grid_'s tiles. Yes where some rank's burn-in piled its chains on one
    // path (strata_for_piles) and every rank has as many tiles, more than
    // one; the same answer on every rank.
    bool piles_keep_tiles(RankGroup& ranks) const;
    // What each tile's large steps weigh, once the target is fixed: their
    // density q on its chains' part and, with Kelemen's weights, p q b0.
    void set_stratum_weights(RankGroup& ranks);
    // --restart, after each step: the next restart's share of burn-in
    // rounds and, where `restart` (the chains have splatted what they owe),
    // every chain's new start among them.
    void restart_work(bool restart);
    // Where the restarts' rounds lie on the film: one film for all of them.
    BurnInFilm restart_film() const;
    // The tests' view of the device's buffers and program, for their probes
    // (test/test_support.hpp).
    friend struct MltInspect;
    const ClContext& cl_;
    const DeviceScene& ds_;
    MltOptions opt_;
    MltTestHooks hooks_;
    MemoryPlan plan_; // sizes of every buffer below (src/device/memory_plan.cpp)
    ClProgram program_;
    ClKernel k_init_, k_step_;
    mutable ClKernel k_owed_; // run by image(), which leaves the film as it was
    SceneBuffers scene_;
    ClBuffer state_, values_, stats_, picks_;
    TargetBuffer target_;     // one cell of weight 1 until two-stage fixes them
    StrataGrid grid_;         // the strata's tiles (src/render/strata.hpp)
    StrataBuffer strata_;     // the tiles, the groups' tiles and p b0 per tile
    BurnInFilm burn_in_film_; // where the burn-in's samples lie on the film
    std::uint32_t restarts_ = 0;
    MltBurnIn burn_in_;
    MltFilm film_;
    Split split_;
    std::unique_ptr<OmcSchedule> omc_; // the OMC part's per-pixel samples (a split)
    std::uint32_t steps_run_ = 0;      // steps of the chains (none with Split::All)
    // The OMC part's path tracer for `split`.
    std::unique_ptr<OmcSchedule> make_omc_part(Split split) const;
    // Kelemen's weights, per tile: c B0, B0 from every rank's burn-in, and
    // B0 itself, which scales the large steps' layer of the film; 0 without.
    // c, the uniform samples per mutation, is kelemen_rate_: the large
    // steps' p q (kelemen_large_) and the restarts' samples (restart_rate).
    std::vector<float> kelemen_pb_;
    std::vector<double> kelemen_b0_, kelemen_large_, kelemen_rate_;
    // Per tile, the restarts' burn-in samples that land in it per mutation
    // of its chains, over every rank (--restart with burn-in; else 0).
    std::vector<double> restart_rate(RankGroup& ranks) const;
    // What the split's rule weighs, from the burn-in and the first step.
    SplitCosts split_costs() const;
    Image image_of(const Tally& summed, bool mlt, bool omc) const;
    // Adds each tile's mutations and large steps (from its work-groups' rows
    // of counters) and its burn-in sums to t.
    void tile_counts(MltTally& t) const;
    // The threads of work-group g (the last may be partial; 0 past them).
    std::uint64_t group_threads(std::size_t g) const;
    // B per tile from a tally's sums (mlt_tile_b).
    std::vector<double> tile_b_of(const MltTally& t) const;
    // Runs mlt_owed in `mode` (MLT_OWED_*, cl/core/shared_types.h).
    void owed(std::uint32_t mode) const;
    BEstimate b_estimate(const MltStats& s) const;
    bool prepared_ = false;
    std::uint32_t iterations_ = 0;
    double prepare_seconds_ = 0, step_seconds_ = 0; // wall time of b + chain start, of steps
};

} // namespace smallmlt
