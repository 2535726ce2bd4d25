#include "app/cli.hpp"

#include "base/bits.hpp"
#include "base/error.hpp"
#include "device/device_profile.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace smallmlt {

const char* usage_text() {
    return R"(smallmlt: Metropolis light transport for small OpenCL devices

Usage:
  smallmlt render SCENE [options]   render a .scene file
  smallmlt budget SCENE [options]   device memory per bounce depth, without rendering
  smallmlt compare IMAGE REFERENCE [--mask FILE]
                                    error of IMAGE against REFERENCE (.pfm or .exr):
                                    MSE, relative MSE and the MSE of 8x8 block means
                                    (block8_mse) on linear values; with --mask, also
                                    the MSE over the pixels where FILE is black
                                    (mse_unlit)
  smallmlt devices                  list OpenCL devices and their memory
  smallmlt --help | --version

Render options:
  --method mlt|pt    Metropolis light transport in primary sample space (Kelemen;
                     default), one chain per thread, or path tracing
  --spp N            samples per pixel (default 16); for mlt, mutations per pixel
                     on average
  --time SECONDS     render for this long instead of a sample count
  --seed S           seed of all random numbers (default 1); same seed, same image
  --out FILE         output image: .png (tone-mapped sRGB), .pfm or .exr (linear
                     radiance); may be repeated (default: SCENE's name + .png)
  --width W          film width in pixels (overrides the scene)
  --height H         film height in pixels (overrides the scene)
  --depth D          maximum bounces, 0..64 (overrides the scene)
  --device INDEX     OpenCL device from `smallmlt devices` (default 0)
  --rr-start B       Russian roulette from bounce B on (default 3)
  --rr-threshold T   ... only while the path's throughput is below T; it survives
                     with probability throughput / T (default 0.3)
  --rr-cap C         ... and at most C (default 1)
  --rr-by max|luminance  the throughput is its largest channel (default) or its
                     luminance. The earlier rule: --rr-threshold 1
                     --rr-cap 0.95
  --quiet            no progress bar and no summary line
  --reference FILE   long render (.pfm or .exr, same film) to measure the error
                     against: the errors of `compare`, printed at the end
  --log FILE.csv     with --reference: a row every --log-every seconds of render
                     time (default 1) with seconds, samples (or mutations) per
                     pixel, samples, mse, rel_mse, mse_unlit, block8_mse;
                     measuring is not render time
  --reference-mask FILE  with --reference: an image of the film (.pfm or .exr)
                     whose lit pixels mse_unlit leaves out, e.g. a --depth 0
                     render (the lights seen directly); without it mse_unlit is
                     an empty field

  --device-mem BYTES use at most this much device memory, as if the device had
                     only BYTES (suffixes K, M, G); its largest buffer is BYTES/4
  --profile NAME     count the device as one of doc/devices.md (mali-g610,
                     adreno-650, apple-m1, videocore-iv): its memory, largest
                     allocation, compute units, work-group size, and whether
                     it has 64-bit atomics (never more than the device has)

PT options:
  --sampler sobol|random  Owen-scrambled Sobol points per pixel (default) or
                     independent random numbers

MLT options:
  --threads N|auto   threads (default auto: enough to keep the device busy, halved
                     until the render fits in half the device memory)
  --proposals K      split-transition MLT: K proposals per chain, N/K chains
                     (K a power of two up to 64; default 1, plain MLT)
  --burn-in omc|none start chains at OMC samples picked in proportion to their
                     luminance (default), or at fresh OMC samples
  --burn-in-iters T  OMC rounds of one sample per chain (default 32); all of them
                     estimate the normalization b
  --split none|visible|direct|all|auto  what the chains render: all light
                     (none), or all but the OMC part, rendered by per-pixel
                     samples: the emission the camera sees (visible), plus
                     direct light at the first vertex (direct), or nothing
                     (all: path tracing); auto (the default) is visible, or all
                     where the burn-in shows that path tracing renders the
                     rest well (doc/design.md, "The split")
  --omc-effort F     F times the OMC part's share of time that the split's rule
                     gives it (default 1; doc/design.md, "The split")
  --target luminance|two-stage  the chains' target: the luminance of what they
                     render (the default), or that divided by a coarse image
                     of it from the first half of burn-in, so that dim regions
                     get as many mutations per pixel as bright ones
                     (doc/design.md, "The target")
  --large-step P     probability that a mutation draws a whole new path
                     (default 0.3 with burn-in, 0.1 with burn-in and
                     --weights expected, 0.5 without burn-in)
  --weights kelemen|expected  what a splat weighs: Kelemen's weights (the
                     default), which also count every large step as an
                     independent sample, or its expected value alone, with
                     which the image's mean is b (doc/design.md, "Kelemen's
                     weights")
  --stuck-run R      a chain that rejects R proposals in a row counts as stuck
                     (default 1000); the summary gives how many did and the
                     longest run, and a note warns when any did
  --film-atomics 32|64  splat through 32-bit atomics into a film drained to the
                     host (default; every device), or 64-bit atomics into one
                     64-bit film (the reference build; needs
                     cl_khr_int64_base_atomics)

Budget options:
  --threads N|auto   as for render (default auto)
  --proposals K      proposals per chain: N threads keep N/K chain states (default 1)
  --split none|visible|direct|all|auto  as for render (a split adds the OMC
                     part's film)
  --target luminance|two-stage  as for render (two-stage adds its weights)
  --depth D          report depths 1..D (default: the scene's depth)
  --width W, --height H  the film (overrides the scene)
  --device-mem BYTES as for render
  --profile NAME     as for render
  --format table|csv|json
  --device INDEX

Exit status: 0 success, 1 bad input or device error, 2 bad command line,
3 interrupted (the image so far was written).
The scene format is described in doc/scene-format.md.
)";
}

namespace {

struct ArgReader {
    int argc;
    const char* const* argv;
    int i;

    bool done() const { return i >= argc; }
    std::string next() { return argv[i++]; }
    // Value of `flag`, given as "--flag value" or "--flag=value".
    std::string value(const std::string& flag, const std::string& arg) {
        std::size_t eq = arg.find('=');
        if (eq != std::string::npos) return arg.substr(eq + 1);
        if (done()) throw UsageError(flag + ": missing value");
        return next();
    }
};

long long to_int(const std::string& flag, const std::string& v, long long lo, long long hi) {
    errno = 0;
    char* end = nullptr;
    long long x = std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno == ERANGE)
        throw UsageError(flag + ": '" + v + "' is not an integer");
    if (x < lo || x > hi)
        throw UsageError(flag + ": " + v + " is out of range " + std::to_string(lo) + ".." +
                         std::to_string(hi));
    return x;
}

std::uint64_t to_u64(const std::string& flag, const std::string& v) {
    errno = 0;
    char* end = nullptr;
    unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    if (v.empty() || v[0] == '-' || *end != '\0' || errno == ERANGE)
        throw UsageError(flag + ": '" + v + "' is not a non-negative integer");
    return x;
}

std::uint64_t to_bytes(const std::string& flag, const std::string& v) {
    char* end = nullptr;
    errno = 0;
    unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    std::uint64_t scale = 1;
    std::string suffix = end ? end : "";
    if (suffix == "K" || suffix == "k")
        scale = 1ull << 10;
    else if (suffix == "M" || suffix == "m")
        scale = 1ull << 20;
    else if (suffix == "G" || suffix == "g")
        scale = 1ull << 30;
    else if (!suffix.empty())
        scale = 0;
    if (v.empty() || v[0] == '-' || end == v.c_str() || scale == 0 || errno == ERANGE || x == 0 ||
        x > (~0ull) / scale)
        throw UsageError(flag + ": '" + v + "' is not a size in bytes (e.g. 65536, 64K, 16M, 1G)");
    return x * scale;
}

std::uint32_t to_proposals(const std::string& flag, const std::string& v) {
    long long k = to_int(flag, v, 1, 64);
    if (!is_power_of_two(std::uint64_t(k)))
        throw UsageError(flag + ": " + v + " is not a power of two");
    return std::uint32_t(k);
}

std::optional<std::uint32_t> to_threads(const std::string& flag, const std::string& v) {
    if (v == "auto") return std::nullopt;
    return std::uint32_t(to_int(flag, v, 1, 1 << 26));
}

double to_unit_interval(const std::string& flag, const std::string& v) {
    char* end = nullptr;
    double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !(x >= 0 && x <= 1))
        throw UsageError(flag + ": '" + v + "' is not a probability in [0, 1]");
    return x;
}

double to_positive(const std::string& flag, const std::string& v, const char* what = "number") {
    char* end = nullptr;
    double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x) || x <= 0)
        throw UsageError(flag + ": '" + v + "' is not a positive " + what);
    return x;
}

double to_non_negative(const std::string& flag, const std::string& v) {
    char* end = nullptr;
    double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x) || x < 0)
        throw UsageError(flag + ": '" + v + "' is not a number >= 0");
    return x;
}

double to_seconds(const std::string& flag, const std::string& v) {
    return to_positive(flag, v, "number of seconds");
}

// What is not a known option: an unknown option is an error, the first
// other argument is the scene, a second one is an error.
void take_scene(const std::string& arg, const std::string& flag, std::string& scene) {
    if (arg.rfind("-", 0) == 0)
        throw UsageError("unknown option " + flag + " (see smallmlt --help)");
    if (!scene.empty()) throw UsageError("unexpected argument '" + arg + "': one scene at a time");
    scene = arg;
}

std::string default_out(const std::string& scene) {
    std::size_t slash = scene.find_last_of('/');
    std::string base = scene.substr(slash == std::string::npos ? 0 : slash + 1);
    std::size_t dot = base.find_last_of('.');
    return (dot == std::string::npos ? base : base.substr(0, dot)) + ".png";
}

RenderOptions parse_render(ArgReader& r) {
    RenderOptions o;
    while (!r.done()) {
        std::string arg = r.next();
        std::string flag = arg.substr(0, arg.find('='));
        if (flag == "--method") {
            std::string m = r.value(flag, arg);
            if (m == "pt")
                o.method = Method::Pt;
            else if (m == "mlt")
                o.method = Method::Mlt;
            else
                throw UsageError("--method: '" + m + "' is not a method (pt or mlt)");
        } else if (flag == "--large-step") {
            o.large_step = float(to_unit_interval(flag, r.value(flag, arg)));
        } else if (flag == "--split") {
            o.split = parse_split(flag, r.value(flag, arg));
        } else if (flag == "--target") {
            o.target = parse_target(flag, r.value(flag, arg));
        } else if (flag == "--weights") {
            std::string w = r.value(flag, arg);
            if (w != "expected" && w != "kelemen")
                throw UsageError("--weights: '" + w + "' is not a weighting (expected or kelemen)");
            o.kelemen = w == "kelemen";
        } else if (flag == "--omc-effort") {
            o.omc_effort = to_non_negative(flag, r.value(flag, arg));
        } else if (flag == "--stuck-run") {
            o.stuck_run = std::uint32_t(to_int(flag, r.value(flag, arg), 1, CHAIN_RUN_MAX));
        } else if (flag == "--burn-in") {
            std::string b = r.value(flag, arg);
            if (b == "omc")
                o.burn_in = true;
            else if (b == "none")
                o.burn_in = false;
            else
                throw UsageError("--burn-in: '" + b + "' is not a burn-in (omc or none)");
        } else if (flag == "--burn-in-iters") {
            o.burn_in_iters = std::uint32_t(to_int(flag, r.value(flag, arg), 1, 1 << 16));
        } else if (flag == "--threads") {
            o.threads = to_threads(flag, r.value(flag, arg));
        } else if (flag == "--device-mem") {
            o.device_mem = to_bytes(flag, r.value(flag, arg));
        } else if (flag == "--profile") {
            o.profile = find_device_profile(r.value(flag, arg)).name;
        } else if (flag == "--film-atomics") {
            std::string b = r.value(flag, arg);
            if (b != "32" && b != "64")
                throw UsageError("--film-atomics: '" + b + "' is not 32 or 64");
            o.film_atomics64 = b == "64";
        } else if (flag == "--proposals") {
            o.proposals = to_proposals(flag, r.value(flag, arg));
        } else if (flag == "--spp") {
            o.spp = std::uint32_t(to_int(flag, r.value(flag, arg), 1, 1 << 30));
        } else if (flag == "--time") {
            o.time_s = to_seconds(flag, r.value(flag, arg));
        } else if (flag == "--seed") {
            o.seed = to_u64(flag, r.value(flag, arg));
        } else if (flag == "--out") {
            std::string f = r.value(flag, arg);
            image_format_of(f);
            o.outs.push_back(f);
        } else if (flag == "--reference") {
            o.reference = r.value(flag, arg);
            ImageFormat f = image_format_of(o.reference, flag);
            if (f == ImageFormat::Png)
                throw UsageError("--reference " + o.reference +
                                 ": a reference holds linear radiance (.pfm or .exr)");
        } else if (flag == "--log") {
            o.log = r.value(flag, arg);
        } else if (flag == "--log-every") {
            o.log_interval_s = to_seconds(flag, r.value(flag, arg));
        } else if (flag == "--reference-mask") {
            o.reference_mask = r.value(flag, arg);
            if (image_format_of(o.reference_mask, flag) == ImageFormat::Png)
                throw UsageError("--reference-mask " + o.reference_mask +
                                 ": a mask holds linear radiance (.pfm or .exr)");
        } else if (flag == "--width") {
            o.width = int(to_int(flag, r.value(flag, arg), 1, kMaxFilmSide));
        } else if (flag == "--height") {
            o.height = int(to_int(flag, r.value(flag, arg), 1, kMaxFilmSide));
        } else if (flag == "--depth") {
            o.depth = int(to_int(flag, r.value(flag, arg), 0, kMaxDepth));
        } else if (flag == "--device") {
            o.device = int(to_int(flag, r.value(flag, arg), 0, 1 << 20));
            o.device_given = true;
        } else if (flag == "--rr-start") {
            o.roulette.start = int(to_int(flag, r.value(flag, arg), 0, kMaxDepth));
        } else if (flag == "--rr-threshold") {
            o.roulette.threshold = float(to_positive(flag, r.value(flag, arg)));
        } else if (flag == "--rr-cap") {
            double c = to_unit_interval(flag, r.value(flag, arg));
            if (c == 0) throw UsageError("--rr-cap: 0 would end every path");
            o.roulette.cap = float(c);
        } else if (flag == "--rr-by") {
            std::string b = r.value(flag, arg);
            if (b != "max" && b != "luminance")
                throw UsageError("--rr-by: '" + b + "' is not a measure (max or luminance)");
            o.roulette.by_luminance = b == "luminance";
        } else if (flag == "--sampler") {
            std::string b = r.value(flag, arg);
            if (b == "sobol")
                o.sampler = PtSampler::Sobol;
            else if (b == "random")
                o.sampler = PtSampler::Random;
            else
                throw UsageError("--sampler: '" + b + "' is not a sampler (sobol or random)");
        } else if (arg == "--quiet") {
            o.quiet = true;
        } else {
            take_scene(arg, flag, o.scene);
        }
    }
    if (o.scene.empty()) throw UsageError("render: no scene file given");
    if (o.spp && o.time_s) throw UsageError("--spp and --time: give one of them, not both");
    if (!o.spp && !o.time_s) o.spp = kDefaultSpp;
    if (o.outs.empty()) o.outs.push_back(default_out(o.scene));
    if (!o.log.empty() && o.reference.empty())
        throw UsageError("--log " + o.log + ": give --reference, the image to measure against");
    if (!o.reference_mask.empty() && o.reference.empty())
        throw UsageError("--reference-mask " + o.reference_mask +
                         ": give --reference, the image to measure against");
    if (!o.large_step)
        o.large_step = !o.burn_in  ? kDefaultLargeStepNoBurnIn
                       : o.kelemen ? kDefaultLargeStepKelemen
                                   : kDefaultLargeStepBurnIn;
    return o;
}

BudgetOptions parse_budget(ArgReader& r) {
    BudgetOptions o;
    while (!r.done()) {
        std::string arg = r.next();
        std::string flag = arg.substr(0, arg.find('='));
        if (flag == "--threads") {
            o.threads = to_threads(flag, r.value(flag, arg));
        } else if (flag == "--proposals") {
            o.proposals = to_proposals(flag, r.value(flag, arg));
        } else if (flag == "--split") {
            o.split = parse_split(flag, r.value(flag, arg));
        } else if (flag == "--target") {
            o.target = parse_target(flag, r.value(flag, arg));
        } else if (flag == "--depth") {
            o.depth = int(to_int(flag, r.value(flag, arg), 1, kMaxDepth));
        } else if (flag == "--device-mem") {
            o.device_mem = to_bytes(flag, r.value(flag, arg));
        } else if (flag == "--profile") {
            o.profile = find_device_profile(r.value(flag, arg)).name;
        } else if (flag == "--width") {
            o.width = int(to_int(flag, r.value(flag, arg), 1, kMaxFilmSide));
        } else if (flag == "--height") {
            o.height = int(to_int(flag, r.value(flag, arg), 1, kMaxFilmSide));
        } else if (flag == "--device") {
            o.device = int(to_int(flag, r.value(flag, arg), 0, 1 << 20));
        } else if (flag == "--format") {
            std::string f = r.value(flag, arg);
            if (f == "table")
                o.format = BudgetFormat::Table;
            else if (f == "csv")
                o.format = BudgetFormat::Csv;
            else if (f == "json")
                o.format = BudgetFormat::Json;
            else
                throw UsageError("--format: '" + f + "' is not a format (table, csv or json)");
        } else {
            take_scene(arg, flag, o.scene);
        }
    }
    if (o.scene.empty()) throw UsageError("budget: no scene file given");
    return o;
}

} // namespace

Command parse_command_line(int argc, const char* const* argv) {
    ArgReader r{argc, argv, 1};
    Command c;
    if (r.done()) throw UsageError("no command given (see smallmlt --help)");
    std::string cmd = r.next();
    for (int i = r.i; i < argc && (cmd == "render" || cmd == "budget"); ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return c;
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        c.kind = CommandKind::Help;
    } else if (cmd == "--version") {
        c.kind = CommandKind::Version;
    } else if (cmd == "devices") {
        c.kind = CommandKind::Devices;
        if (!r.done()) throw UsageError("devices: unexpected argument '" + r.next() + "'");
    } else if (cmd == "budget") {
        c.kind = CommandKind::Budget;
        c.budget = parse_budget(r);
    } else if (cmd == "compare") {
        c.kind = CommandKind::Compare;
        std::vector<std::string> files; // IMAGE REFERENCE, with --mask FILE anywhere
        while (!r.done()) {
            std::string arg = r.next();
            std::string flag = arg.substr(0, arg.find('='));
            if (flag == "--mask")
                c.mask = r.value(flag, arg);
            else if (arg.rfind("-", 0) == 0)
                throw UsageError("unknown option " + flag + " (see smallmlt --help)");
            else
                files.push_back(arg);
        }
        if (files.size() < 2) throw UsageError("compare: give IMAGE and REFERENCE");
        if (files.size() > 2) throw UsageError("compare: unexpected argument '" + files[2] + "'");
        c.image = files[0];
        c.reference = files[1];
    } else if (cmd == "render") {
        c.kind = CommandKind::Render;
        c.render = parse_render(r);
    } else {
        throw UsageError("unknown command '" + cmd +
                         "' (expected render, budget, compare or devices; see --help)");
    }
    return c;
}

} // namespace smallmlt
