// The words an MLT render reports: its summary line and its notes to the
// user, made from a plain account of the render (MltRenderer::report).
#pragma once
#include "render/mlt_stats.hpp"
#include "render/omc_cells.hpp"
#include "render/split.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

// Above this relative standard error of b, a render says so (b scales the
// whole image; its error is not reduced by running the chains longer).
constexpr double kMaxBRelError = 0.01;

struct MltReport {
    MltStats stats;
    double b = 0, b_rel_error = 0;
    bool prepared = false, finished = false;
    Split split = Split::None, split_asked = Split::None; // in force; as asked (Auto)
    bool burn_in_lit = false;          // some burn-in sample carried light (b > 0)
    std::uint64_t burn_in_samples = 0; // threads x rounds
    double burn_in_spp = 0;            // the burn-in's samples per pixel
    std::uint32_t chains = 0, proposals = 1, steps = 0, iterations = 0, state_bytes = 0;
    std::uint32_t stuck_run = 0;
    double prepare_seconds = 0, step_seconds = 0; // b and chain start; steps
    bool omc_part = false;                        // a split's OMC part
    std::uint32_t omc_spp = 0;
    double omc_rate = 0, mlt_relative_variance = 0, behind_specular_share = 0;
    std::uint32_t omc_cell_spp = 0; // in the cells the OMC part renders whole
    double omc_cell_rate = 0;
    bool kelemen = false;
    float kelemen_pb = 0; // M c b0: c the uniform samples per mutation, M mutations a sample
    double mutations_per_sample = 1;
    std::uint32_t restart_every = 0, restarts = 0; // --restart's steps; restarts so far
    // Where the chains would stay on small bright areas, their error over
    // their error were they free (MltBurnIn::chains_stay); none where the
    // cells were not chosen.
    std::optional<ChainsStay> chains_stay;
    bool restart_samples = false; // the restarts' burn-in samples are large steps'
    std::uint32_t strata = 1;     // tiles of stratified MLT
    bool strata_piles = false;    // those of --strata piles, kept
    bool two_stage = false;
    std::uint32_t target_cells = 1;
    std::uint32_t omc_cells = 0; // cells the OMC part renders whole
    double omc_cell_share = 0;   // the share of the film they cover
};

// The summary line: chains, throughput, acceptance, b, stuck chains, the
// split's and the weights' figures.
std::string mlt_summary(const MltReport& r);
// What the user should know: dropped samples, a split that ran no chain, an
// unlit burn-in, light behind glass the burn-in missed, an uncertain b,
// stuck chains, few steps after the burn-in.
std::vector<std::string> mlt_notes(const MltReport& r);

} // namespace smallmlt
