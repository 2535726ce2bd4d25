// The table of render's and budget's flags (options.hpp).
#include "app/options.hpp"

#include "base/error.hpp"
#include "device/device_profile.hpp"
#include "image/image.hpp"
#include "render/split.hpp"
#include "render/strata.hpp"
#include "render/target.hpp"
#include "scene/scene.hpp"

#include <cstdio>

namespace smallmlt {

namespace {

std::string number(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", x);
    return s;
}

std::string profile_names() {
    std::string s;
    for (const DeviceProfile& p : device_profiles())
        s += (s.empty() ? "" : ", ") + p.name;
    return s;
}

// A file of linear radiance, given to `flag` as `what`.
std::string linear_image(const FlagValue& v, const char* what) {
    if (image_format_of(v.text, v.flag.name) == ImageFormat::Png)
        throw UsageError(std::string(v.flag.name) + " " + v.text + ": " + what +
                         " holds linear radiance (.pfm or .exr)");
    return v.text;
}

// The flags of the render, the film and the device (--help's render and PT
// options).
const std::vector<Flag> kRenderFlags = {
    {"--method", "pt|mlt", Section::Render,
     [](RenderOptions& o, const FlagValue& v) {
         o.method = v.pick({Method::Pt, Method::Mlt});
     },
     "path tracing, or Metropolis light transport in primary sample space (Kelemen), one "
     "chain per thread (default {default})",
     0, 0, "method",
     [] { return std::string(RenderOptions().method == Method::Pt ? "pt" : "mlt"); }},
    {"--spp", "N", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.spp = std::uint32_t(v.integer()); },
     "samples per pixel (default {default}); for mlt, mutations per pixel on average", 1, 1 << 30,
     nullptr, [] { return std::to_string(kDefaultSpp); }},
    {"--time", "SECONDS", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.time_s = v.positive("number of seconds"); },
     "render for this long instead of a sample count (at least one pass: for mlt, one "
     "step after the burn-in)"},
    {"--seed", "S", Section::Render, [](RenderOptions& o, const FlagValue& v) { o.seed = v.u64(); },
     "seed of all random numbers (default {default}); same seed, same image", 0, 0, nullptr,
     [] { return std::to_string(RenderOptions().seed); }},
    {"--out", "FILE", Section::Render,
     [](RenderOptions& o, const FlagValue& v) {
         image_format_of(v.text);
         o.outs.push_back(v.text);
     },
     "output image: .png (tone-mapped sRGB), .pfm or .exr (linear radiance); may be repeated "
     "(default: SCENE's name + .png)"},
    {"--width", "W", Section::Render,
     [](JobOptions& o, const FlagValue& v) { o.width = int(v.integer()); },
     "film width in pixels, {range} (overrides the scene)", 1, kMaxFilmSide},
    {"--height", "H", Section::Render,
     [](JobOptions& o, const FlagValue& v) { o.height = int(v.integer()); },
     "film height in pixels, {range} (overrides the scene)", 1, kMaxFilmSide},
    {"--depth", "D", Section::Render,
     [](JobOptions& o, const FlagValue& v) { o.depth = int(v.integer()); },
     "maximum bounces, {range} (overrides the scene); budget reports each depth from 1 to D "
     "(D = 0: depth 0 alone)",
     0, kMaxDepth},
    {"--texture-max", "N", Section::Render,
     [](JobOptions& o, const FlagValue& v) { o.texture_max = int(v.integer()); },
     "halve every texture until its longer side is at most N pixels, {range} (textures are "
     "also halved, largest first, to fit a quarter of the device's memory)",
     1, 16384},
    {"--device", "INDEX", Section::Render,
     [](JobOptions& o, const FlagValue& v) {
         o.device = int(v.integer());
         o.device_given = true;
     },
     "OpenCL device from `smallmlt devices` (default {default})", 0, 1 << 20, nullptr,
     [] { return std::to_string(JobOptions().device); }},
    {"--rr-start", "B", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.roulette.start = int(v.integer()); },
     "Russian roulette from bounce B on (default {default})", 0, kMaxDepth, nullptr,
     [] { return std::to_string(Roulette().start); }},
    {"--rr-threshold", "T", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.roulette.threshold = float(v.positive()); },
     "... only while the path's throughput is below T; it survives with probability "
     "throughput / T (default {default})",
     0, 0, nullptr, [] { return number(Roulette().threshold); }},
    {"--rr-cap", "C", Section::Render,
     [](RenderOptions& o, const FlagValue& v) {
         double c = v.probability();
         if (c == 0) throw UsageError(std::string(v.flag.name) + ": 0 would end every path");
         o.roulette.cap = float(c);
     },
     "... and at most C (default {default})", 0, 0, nullptr, [] { return number(Roulette().cap); }},
    {"--rr-by", "max|luminance", Section::Render,
     [](RenderOptions& o, const FlagValue& v) {
         o.roulette.by_luminance = v.pick({false, true});
     },
     "the throughput is its largest channel or its luminance (default {default}). The earlier "
     "rule: --rr-threshold 1 --rr-cap 0.95",
     0, 0, "measure", [] { return std::string(Roulette().by_luminance ? "luminance" : "max"); }},
    {"--quiet", "", Section::Render, [](RenderOptions& o, const FlagValue&) { o.quiet = true; },
     "no progress bar and no summary line"},
    {"--reference", "FILE", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.reference = linear_image(v, "a reference"); },
     "long render (.pfm or .exr, same film) to measure the error against: the errors of "
     "`compare`, printed at the end"},
    {"--log", "FILE.csv", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.log = v.text; },
     "with --reference: a row every --log-every seconds of render time with seconds, samples "
     "(or mutations) per pixel, samples, mse, rel_mse, mse_unlit, block8_mse, block32_mse; "
     "measuring is not render time"},
    {"--log-every", "SECONDS", Section::Render,
     [](RenderOptions& o, const FlagValue& v) {
         o.log_interval_s = v.positive("number of seconds");
     },
     "seconds of render time between rows of --log (default {default})", 0, 0, nullptr,
     [] { return number(RenderOptions().log_interval_s); }},
    {"--reference-mask", "FILE", Section::Render,
     [](RenderOptions& o, const FlagValue& v) { o.reference_mask = linear_image(v, "a mask"); },
     "with --reference: an image of the film (.pfm or .exr) whose lit pixels mse_unlit leaves "
     "out, e.g. a --depth 0 render (the lights seen directly); without it mse_unlit is an "
     "empty field"},
    {"--device-mem", "BYTES", Section::Render,
     [](JobOptions& o, const FlagValue& v) { o.device_mem = v.bytes(); },
     "use at most this much device memory, as if the device had only BYTES (suffixes K, M, "
     "G); its largest buffer is BYTES/4"},
    {"--profile", "NAME", Section::Render,
     [](JobOptions& o, const FlagValue& v) { o.profile = find_device_profile(v.text).name; },
     "count the device as one of doc/devices.md ({default}): its memory, largest allocation, "
     "compute units, work-group size, and whether it has 64-bit atomics (never more than the "
     "device has)",
     0, 0, nullptr, profile_names},
    {"--sampler", "sobol|random", Section::Pt,
     [](RenderOptions& o, const FlagValue& v) {
         o.sampler = v.pick({PtSampler::Sobol, PtSampler::Random});
     },
     "Owen-scrambled Sobol points per pixel or independent random numbers (default {default})", 0,
     0, "sampler",
     [] { return std::string(kDefaultPtSampler == PtSampler::Sobol ? "sobol" : "random"); }},
};

std::string large_step_defaults() {
    return number(default_large_step(true, true)) + " with burn-in, " +
           number(default_large_step(true, true, true)) + " with burn-in and restarts, " +
           number(default_large_step(true, false)) + " with burn-in and --weights expected, " +
           number(default_large_step(false, true)) + " without burn-in";
}

// The chains' flags, and budget's own.
const std::vector<Flag> kMltFlags = {
    {"--threads", "N|auto", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) {
         o.threads = v.text == "auto" ? std::nullopt
                                      : std::optional<std::uint32_t>(std::uint32_t(v.integer()));
     },
     "threads (default auto: enough to keep the device busy, halved until the render fits in "
     "half the device memory)",
     1, 1 << 26},
    {"--proposals", "K", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) { o.mlt.proposals = v.power_of_two(); },
     "split-transition MLT: K proposals per chain, N/K chains (K a power of two in {range}; "
     "default {default}, plain MLT)",
     1, 64, nullptr, [] { return std::to_string(MltOptions().proposals); }},
    {"--burn-in", "omc|none", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) {
         o.mlt.burn_in = v.pick({true, false});
     },
     "start chains at OMC samples picked in proportion to their luminance, or at fresh OMC "
     "samples (default {default})",
     0, 0, "burn-in", [] { return std::string(MltOptions().burn_in ? "omc" : "none"); }},
    {"--burn-in-iters", "T", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) { o.mlt.burn_in_iters = std::uint32_t(v.integer()); },
     "OMC rounds of one sample per chain (default {default}); all of them estimate the "
     "normalization b",
     1, 1 << 16, nullptr, [] { return std::to_string(MltOptions().burn_in_iters); }},
    {"--split", "none|visible|direct|all|auto", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) { o.mlt.split = parse_split(v.flag.name, v.text); },
     "what the chains render: all light (none), or all but the OMC part, rendered by "
     "per-pixel samples: the emission the camera sees (visible), plus direct light at the "
     "first vertex (direct), or nothing (all: path tracing); auto is visible, or all where "
     "the burn-in shows that path tracing renders the rest well (default {default}; "
     "doc/design.md, \"The split\")",
     0, 0, nullptr, [] { return std::string(split_name(MltOptions().split)); }},
    {"--omc-effort", "F", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) { o.mlt.omc_effort = v.non_negative(); },
     "F times the OMC part's share of time that the split's rule gives it (default {default}; "
     "doc/design.md, \"The split\")",
     0, 0, nullptr, [] { return number(MltOptions().omc_effort); }},
    {"--omc-cells", "on|off", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) {
         o.mlt.omc_cells = parse_omc_cells(v.flag.name, v.text);
     },
     "with a split, give the OMC part whole the cells of the film where burn-in rounds of "
     "their own (half of --burn-in-iters, before the others) show that path tracing renders "
     "the chains' part well; the chains render the rest (default {default}; doc/design.md, "
     "\"Cells for the OMC part\")",
     0, 0, nullptr, [] { return std::string(MltOptions().omc_cells ? "on" : "off"); }},
    {"--target", "luminance|two-stage", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) { o.mlt.target = parse_target(v.flag.name, v.text); },
     "the chains' target: the luminance of what they render, or that divided by a coarse "
     "image of it from the first half of burn-in, so that dim regions get as many mutations "
     "per pixel as bright ones (default {default}; doc/design.md, \"The target\")",
     0, 0, nullptr, [] { return std::string(target_name(MltOptions().target)); }},
    {"--strata", "none|piles|auto|PIXELS", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) {
         o.mlt.strata = v.text == "none"    ? 0
                        : v.text == "auto"  ? kStrataAuto
                        : v.text == "piles" ? kStrataPiles
                                            : std::uint32_t(v.integer());
     },
     "stratified MLT: the film cut into square tiles of PIXELS on a side ({range}), each "
     "with its own chains and normalization; auto: tiles of at least 8 pixels, at most one "
     "for every 4 work-groups of chains; piles: auto's tiles where the burn-in started more "
     "than 1% of the chains on one path, else none (default {default}; doc/design.md, "
     "\"Strata\")",
     1, 16384, nullptr,
     [] {
         std::uint32_t s = MltOptions().strata;
         return s == 0              ? std::string("none")
                : s == kStrataAuto  ? "auto"
                : s == kStrataPiles ? "piles"
                                    : std::to_string(s);
     }},
    {"--film-step", "auto|film|PIXELS", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) {
         o.mlt.film_step = v.text == "film"   ? 0
                           : v.text == "auto" ? kFilmStepAuto
                                              : std::uint32_t(v.integer());
     },
     "the largest small step of a chain's film position: PIXELS ({range}; at least a 64th "
     "of its tile); film: a 64th of the film's width and height, Kelemen's step, in a tile "
     "of --strata as on the film; auto: the larger of twice that, a 32nd of the film, and 4 "
     "pixels (default {default}; "
     "doc/design.md, \"Small steps on the film\")",
     1, 16384, nullptr,
     [] {
         std::uint32_t s = MltOptions().film_step;
         return s == 0 ? std::string("film") : s == kFilmStepAuto ? "auto" : std::to_string(s);
     }},
    {"--path-step", "N", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) { o.mlt.path_step = v.power_of_two(); },
     "the largest small step of a chain's path numbers (all but its film position): 1/N of "
     "their unit interval, the smallest 1/(16 N) (N a power of two in {range}; Kelemen's is "
     "64; default {default}; doc/design.md, \"Small steps\")",
     kPathStepMin, kPathStepMax, nullptr, [] { return std::to_string(MltOptions().path_step); }},
    {"--restart", "auto|STEPS", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) {
         o.mlt.restart = v.text == "auto" ? kRestartAuto : std::uint32_t(v.integer());
     },
     "every STEPS steps each chain starts again at a pick of --burn-in-iters fresh burn-in "
     "rounds (at a fresh sample without burn-in), whose samples are also large steps' under "
     "Kelemen's weights and, in the OMC part's cells, its per-pixel samples: more, shorter "
     "chains, whose error is less correlated across the film; 0: never ({range}); auto: "
     "every 8 steps where the chains are at least the film's pixels and Kelemen's weights "
     "are in force; where they are fewer, every 16 steps after a burn-in that started more "
     "than 1% of the chains on one path or found small bright areas they would stay on; else "
     "never (default {default}; "
     "doc/design.md, \"Restarts\")",
     0, 1 << 30, nullptr,
     [] {
         std::uint32_t s = MltOptions().restart;
         return s == kRestartAuto ? std::string("auto") : std::to_string(s);
     }},
    {"--large-step", "P", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) { o.mlt.large_step = float(v.probability()); },
     "probability that a mutation draws a whole new path (default {default})", 0, 0, nullptr,
     large_step_defaults},
    {"--weights", "expected|kelemen", Section::Mlt,
     [](JobOptions& o, const FlagValue& v) {
         o.mlt.kelemen = v.pick({false, true});
     },
     "what a splat weighs: its expected value alone, with which the image's mean is b, or "
     "Kelemen's weights, which also count every large step as an independent sample "
     "(default {default}; doc/design.md, \"Kelemen's weights\")",
     0, 0, "weighting", [] { return std::string(MltOptions().kelemen ? "kelemen" : "expected"); }},
    {"--mutations-per-sample", "M", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) {
         o.mlt.mutations_per_sample = v.positive("number of mutations");
     },
     "Kelemen's weights count M of a chain's mutations as one independent sample beside the "
     "large steps' and the restarts' samples: a chain's mutations are correlated, so its "
     "light counts for less where those also find it; any M leaves the image unbiased "
     "(default {default}; 1 is Kelemen's; doc/design.md, \"Kelemen's weights\")",
     0, 0, nullptr,
     [] {
         return number(default_mutations_per_sample(true)) + " where chains restart, " +
                number(default_mutations_per_sample(false)) + " where they do not";
     }},
    {"--stuck-run", "R", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) { o.mlt.stuck_run = std::uint32_t(v.integer()); },
     "a chain that rejects R proposals in a row counts as stuck (default {default}); the "
     "summary gives how many did and the longest run, and a note warns when any did",
     1, CHAIN_RUN_MAX, nullptr, [] { return std::to_string(MltOptions().stuck_run); }},
    {"--film-atomics", "32|64", Section::Mlt,
     [](RenderOptions& o, const FlagValue& v) {
         o.mlt.film_atomics64 = v.pick({false, true});
     },
     "splat through 32-bit atomics into a film drained to the host (every device), or 64-bit "
     "atomics into one 64-bit film (the reference build; needs cl_khr_int64_base_atomics); "
     "default {default}",
     0, 0, nullptr, [] { return std::string(MltOptions().film_atomics64 ? "64" : "32"); }},
    {"--format", "table|csv|json", Section::Budget,
     [](BudgetOptions& o, const FlagValue& v) {
         o.format = v.pick({BudgetFormat::Table, BudgetFormat::Csv, BudgetFormat::Json});
     },
     "the report's format (default {default})", 0, 0, "format",
     [] {
         BudgetFormat f = BudgetOptions().format;
         return std::string(f == BudgetFormat::Table ? "table"
                            : f == BudgetFormat::Csv ? "csv"
                                                     : "json");
     }},
};

std::vector<Flag> all_flags() {
    std::vector<Flag> all = kRenderFlags;
    all.insert(all.end(), kMltFlags.begin(), kMltFlags.end());
    return all;
}

} // namespace

const std::vector<Flag>& flag_table() {
    static const std::vector<Flag> table = all_flags();
    return table;
}

const Flag* find_flag(const std::string& name) {
    for (const Flag& f : flag_table())
        if (name == f.name) return &f;
    return nullptr;
}

bool takes(const Flag& f, const RenderOptions&) {
    return !std::holds_alternative<SetBudget>(f.set);
}

bool takes(const Flag& f, const BudgetOptions&) {
    return !std::holds_alternative<SetRender>(f.set);
}

void apply(const Flag& f, RenderOptions& o, const FlagValue& v) {
    if (const SetJob* s = std::get_if<SetJob>(&f.set)) return (*s)(o, v);
    std::get<SetRender>(f.set)(o, v);
}

void apply(const Flag& f, BudgetOptions& o, const FlagValue& v) {
    if (const SetJob* s = std::get_if<SetJob>(&f.set)) return (*s)(o, v);
    std::get<SetBudget>(f.set)(o, v);
}

} // namespace smallmlt
