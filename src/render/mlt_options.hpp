// An MLT render's options and the tests' hooks, with the defaults that
// the command line shares (src/app/options.cpp).
#pragma once
#include "device/memory_plan.hpp"
#include "render/mlt_film.hpp"
#include "render/omc_cells.hpp"
#include "render/split.hpp"
#include "render/strata.hpp"
#include "render/target.hpp"

#include "film_step.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

constexpr std::uint32_t kDefaultStuckRun = 1000;
// Defaults chosen by the benches of doc/RESULTS.md: Kelemen's weights, with
// which large steps pay more often than with expected values alone.
constexpr bool kDefaultKelemen = true;
constexpr float kDefaultLargeStepKelemen = 0.3f; // with burn-in and Kelemen's weights
// With those and restarts, whose samples are large steps' too
// (doc/RESULTS.md, "Large steps beside restarts").
constexpr float kDefaultLargeStepRestart = 0.1f;
constexpr float kDefaultLargeStepBurnIn = 0.1f;   // with burn-in and expected values
constexpr float kDefaultLargeStepNoBurnIn = 0.5f; // the paper's baseline without
// Kelemen's weights count this many of a chain's mutations as one
// independent sample: 3 where the chains restart, whose uniform samples are
// mostly the restarts', and 1 beside the large steps alone (doc/RESULTS.md,
// "A chain's mutations as a third of a sample").
constexpr double kDefaultMutationsPerSampleRestart = 3;
constexpr double kDefaultMutationsPerSample = 1;
// --film-step: 0 is Kelemen's step, a 64th of the film; auto is the larger of
// kFilmStepAutoShare 64ths of the film and kFilmStepFloorPixels (doc/design.md,
// "Small steps on the film"; a 32nd: doc/RESULTS.md, "A 32nd of the film").
constexpr std::uint32_t kFilmStepAuto = 0xFFFFFFFFu;
constexpr std::uint32_t kFilmStepAutoShare = 2;
constexpr std::uint32_t kFilmStepFloorPixels = 4;
constexpr std::uint32_t kDefaultFilmStep = kFilmStepAuto;
// --restart auto (restart_steps), the default: at 128x128 its block error
// is 1.8-2.2 times lower than never restarting's (doc/RESULTS.md, "The
// restarts' rounds in the split's rule").
constexpr std::uint32_t kRestartAuto = 0xFFFFFFFFu;
constexpr std::uint32_t kDefaultRestart = kRestartAuto;
// --path-step: the path numbers' largest small step is 1/kDefaultPathStep of
// their unit interval, half Kelemen's 1/64 (doc/RESULTS.md, "Path numbers'
// steps half as wide"). At most 1/1024, so that the smallest step, 1/(16 N),
// is still 4 grid steps of a 16-bit slot.
constexpr std::uint32_t kDefaultPathStep = 128;
constexpr std::uint32_t kPathStepMin = 16, kPathStepMax = 1024;

// What tests change in an MLT render besides its options, passed to the
// renderer apart from them (the command line never sets these): reference
// builds to compare against, and the program's evaluator and probes.
struct MltTestHooks {
    bool float32_states = false; // unpacked float32 states
    bool eager_stay = false;     // splat x's stay weight at every step
    // Kelemen's weights from this multiple of b0: a deliberately wrong b0,
    // which must leave the image unbiased.
    double b0_scale = 1;
    // The file that defines eval_state: cl/path/eval_path.cl renders the
    // scene; the sampler tests use test/cl/eval_target.cl, a known target
    // (2D, or with bounces on a layout that has bounce slots).
    std::string evaluator = "cl/path/eval_path.cl";
    std::vector<std::string> extra_files; // appended to the program (test probes)
    // A target of weight 0 in the cells of `cells` that `zero_cells` marks,
    // from the start, as if the OMC part rendered them whole: the known
    // target with holes (empty: none).
    TargetCells cells = target_one_cell();
    std::vector<bool> zero_cells;
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
    // drawn from all rounds' samples in proportion to luminance (systematic
    // resampling along the film, StartPicks). All threads x iters samples
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
    // the time the rule of split.hpp gives it (kDefaultOmcEffort), and by
    // the burn-in's paths.
    Split split = kDefaultSplit;
    double omc_effort = kDefaultOmcEffort;
    // With a split, the cells whose MLT part path tracing renders well go
    // to the OMC part whole (src/render/omc_cells.hpp).
    bool omc_cells = kDefaultOmcCells;
    // The chains' target (src/render/target.hpp).
    Target target = kDefaultTarget;
    // Kelemen's weights (Kelemen et al. 2002, section 5; cl/mlt/mlt_step.cl):
    // large steps also count as independent samples, combined with the
    // chains' expected values by the balance heuristic. Off: expected values
    // alone, and the image's mean is b.
    bool kelemen = kDefaultKelemen;
    // Kelemen's weights take the chains' density as I/b over this: M of a
    // chain's mutations count as one independent sample beside the large
    // steps' and the restarts' samples. Any M > 0 leaves the image unbiased
    // (doc/design.md, "Kelemen's weights"); it only moves light between the
    // two estimates. Unset: default_mutations_per_sample (mutations_per_sample_of).
    std::optional<double> mutations_per_sample;
    // Stratified MLT (src/render/strata.hpp): the tiles' side in pixels, 0
    // for none (one tile, the whole film), kStrataAuto for the rule's,
    // kStrataPiles for the rule's where the chains pile up (strata_for_piles).
    std::uint32_t strata = kStrataPiles;
    // The largest small step of the film numbers, in pixels (0: a 64th of
    // the film, Kelemen's 2^-6 of the unit square; cl/sampling/sample_chain.cl).
    std::uint32_t film_step = kDefaultFilmStep;
    // The largest small step of the path's numbers (all but the film's two)
    // is 1/path_step of their unit interval, the smallest 1/16 of that: a
    // power of two, the kernels' MLT_PATH_STEP_LOG2 (cl/sampling/sample_chain.cl).
    std::uint32_t path_step = kDefaultPathStep;
    // Every `restart` steps, each chain starts again at a pick of
    // burn_in_iters fresh burn-in rounds (MltBurnIn::restart_rounds): more, shorter
    // chains in the same memory. 0: never; kRestartAuto: restart_steps's rule.
    std::uint32_t restart = kDefaultRestart;
};

// The large step's probability where none is given: it depends on burn-in,
// the weights and whether chains restart.
constexpr float default_large_step(bool burn_in, bool kelemen, bool restarts = false) {
    return !burn_in   ? kDefaultLargeStepNoBurnIn
           : !kelemen ? kDefaultLargeStepBurnIn
           : restarts ? kDefaultLargeStepRestart
                      : kDefaultLargeStepKelemen;
}
// Whether the chains of a render of `opt` restart: --restart auto counts
// once resolved to steps (MltRenderer::prepare), not before.
inline bool restarts_resolved(const MltOptions& opt) {
    return opt.restart != 0 && opt.restart != kRestartAuto;
}
// The large step's probability of a render of `opt`.
inline float large_step_of(const MltOptions& opt) {
    return opt.large_step.value_or(
        default_large_step(opt.burn_in, opt.kelemen, restarts_resolved(opt)));
}

// M, the chain's mutations that Kelemen's weights count as one sample,
// where none is given: it depends on whether chains restart.
constexpr double default_mutations_per_sample(bool restarts) {
    return restarts ? kDefaultMutationsPerSampleRestart : kDefaultMutationsPerSample;
}
// M of a render of `opt`, once --restart auto is resolved.
inline double mutations_per_sample_of(const MltOptions& opt) {
    return opt.mutations_per_sample.value_or(default_mutations_per_sample(restarts_resolved(opt)));
}

// --film-step's pixels asked for (0: film_step_share 64ths of the film, with
// the floor of film_step_floor), share and floor (0: none), the kernels'
// MLT_FILM_STEP, MLT_FILM_STEP_SHARE and MLT_FILM_STEP_FLOOR
// (cl/core/film_step.h).
inline std::uint32_t film_step_asked(const MltOptions& opt) {
    return opt.film_step == kFilmStepAuto ? 0 : opt.film_step;
}
inline std::uint32_t film_step_share(const MltOptions& opt) {
    return opt.film_step == kFilmStepAuto ? kFilmStepAutoShare : 1;
}
inline std::uint32_t film_step_floor(const MltOptions& opt) {
    return opt.film_step == kFilmStepAuto ? kFilmStepFloorPixels : 0;
}

// The largest small step on a film `width` pixels wide, in pixels, of a
// chain on the whole film.
inline std::uint32_t film_step_pixels(const MltOptions& opt, std::uint32_t width) {
    return film_step_pixels_of(width,
                               film_step_stretch(width, 1, film_step_asked(opt),
                                                 film_step_share(opt), film_step_floor(opt)));
}

// Kelemen's weights in force: asked for, with large steps to weigh.
inline bool kelemen_in_force(const MltOptions& opt) {
    return opt.kelemen && large_step_of(opt) > 0;
}

// --restart auto: every kRestartAutoSteps steps where the chains are at
// least the film's pixels and the restarts' samples are large steps'
// (Kelemen's weights, with burn-in); where they are fewer, every
// kRestartPileSteps steps where the burn-in shows the chains piling up
// (restart_pile_steps); else never (doc/design.md, "Restarts"). Where
// chains are fewer than pixels the restarts lose by MSE but for such
// piles. Every 8
// steps, not 16: at 128x128 the 8x8-block error then falls below path
// tracing's on cornell-water, cornell-glass and ajar, for 1-14% more MSE
// (doc/RESULTS.md, "The restarts' rounds in the split's rule").
constexpr std::uint32_t kRestartAutoSteps = 8;
// The steps between restarts of a render of `opt` with `chains` chains on
// a film of `pixels`, the same on every rank that has as many.
inline std::uint32_t restart_steps(const MltOptions& opt, std::uint64_t chains,
                                   std::uint64_t pixels) {
    if (opt.restart != kRestartAuto) return opt.restart;
    return kelemen_in_force(opt) && opt.burn_in && chains >= pixels ? kRestartAutoSteps : 0;
}
// Chains started on one burn-in path stay together until their steps part
// them, and on a path far brighter than b that can take the whole render:
// the image then holds that path's light at the burn-in's samples per
// pixel, 2 at 512x512 on 2 cores. There (16,384 chains, seeds 1-4) the
// brightest path took 0.03-0.08% of the chains on cornell-water,
// cornell-glass, ajar and cornell-glossy, 0.12-0.38% on veach-mis, and
// 14.6-15.1% on tiny-caustic at the three seeds whose burn-in found a path
// from the ceiling through the ball to the spark (0.015% at the fourth):
// some 2,400 chains on one pixel, 59 times path tracing's MSE over the
// film. Restarting every 16 steps brought that to 2.0-2.4 times, where on the
// four others it cost 1.2-1.6 times the MSE (doc/RESULTS.md, "Piles of
// chains on one path").
constexpr double kPileShare = 0.01;
// Whether a burn-in that started a share `largest_share` of the chains on
// its brightest path piled them on it.
inline bool piled_on_one_path(double largest_share) {
    return largest_share > kPileShare;
}
// Chains pile up too on small areas far brighter than b, where they stay
// until a large step takes them away (chain_correlation): the OMC part's
// cells take such areas where path tracing renders them well, and the rest
// of that error, before any cell goes, is `stay` of omc_cells, over the
// error the chains would have were they free. At 512x512 (seeds 1-4) it
// was 0.0012-0.20 on the bench's other scenes and 2.7-3.7 on veach-mis,
// whose lamps' images on the plates held the chains: 8x8-block error 7.0
// times PT's, 1.15 with these restarts and the cells chosen for them
// (MltBurnIn::fix_target; doc/RESULTS.md, "Piles of chains on one path").
// That is the stay by each pixel's own samples (ChainsStay::own), which
// reads high where they are few: with more it fell to 0.28-0.70 on
// veach-mis (5.3 to 43 burn-in samples per pixel) and would not restart
// it. The stay by the neighbours' samples read 0.05-0.36 there from 1.3
// samples per pixel on, and at most 0.009 on the bench's other scenes but
// tiny-caustic at 32, 0.018-0.041 where its own stay was above 1 too:
// it restarts above kPileStayNeighbours (doc/RESULTS.md, "The chains'
// stay, two ways").
constexpr double kPileStay = 1.0;
constexpr double kPileStayNeighbours = 0.03;
constexpr std::uint32_t kRestartPileSteps = 16;
// Whether chains whose stay is `stay` would stay on small bright areas for
// long enough that restarting them pays: where either measure says so.
inline bool chains_would_stay(const ChainsStay& stay) {
    return stay.own > kPileStay || stay.neighbours > kPileStayNeighbours;
}
// --restart auto's steps between restarts, where restart_steps gave none,
// after a burn-in that started a share `largest_share` of the chains on its
// brightest path and found the chains' stay `stay`.
inline std::uint32_t restart_pile_steps(const MltOptions& opt, double largest_share,
                                        const ChainsStay& stay) {
    return opt.restart == kRestartAuto && kelemen_in_force(opt) && opt.burn_in &&
                   (piled_on_one_path(largest_share) || chains_would_stay(stay))
               ? kRestartPileSteps
               : 0;
}
// --strata piles: the tiles of auto where the burn-in that started a share
// `largest_share` of the chains on its brightest path piled them on it,
// else none. A restart's pile then forms among one tile's chains and holds
// that tile's light, not the film's: tiny-caustic at 512x512 (eight seeds
// of 20 s, four of them piled) read 1.05 / 1.37 / 1.33 times path
// tracing's MSE / 8x8 / 32x32 error without strata, 0.15 / 0.19 / 0.27
// with these. On the bench's other scenes, where no burn-in piles, strata
// cost up to 1.25 times the MSE and 1.34 times the 8x8 blocks
// (doc/RESULTS.md, "Piles of chains on one path").
inline bool strata_for_piles(const MltOptions& opt, double largest_share) {
    return opt.strata == kStrataPiles && piled_on_one_path(largest_share);
}
// The burn-in rounds, a path per thread each, that a step runs for the next
// restart: B / R (MltRenderer::restart_work); 0 without restarts, or before
// --restart auto is resolved.
inline double restart_rounds_per_step(const MltOptions& opt) {
    return restarts_resolved(opt) && opt.burn_in ? double(opt.burn_in_iters) / double(opt.restart)
                                                 : 0.0;
}

// The OMC part's cells in force: asked for, with a split and burn-in rounds
// to choose them from before the rounds that estimate b.
inline bool omc_cells_in_force(const MltOptions& opt) {
    return opt.omc_cells && opt.split != Split::None && opt.split != Split::All &&
           opt.burn_in_iters >= 2;
}

// The burn-in's rounds that choose the OMC part's cells, before the usual
// ones (MltBurnIn::run): half as many as --burn-in-iters, or none.
inline std::uint32_t omc_cell_rounds(const MltOptions& opt) {
    return omc_cells_in_force(opt) ? opt.burn_in_iters / 2 : 0;
}

// The burn-in's rounds: --burn-in-iters and the cells' before them.
inline std::uint32_t burn_in_rounds(const MltOptions& opt) {
    return (opt.burn_in_iters > 1 ? opt.burn_in_iters : 1) + omc_cell_rounds(opt);
}

// What the memory plan needs to know of a render of `opt` (one definition
// for the renderer, `render --threads auto` and `budget`).
inline ChainShape mlt_chain_shape(const MltOptions& opt, const MltTestHooks& hooks = {}) {
    ChainShape s;
    s.threads = opt.threads;
    s.proposals = opt.proposals;
    s.float32_states = hooks.float32_states;
    s.film_atomics64 = opt.film_atomics64;
    s.omc_part = opt.split != Split::None;
    s.target_cells =
        opt.target == Target::TwoStage || omc_cells_in_force(opt) || !hooks.zero_cells.empty()
            ? kTargetMaxCells
            : 1;
    s.film_layers = kelemen_in_force(opt) ? 2 : 1;
    s.strata = opt.strata != 0;
    return s;
}

} // namespace smallmlt
