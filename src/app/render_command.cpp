// `smallmlt render`: load the scene, fit the method to the device, run the
// pass loop, write the image and the convergence log.
#include "app/commands.hpp"

#include "base/clock.hpp"
#include "base/error.hpp"
#include "base/interrupt.hpp"
#include "device/device_profile.hpp"
#include "device/memory_plan.hpp"
#include "image/image_metrics.hpp"
#include "render/convergence_log.hpp"
#include "render/mlt.hpp"
#include "render/path_tracer.hpp"
#include "render/progress.hpp"
#include "render/ranks.hpp"
#include "render/render_loop.hpp"
#include "scene/scene.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <unistd.h>

namespace smallmlt {

namespace {

// Fails early, before a long render, if an output could not be written.
void check_output_dirs(const std::vector<std::string>& outs, const char* flag = "--out") {
    for (const std::string& f : outs) {
        std::size_t slash = f.find_last_of('/');
        std::string dir = slash == std::string::npos ? "." : f.substr(0, slash + 1);
        if (access(dir.c_str(), W_OK) != 0)
            throw UsageError(std::string(flag) + " " + f + ": directory " + dir +
                             " does not exist or is not writable");
    }
}

// Thread count for MLT (auto or checked) such that the render fits the
// device; PT only has to fit. Says what it chose if `say`.
std::uint32_t fit_to_device(const RenderOptions& o, const ClContext& cl, const DeviceScene& ds,
                            bool say) {
    require_work_group(cl.device());
    DeviceBudget budget = device_budget(cl.device(), o.device_mem);
    std::string allowed =
        format_bytes(std::uint64_t(kMemoryFraction * double(budget.global_bytes)));
    if (o.method == Method::Pt) {
        MemoryPlan plan = plan_pt(ds, budget.max_alloc_bytes);
        if (!plan_fits(plan, budget))
            throw InputError("not enough device memory: a " + std::to_string(ds.frame.width) + "x" +
                             std::to_string(ds.frame.height) + " path-traced film needs " +
                             format_bytes(plan.total()) + " (largest buffer " +
                             format_bytes(plan.largest()) + "); the device allows " + allowed +
                             " (max allocation " + format_bytes(budget.max_alloc_bytes) +
                             "); it would take " +
                             format_bytes(smallest_device_memory(
                                 [&](std::uint64_t max_alloc) { return plan_pt(ds, max_alloc); })) +
                             " of device memory");
        if (say)
            std::printf("film: %s in %u band(s); device memory %s of %s allowed\n",
                        format_bytes(plan.film()).c_str(), plan.film_bands(),
                        format_bytes(plan.total()).c_str(), allowed.c_str());
        return 0;
    }
    ChainShape shape = mlt_chain_shape(o.mlt);
    if (o.threads) {
        shape.threads = *o.threads;
        check_chain_shape(shape);
        MemoryPlan plan = check_threads(ds, shape, budget);
        if (say)
            std::printf("threads: %u (given); film %s in %u band(s); device memory %s of %s "
                        "allowed\n",
                        *o.threads, format_bytes(plan.film()).c_str(), plan.film_bands(),
                        format_bytes(plan.total()).c_str(), allowed.c_str());
        return *o.threads;
    }
    ThreadChoice c = choose_threads(ds, shape, cl.device(), budget);
    if (say)
        std::printf("threads: %u (auto: %u keep the device busy, reduced %ux to fit); film %s "
                    "in %u band(s); device memory %s of %s allowed\n",
                    c.threads, busy_threads(cl.device()), c.reduction,
                    format_bytes(c.plan.film()).c_str(), c.plan.film_bands(),
                    format_bytes(c.plan.total()).c_str(), allowed.c_str());
    return c.threads;
}

} // namespace

std::unique_ptr<Integrator> make_integrator(const RenderOptions& o, const ClContext& cl,
                                            const DeviceScene& ds, const RankGroup& ranks) {
    // With several ranks each sizes itself; rank 0 says what it chose, and
    // the summary gives every rank's chains.
    std::uint32_t threads = fit_to_device(o, cl, ds, !o.quiet && ranks.rank() == 0);
    std::uint64_t max_alloc = device_budget(cl.device(), o.device_mem).max_alloc_bytes;
    if (o.method == Method::Pt)
        return std::make_unique<PathTracer>(cl, ds, o.seed, o.sampler, max_alloc,
                                            std::uint32_t(ranks.rank()),
                                            std::uint32_t(ranks.size()));
    MltOptions m = o.mlt; // as the flags set it; the device and the rank set the rest
    m.max_alloc_bytes = max_alloc;
    m.threads = threads;
    m.seed = rank_seed(o.seed, ranks.rank());
    return std::make_unique<MltRenderer>(cl, ds, m);
}

namespace {

// What every rank sets up before the first pass.
struct RenderSetup {
    Scene scene;
    std::unique_ptr<ConvergenceLog> log; // rank 0 only
    DeviceScene ds;
    std::unique_ptr<ClContext> cl;
    std::unique_ptr<Integrator> method;
    std::string texture_note; // what fit_scene_textures halved
};

void set_up(const RenderOptions& o, RankGroup& ranks, RenderSetup& s) {
    if (ranks.size() > 1 && !o.log.empty())
        throw UsageError("--log " + o.log + ": one process only (this render has " +
                         std::to_string(ranks.size()) + " ranks); --reference alone works");
    check_output_dirs(o.outs);
    if (!o.log.empty()) check_output_dirs({o.log}, "--log");
    s.scene = load_scene(o.scene);
    if (ranks.rank() == 0) {
        for (const std::string& w : o.warnings)
            std::fprintf(stderr, "smallmlt: %s\n", w.c_str());
        print_scene_warnings(s.scene);
    }
    if (o.width) s.scene.width = *o.width;
    if (o.height) s.scene.height = *o.height;
    if (o.depth) s.scene.depth = *o.depth;
    s.scene.roulette = o.roulette;
    if (!o.reference.empty() && ranks.rank() == 0)
        s.log = std::make_unique<ConvergenceLog>(o.reference, o.reference_mask, o.log,
                                                 o.log_interval_s, s.scene.width, s.scene.height);
    int device = o.device;
    if (!o.device_given) device = ranks.local_rank() % int(cl_list_devices().size());
    s.cl = std::make_unique<ClContext>(device);
    if (o.profile) s.cl->emulate(emulate_profile(s.cl->device(), find_device_profile(*o.profile)));
    s.texture_note =
        fit_scene_textures(s.scene, device_budget(s.cl->device(), o.device_mem), o.texture_max);
    s.ds = prepare_scene(s.scene);
    s.method = make_integrator(o, *s.cl, s.ds, ranks);
}

// Sets up every rank; with several, a rank that fails makes all stop, each
// with a message naming the rank and host (rank 0 names every failure).
void set_up_every_rank(const RenderOptions& o, RankGroup& ranks, RenderSetup& s) {
    if (ranks.size() == 1) return set_up(o, ranks, s);
    std::string failure;
    bool usage = false;
    try {
        set_up(o, ranks, s);
    } catch (const UsageError& e) {
        failure = e.what();
        usage = true;
    } catch (const std::exception& e) {
        failure = e.what();
    }
    std::string me = "rank " + std::to_string(ranks.rank()) + " on " + ranks.host();
    std::vector<std::string> all = ranks.gather(failure.empty() ? "" : me + ": " + failure);
    if (ranks.all(failure.empty())) return;
    int code = usage ? kExitUsageError : kExitInputError;
    if (!failure.empty()) throw RankFailure(me + ": " + failure, code);
    std::string which;
    for (const std::string& f : all)
        if (!f.empty()) which += "\n  " + f;
    throw RankFailure(me + ": stopped, as another rank failed to start" + which, kExitInputError);
}

void print_summary(const RenderOptions& o, const RenderSetup& s, const LoopResult& r,
                   double setup_s, RankGroup& ranks, const Image& img) {
    const Integrator& m = *s.method;
    std::string what = o.method == Method::Pt ? "pt" : "mlt";
    std::vector<std::string> lines = ranks.gather(m.summary(r.render_s));
    std::string my_notes;
    for (const std::string& note : m.notes())
        my_notes += (my_notes.empty() ? "" : "\n") + note;
    std::vector<std::string> notes = ranks.gather(my_notes);
    std::vector<std::string> pass_counts = ranks.gather(std::to_string(r.passes));
    if (ranks.rank() != 0 || o.quiet) return;
    if (ranks.size() == 1) {
        std::printf("%s: %dx%d, depth %d, %s: %.2f s (+%.2f s setup), %s\n", o.scene.c_str(),
                    s.scene.width, s.scene.height, s.scene.depth, what.c_str(), r.render_s, setup_s,
                    lines[0].c_str());
    } else {
        std::string passes;
        for (const std::string& p : pass_counts)
            passes += (passes.empty() ? "" : " ") + p;
        std::printf("%s: %dx%d, depth %d, %s on %d ranks: %.2f s (+%.2f s setup), passes per "
                    "rank %s, image mean %.5g\n",
                    o.scene.c_str(), s.scene.width, s.scene.height, s.scene.depth, what.c_str(),
                    ranks.size(), r.render_s, setup_s, passes.c_str(), img.mean_luminance());
        for (std::size_t k = 0; k < lines.size(); ++k)
            std::printf("rank %zu: %s\n", k, lines[k].c_str());
    }
    if (s.log) {
        const ErrorSample& e = s.log->last();
        std::printf("error against %s: mse %.6g rel_mse %.6g block8_mse %.6g block32_mse %.6g",
                    o.reference.c_str(), e.mse, e.rel_mse, e.block8_mse, e.block32_mse);
        if (s.log->has_mask()) std::printf(" mse_unlit %.6g", e.mse_unlit);
        std::printf("\n");
    }
    for (std::size_t k = 0; k < notes.size(); ++k) {
        std::string rest = notes[k],
                    who = ranks.size() == 1 ? "" : " (rank " + std::to_string(k) + ")";
        for (std::size_t at; !rest.empty();
             rest = at == std::string::npos ? "" : rest.substr(at + 1)) {
            at = rest.find('\n');
            std::printf("note%s: %s\n", who.c_str(), rest.substr(0, at).c_str());
        }
    }
    if (!s.texture_note.empty()) std::printf("note: %s\n", s.texture_note.c_str());
    if (s.scene.dropped_degenerate)
        std::printf("note: %d zero-area triangle(s) left out\n", s.scene.dropped_degenerate);
}

} // namespace

std::string fit_scene_textures(Scene& scene, const DeviceBudget& budget,
                               std::optional<int> texture_max) {
    std::vector<std::string> before;
    for (const SceneTexture& t : scene.textures)
        before.push_back(std::to_string(t.width) + "x" + std::to_string(t.height));
    int n = fit_textures(scene.textures, texture_budget(budget), texture_max.value_or(0));
    if (n == 0) return "";
    std::string what;
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const SceneTexture& t = scene.textures[i];
        if (t.halvings == 0) continue;
        what += (what.empty() ? "" : ", ") + t.file + " " + std::to_string(t.width) + "x" +
                std::to_string(t.height) + " (from " + before[i] + ")";
    }
    return "textures halved " + std::to_string(n) + " time(s) to fit " +
           format_bytes(texture_budget(budget)) +
           (texture_max ? " and --texture-max " + std::to_string(*texture_max) : "") + ": " + what;
}

void print_scene_warnings(const Scene& scene) {
    for (const std::string& w : scene.warnings)
        std::fprintf(stderr, "smallmlt: %s\n", w.c_str());
}

int run_render(const RenderOptions& o, RankGroup& ranks) {
    InterruptGuard interrupts; // from here on, a signal stops the render cleanly
    Clock::time_point t_setup = Clock::now();
    RenderSetup s;
    set_up_every_rank(o, ranks, s);
    double setup_s = seconds_since(t_setup);
    // Every rank is set up, its kernels built; the render (MLT: its burn-in
    // first) begins. Flushed, so that a script can wait for it.
    if (!o.quiet && ranks.rank() == 0) {
        std::printf("set up in %.2f s; rendering\n", setup_s);
        std::fflush(stdout);
    }

    Progress progress(!o.quiet && ranks.rank() == 0);
    LoopLimits limits{o.spp, o.time_s, std::min(kPassSeconds, o.log_interval_s)};
    LoopResult r =
        render_loop(*s.method, limits, ranks.size() == 1 ? s.log.get() : nullptr, progress, ranks);

    // The image of every rank's tally, summed on rank 0.
    Tally t = s.method->tally();
    ranks.sum_to_root(t.ints);
    ranks.sum_to_root(t.reals);
    Image img;
    if (ranks.rank() == 0) {
        img = s.method->image_from(t);
        for (const std::string& f : o.outs)
            write_image(img, f);
        if (s.log) s.log->finish(r.render_s, s.method->spp_done() * ranks.size(), img);
    }
    print_summary(o, s, r, setup_s, ranks, img);
    if (r.interrupted) {
        if (ranks.rank() == 0)
            std::fprintf(stderr,
                         "smallmlt: interrupted after %.2f s; the image so far is written\n",
                         r.render_s);
        return kExitInterrupted;
    }
    return 0;
}

} // namespace smallmlt
