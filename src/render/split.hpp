// The split of each path's contribution between an OMC part and an MLT part
// (cl/path/path.cl): light that reaches the camera after fewer than L surface
// vertices is the OMC part, rendered by stratified per-pixel samples (what
// path tracing renders well: the emission the camera sees, direct light);
// the rest is the target of the Markov chains. The parts add up to the path
// tracer's estimate, path by path.
#pragma once
#include "scene/device_scene.hpp"

#include <cstdint>
#include <string>

namespace smallmlt {

enum class Split {
    None,    // everything to the chains (the paper's estimator)
    Visible, // OMC: emission seen directly by the camera (L < 1)
    Direct,  // OMC: that plus direct light at the first vertex, NEE and BSDF hits, MIS (L < 2)
    All,     // OMC: everything (path tracing; no chains)
    Auto,    // kChainsSplit, or All where the chains would not pay (chains_pay)
};

// What Split::Auto runs where the chains pay: chosen by the bench.
constexpr Split kChainsSplit = Split::Visible;

// Chosen by the error-against-time bench (doc/RESULTS.md).
constexpr Split kDefaultSplit = Split::Auto;

const char* split_name(Split s);
// Throws UsageError naming `flag` for an unknown name.
Split parse_split(const std::string& flag, const std::string& name);
// L: terms after fewer vertices are the OMC part (PATH_SPLIT of cl/path/path.cl);
// Auto's burn-in traces with kChainsSplit's.
std::uint32_t split_vertices(Split s);
std::string split_defines(Split s);

// How the render time is divided between the parts. With t_o and t_m the
// times of the OMC part and of the chains, the image's squared error
// (summed over pixels) is about A / t_o + C / t_m, least when
// t_o / t_m = sqrt(A / C):
//   A = V_o P c_o: V_o the per-pixel variances of one OMC-part sample, summed
//       over the P pixels; c_o the rays of one such sample;
//   C = tau b^2 P^2 c_m: what the chains' film would have were its samples
//       independent (pixel p is found by a fraction mu_p / (b P) of them), tau
//       the chains' correlation (samples per independent one); c_m the rays
//       of one mutation, with its share of the restarts' rounds (--restart:
//       B / R paths, each about a mutation's rays). With restarts that take
//       a share u / (1 + u) of the chains' time and leave their error as
//       it was, t_o is then sqrt(1 + u) times what it is without: the
//       optimum of A / t_o + C / t_m at equal time.
// The OMC part then takes n_o = (t_o / t_m) T c_m / (P c_o) samples per
// pixel per step of T threads. tau is measured (doc/RESULTS.md, "Split").
// t_o / t_m is at most kOmcMaxTimeRatio: where the rule gives the OMC part
// more, its squared error is that of a few pixels of emission far above
// display white (a small light seen directly), which the rule would render
// at the expense of everything else: water-spark's 1 cm light asks for 71
// times the chains' time at 128x128 and 169 at its 160x90, and the chains
// ran one step in the whole render. The bench's scenes ask 0.17
// (tiny-caustic) to 0.49 (cornell-water), below the cap. And t_o / t_m is
// at least kOmcMinTimeRatio: V_o is 0 where the OMC part renders nothing
// the burn-in saw, and the OMC part must still converge. V_o is at least
// what one burn-in sample of the brightest light the camera sees would give
// it (src/render/emission_seen.hpp): water-spark's light covers 3% of a
// pixel, 2^19 paths hit it about once, and a burn-in that missed it put
// the OMC part on the floor.
// With cells the OMC part renders whole (src/render/omc_cells.hpp), those
// P_c pixels are a part of their own, A_c = g V_c P_c c_c (V_c, c_c as V_o,
// c_o, for whole paths there; g = kPixelStratification, as the cells are
// chosen where the chains' part is smooth enough for per-pixel samples),
// and V_o, c_o are those of the other P - P_c pixels. The parts' times are
// then in proportion to sqrt(A), sqrt(A_c) and sqrt(C), with the cap on the
// OMC part's two together and the floor on the film's; and the cells take
// at least their share P_c / P of the whole render's time, as a path
// tracer would. Without that floor the rule gave a cell of cornell-glass
// 34 to 176 samples per pixel in 10 s where path tracing takes 307, and
// cornell-glossy's cells (70% of its film) half path tracing's samples
// under the cap, and the error rose on both. The other pixels take n_o
// samples per step and the cells' pixels n_c (omc_samples_per_step).
struct SplitCosts {
    double omc_variance = 0;  // V_o
    double b = 0;             // the MLT part's mean luminance
    double pixels = 0;        // P
    double omc_rays = 0;      // c_o
    double mutation_rays = 0; // c_m, with the restarts' share
    double threads = 0;       // T
    double cell_variance = 0; // V_c
    double cell_pixels = 0;   // P_c
    double cell_rays = 0;     // c_c
};
// --omc-effort's default: half the rule's OMC time did better than the rule
// on the five scenes measured at 128x128 and the three at 512x512, by
// blocks, and by MSE but for ajar at 512x512, level (doc/RESULTS.md, "The
// OMC part's share of time, by --omc-effort").
constexpr double kDefaultOmcEffort = 0.5;
constexpr double kChainCorrelation = 8.0;     // tau
constexpr double kOmcMaxTimeRatio = 1.0;      // the OMC part takes at most the chains' time
constexpr double kOmcMinTimeRatio = 1.0 / 16; // and at least a 16th of it

// Whether the chains should render the MLT part at all (Split::Auto). Per-
// pixel samples render it with a squared error, summed over pixels, of V_m
// / n at n samples per pixel (V_m as V_o, for the MLT part), less by what
// their stratification gains; the chains with tau b^2 P / n at n mutations
// per pixel, a mutation costing about one path. So the chains pay where the
// MLT part's per-pixel relative variance r = V_m / (P b^2) exceeds
// kChainsPayRatio (tau times the stratification's gain). Measured at
// 128x128 with the visible split (doc/RESULTS.md, "The split"): cornell has
// r = 0.67 and the chains take 9.5 times PT's time to its error; ajar (15)
// and cornell-glass (18) are level with PT; cornell-water (54) takes 0.43
// of PT's time. The threshold lies between.
// r misleads where the MLT part's light comes through glass or water from a
// small light: path tracing finds it only by hitting the light, so rarely
// that a burn-in of 2^19 paths may find none, and then r is that of the
// light it did find. On water-spark at its 160x90, seeds 3 and 5 found none
// (r = 0.51) and seeds 1, 2, 4 and 6 found some (r = 4e4 to 2e5);
// tiny-caustic at 128x128 reads r = 1.06 at seed 3 and 6850 at seed 1. So
// the chains also pay where a share s above kChainsPayBehindShare of the
// light the burn-in's paths aimed at (the MLT part and what smooth
// transmitters blocked, cl/path/path.cl) lay behind such surfaces: 53% on
// water-spark, 36% cornell-water, 14% cornell-glass, 7% tiny-caustic, 0 on
// the scenes without them.
constexpr double kChainsPayRatio = 4.0;
constexpr double kChainsPayBehindShare = 0.02;
// Where the chains restart (--restart, restart_steps), a chain moves a few
// pixels between restarts, so its light at the scale of 8x8 blocks is what
// the pool it restarts from put there: a path tracer's estimate from the
// pool's paths (each restart's a fresh set of Sobol points, not one long
// sequence), with a fifth of the time left to the steps. Restarting chains
// pay from kRestartPayFactor times kChainsPayRatio. cornell-glossy at
// 128x128, restarting every 8 steps (r = 4.8-5.7, seeds 1-6), read 0.88 /
// 2.59 / 2.77 times path tracing's MSE / 8x8 / 32x32 error with its chains
// (doc/RESULTS.md, "Why cornell-glossy's blocks miss at 128x128"), and none
// without them; of the bench's other scenes whose chains run there by r,
// the lowest r is ajar's 14.5 ("Restarting chains pay from r = 8").
constexpr double kRestartPayFactor = 2.0;
// The stratification's gain that threshold implies: per-pixel Sobol samples
// of the MLT part have this share of independent samples' variance.
constexpr double kPixelStratification = kChainsPayRatio / kChainCorrelation;
double mlt_part_relative_variance(double mlt_variance, double b, double pixels);
// The threshold on r of chains that restart, or do not.
double chains_pay_ratio(bool restarting);
bool chains_pay(double relative_variance, double behind_specular_share, bool restarting);
// The OMC part's samples per pixel per step: n_o on the film but the cells,
// n_c on the cells' pixels.
struct OmcRates {
    double film = 0, cells = 0;
};
// The rates of the rule's times t_o / t_m and t_c / t_m, times `effort`
// (--omc-effort; 1 is the rule).
OmcRates omc_samples_per_step(const SplitCosts& c, double effort);

} // namespace smallmlt
