// The burn-in of an MLT render by OMC (Frolov and Galaktionov, section
// 3.1): rounds of one OMC sample per thread (cl/kernels/mlt.cl,
// mlt_luminance) that pick the chains' starts (StartPicks), make b's first
// estimate, and, for a split or the two-stage target, leave their paths'
// parts per pixel (BurnInParts). With the two-stage target, the first half
// of the rounds fixes the target's weights and only the second estimates b
// and picks the starts.
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "render/burn_in.hpp"
#include "render/mlt_film.hpp"
#include "render/mlt_options.hpp"
#include "render/ranks.hpp"
#include "render/start_picks.hpp"
#include "render/strata_buffer.hpp"
#include "render/target_buffer.hpp"

#include <cstdint>
#include <optional>

namespace smallmlt {

// b from a fixed-point sum of `samples` luminances (cl/core/fixed_point.h).
double mlt_b(std::uint64_t lum_fixed, std::uint64_t samples);
// A tile's B, the mean of I over it (src/render/strata.hpp): the fixed-point
// luminance sums of the burn-in's samples that landed in it and of its
// `large` large steps, over the samples the burn-in's `samples` put there in
// expectation (samples x area, area its share of the film) and the large
// steps. Unbiased: a burn-in sample lands in the tile with probability area
// and is then uniform in it, and a large step is uniform in it. With one
// tile, area 1: mlt_b of the sums.
double mlt_tile_b(std::uint64_t burn_in_lum, std::uint64_t samples, double area,
                  std::uint64_t large_lum, std::uint64_t large);

// b and its relative standard error.
struct BEstimate {
    double b = 0, rel_error = 0;
};

// What b's estimate sums over the burn-in's samples (those that estimate
// b: after the two-stage target is fixed).
struct BurnInSums {
    std::uint64_t lum_fixed = 0; // sum of I, MLT_B_FRAC_BITS fixed point
    std::uint64_t samples = 0;
    std::vector<std::uint64_t> tile_lum; // lum_fixed of the samples in each tile
    double lum2 = 0;                     // sum of I^2
    double variance = 0;                 // of one sample's I (unbiased)
    std::uint64_t restart_samples = 0;   // of those, the restarts' (--restart)
    void update_variance();              // from the sums above
    // b from these and `large` large steps of fixed-point sum large_lum
    // (each an OMC sample of I), with the error of the burn-in's variance
    // over all of them.
    BEstimate b(std::uint64_t large_lum = 0, std::uint64_t large = 0) const;
};

class MltBurnIn {
  public:
    // The device's buffers a burn-in writes: the chains' states (scratch for
    // the paths), the step counters, and one pick (round, index) per chain.
    struct Chains {
        const ClBuffer &state, &stats, &picks;
        std::uint32_t count;
    };
    // `program` holds mlt_luminance and the picker's kernels; the parts per
    // pixel are kept for `pixels` pixels where `opt` needs them. `opt` is
    // the renderer's and outlives this (its --restart auto resolved by
    // MltRenderer::prepare before run()).
    MltBurnIn(const ClContext& cl, cl_program program, const MltOptions& opt, std::uint64_t pixels);
    // Runs every round on the rank (ranks meet only where the target is
    // fixed), its sums by the tiles of `grid`; start_chains then starts the
    // chains.
    void run(RankGroup& ranks, const MemoryPlan& plan, const SceneBuffers& scene,
             TargetBuffer& target, const BurnInFilm& film, const Chains& chains,
             const StrataGrid& grid, StrataBuffer& strata, MltFilm& image);
    // After run(): the tiles of `to` in place of run()'s `from` (each tile of
    // `from` within one of `to`; films `width` pixels wide): b's sums, the
    // deal's luminances and the draw's layout by the tiles of `to`.
    void regrid(const StrataGrid& from, const StrataGrid& to, std::uint32_t width);
    // After run(): deals the chains' work-groups to the tiles
    // (strata_groups, by each tile's luminance in the first round that
    // estimates b), and each chain picks its start among its tile's samples.
    // Without burn-in, the picks are fresh samples.
    void start_chains(const Chains& chains, StrataBuffer& strata);

    // The rounds of the next restart (--restart), a few at a time: `rounds`
    // more rounds of the burn-in, numbered after every round so far and
    // placed on the film by `film` (the same film until restart_picks),
    // added to the pool the chains will pick from. Their samples add to b's
    // sums (and so to each tile's B); those in the OMC part's cells add to
    // the parts, so their whole paths are the cells' per-pixel samples too;
    // with Kelemen's weights they are large steps' samples in `image`'s
    // large steps' layer, which is then drained. Nothing without burn-in.
    void restart_rounds(const MemoryPlan& plan, const SceneBuffers& scene, TargetBuffer& target,
                        const BurnInFilm& film, const Chains& chains, const StrataGrid& grid,
                        const StrataBuffer& strata, std::uint32_t rounds, MltFilm& image);
    // Draws every chain's start anew from the pool of restart_rounds, as
    // run() did, and empties the pool; without burn-in, fresh samples of a
    // round of their own.
    void restart_picks(const Chains& chains, const StrataBuffer& strata);
    const BurnInSums& sums() const { return sums_; }
    // Per tile, B of every rank's burn-in samples (a collective; the same on
    // every rank): b0, the normalization Kelemen's weights take.
    std::vector<double> ranks_b(RankGroup& ranks, const StrataGrid& grid) const;
    // The paths' parts per pixel; empty unless a split or the two-stage
    // target needs them.
    const BurnInParts& parts() const { return parts_; }
    bool keeps_parts() const { return !parts_.count.empty(); }
    // Once the split is known: the paths of the rounds that chose the OMC
    // part's cells, which parts() left out, join it where `whole` (no chain
    // runs, and path tracing takes every round's whole paths), else go.
    void settle_cell_rounds(bool whole);
    // V_o and V_c of split.hpp (the film but the OMC part's cells, and
    // those) and the MLT part's mean luminance, from the parts (0 without
    // them).
    double omc_variance() const { return omc_variance_; }
    double cell_variance() const { return cell_variance_; }
    double mlt_part_b() const { return mlt_part_b_; }
    // The share of the chains that run() started on its brightest sample
    // (StartPicks::largest_share; 0 without burn-in).
    double largest_start_share() const { return largest_start_share_; }
    // The chains' error where they would stay on small bright areas, over
    // their error were they free, as the OMC part's cells found it for the
    // steps of --restart auto before it resolves (omc_cells' `stay`); none
    // where the cells were not chosen.
    const std::optional<ChainsStay>& chains_stay() const { return chains_stay_; }
    // What --split auto decides by (split.hpp, chains_pay): V_m, the MLT
    // part's mean luminance and the share of its light behind smooth
    // transmitters, from the parts before any cell went to the OMC part.
    struct SplitEvidence {
        double mlt_variance = 0, mlt_part_b = 0, behind_share = 0;
    };
    const SplitEvidence& split_evidence() const { return evidence_; }

  private:
    // What the rounds of one run() or restart_rounds() share.
    struct Round {
        const SceneBuffers& scene;
        TargetBuffer& target;
        const BurnInFilm& film;
        const Chains& chains;
        const StrataGrid& grid;
        const StrataBuffer& strata;
        MltFilm& image;
        bool splat; // the samples go to image's large steps' layer
        const ClBuffer &lum, &omc;
    };
    // lum_ and omc_, allocated once: the plan counts them for the whole
    // render, and the restarts' rounds reuse them.
    void allocate_rounds(const MemoryPlan& plan);
    // Which of a round's paths add to the parts.
    enum class Parts { None, All, Cells };
    void sample_round(const Round& r, std::uint32_t it, Parts parts, BurnInSums& s);
    // Fixes the target from the parts so far (TargetBuffer::fix); where
    // cells go to the OMC part, those parts are dropped. The cells are for
    // the chains' steps, those of restarting chains where the chains' stay
    // will make --restart auto restart (restart_pile_steps). True where the
    // target changed (the two-stage weights, cells of weight 0): samples
    // drawn before then are then not the target's.
    bool fix_target(RankGroup& ranks, const SceneBuffers& scene, TargetBuffer& target,
                    bool two_stage, bool omc);
    static SplitEvidence split_evidence(const BurnInParts& parts);
    // Each chain c's pick is (round rounds_, c), a fresh sample; then rounds_ + 1.
    void fresh_picks(const Chains& chains);
    // Each chain's pick drawn by `picks` (its tile's, by `strata`).
    void write_picks(const StartPicks& picks, const Chains& chains, const StrataBuffer& strata);

    const ClContext& cl_;
    cl_program program_;
    const MltOptions& opt_;
    ClKernel k_lum_;
    BurnInParts parts_;
    BurnInWhole cell_rounds_; // the paths of the rounds that chose the cells
    BurnInSums sums_;
    double omc_variance_ = 0, cell_variance_ = 0, mlt_part_b_ = 0, largest_start_share_ = 0;
    std::optional<ChainsStay> chains_stay_;
    SplitEvidence evidence_;
    std::uint32_t rounds_ = 0;        // rounds run, those of restarts included
    std::optional<StartPicks> picks_; // run()'s rounds, until start_chains
    std::vector<double> deal_lum_;    // per tile, the first round of b's luminance
    std::optional<StartPicks> pool_;  // the next restart's rounds so far
    std::vector<float> host_, host_omc_;
    std::vector<double> round_lum_;
    std::vector<bool> cell_pixels_; // per pixel: in an OMC part's cell (set at the first restart)
    // A round's luminances, and its samples' parts where keeps_parts().
    ClBuffer lum_, omc_;
};

} // namespace smallmlt
