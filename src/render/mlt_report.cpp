#include "render/mlt_report.hpp"

#include "render/mlt_options.hpp"

#include <cstdio>

namespace smallmlt {

namespace {
// Below this many steps a render says that its chains' part rests on them
// (a burn-in that took most of --time).
constexpr std::uint32_t kFewSteps = 4;
} // namespace

std::vector<std::string> mlt_notes(const MltReport& r) {
    std::vector<std::string> out;
    const MltStats& s = r.stats;
    if (std::uint64_t n = s.nonfinite)
        out.push_back(
            std::to_string(n) +
            " samples had a NaN or infinite radiance and were dropped (counted as black)");
    const bool restarting = r.restart_every != 0;
    if (r.prepared && r.split == Split::All && r.split_asked == Split::Auto)
        out.push_back("path tracing renders this scene's light well (the MLT part's relative "
                      "variance is below " +
                      std::to_string(int(chains_pay_ratio(restarting))) +
                      (restarting ? ", as the chains would restart" : "") +
                      "), so no chain ran: --split visible runs them anyway");
    if (r.prepared && r.split != Split::All && r.omc_part &&
        r.mlt_relative_variance <= chains_pay_ratio(restarting) &&
        r.behind_specular_share > kChainsPayBehindShare) {
        char buf[400];
        std::snprintf(buf, sizeof buf,
                      "%.0f%% of the light the burn-in's paths aimed at lay behind glass or "
                      "water, which path tracing finds only by hitting the light, and its paths "
                      "found little of it: b = %.5g may leave that light out, and the chains' "
                      "part of the image is then too dark until large steps find it",
                      100.0 * r.behind_specular_share, r.b);
        out.push_back(buf);
    }
    if (r.prepared && !r.burn_in_lit && !r.finished)
        out.push_back("no OMC sample of the burn-in carried light in the MLT part (b = 0): the "
                      "chains had nothing to render, and the time went to the OMC part");
    if (r.finished)
        out.push_back("no OMC sample of " + std::to_string(r.burn_in_samples) +
                      " carried light (b = 0): the image is black; is the scene lit?");
    else if (r.prepared && r.split != Split::All && r.b_rel_error > kMaxBRelError) {
        char buf[240];
        std::snprintf(buf, sizeof buf,
                      "few OMC samples carried light: b = %.5g has a relative standard error "
                      "of %.2f%% (above %.0f%%), and the whole image scales with it; more "
                      "--burn-in-iters, --threads or a longer render narrow it",
                      r.b, 100.0 * r.b_rel_error, 100.0 * kMaxBRelError);
        out.push_back(buf);
    }
    if (s.stuck > 0) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "%llu of %u chains (%.2f%%) stayed on one path for %u steps or more "
                      "(longest %llu): expect bright blotches where they stayed, fading as "
                      "the render goes on (doc/stability.md)",
                      static_cast<unsigned long long>(s.stuck), r.chains,
                      100.0 * double(s.stuck) / r.chains, r.stuck_run,
                      static_cast<unsigned long long>(s.longest_run));
        out.push_back(buf);
    }
    if (r.prepared && r.burn_in_lit && r.split != Split::All && r.steps < kFewSteps) {
        char buf[240];
        std::snprintf(buf, sizeof buf,
                      "only %u MLT step(s) ran, after a burn-in of %.2f s: the chains' part "
                      "of the image rests on them alone; give more time or fewer "
                      "--burn-in-iters",
                      r.steps, r.prepare_seconds);
        out.push_back(buf);
    }
    return out;
}

std::string mlt_summary(const MltReport& r) {
    const MltStats& s = r.stats;
    double per_s = r.step_seconds > 0 ? 1e-6 / r.step_seconds : 0.0;
    double per_mutation = s.mutations ? 100.0 / double(s.mutations) : 0.0;
    char buf[480];
    std::snprintf(buf, sizeof buf,
                  "%u chains x %u proposals x %u steps (state %u B/chain), %.4g M mutations/s, "
                  "%.4g M rays/s (steps only; b and chain start %.2f s), acceptance %.1f%%, "
                  "large steps %.1f%%, %.2f global atomics/mutation, b = %.5g (+-%.2f%%), "
                  "%llu non-finite dropped, "
                  "longest run of rejections %llu, %llu chains stuck (%u in a row)",
                  r.chains, r.proposals, r.steps, r.state_bytes, double(s.mutations) * per_s,
                  double(s.rays) * per_s, r.prepare_seconds, double(s.accepted) * per_mutation,
                  double(s.large) * per_mutation,
                  s.mutations ? double(s.atomics) / double(s.mutations) : 0.0, r.b,
                  100.0 * r.b_rel_error, static_cast<unsigned long long>(s.nonfinite),
                  static_cast<unsigned long long>(s.longest_run),
                  static_cast<unsigned long long>(s.stuck), r.stuck_run);
    std::string out = buf;
    if (r.omc_part) {
        std::snprintf(buf, sizeof buf,
                      "; split %s%s: OMC part %u spp + %.1f from burn-in (%.3g spp per step), "
                      "MLT part's relative variance %.3g, %.3g%% of its light behind glass",
                      split_name(r.split), r.split_asked == Split::Auto ? " (auto)" : "", r.omc_spp,
                      r.burn_in_spp, r.omc_rate, r.mlt_relative_variance,
                      100.0 * r.behind_specular_share);
        out += buf;
    }
    if (r.kelemen && r.steps > 0) {
        std::snprintf(buf, sizeof buf,
                      "; Kelemen's weights (M %s b0 = %.4g, M = %.3g mutations a sample)",
                      r.restart_samples ? "c" : "p", double(r.kelemen_pb), r.mutations_per_sample);
        out += buf;
    }
    if (r.restarts) {
        std::snprintf(buf, sizeof buf, "; chains restarted every %u steps, %u times%s",
                      r.restart_every, r.restarts,
                      r.restart_samples ? ", their samples large steps'" : "");
        out += buf;
    }
    if (r.chains_stay) {
        std::snprintf(buf, sizeof buf,
                      "; the chains' stay %.3g by each pixel's samples, %.3g by its neighbours' "
                      "(--restart auto restarts above %g or %g)",
                      r.chains_stay->own, r.chains_stay->neighbours, kPileStay,
                      kPileStayNeighbours);
        out += buf;
    }
    if (r.strata > 1) {
        std::snprintf(buf, sizeof buf, "; stratified, %u tiles%s", r.strata,
                      r.strata_piles ? " (the burn-in piled chains on one path)" : "");
        out += buf;
    }
    if (r.omc_cells > 0) {
        std::snprintf(buf, sizeof buf,
                      "; %u of %u cells (%.3g%% of the film) to the OMC part whole, %u spp there "
                      "(%.3g per step)",
                      r.omc_cells, r.target_cells, 100.0 * r.omc_cell_share, r.omc_cell_spp,
                      r.omc_cell_rate);
        out += buf;
    }
    if (r.two_stage && r.steps > 0) {
        std::snprintf(buf, sizeof buf, "; target two-stage (%u cells)", r.target_cells);
        out += buf;
    }
    return out;
}

} // namespace smallmlt
