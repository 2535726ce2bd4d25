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
// device; PT only has to fit. Says what it chose unless quiet.
std::uint32_t fit_to_device(const RenderOptions& o, const ClContext& cl, const DeviceScene& ds) {
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
        if (!o.quiet)
            std::printf("film: %s in %u band(s); device memory %s of %s allowed\n",
                        format_bytes(plan.film()).c_str(), plan.film_bands(),
                        format_bytes(plan.total()).c_str(), allowed.c_str());
        return 0;
    }
    ChainShape shape;
    shape.proposals = o.proposals;
    shape.film_atomics64 = o.film_atomics64;
    if (o.threads) {
        shape.threads = *o.threads;
        check_chain_shape(shape);
        MemoryPlan plan = check_threads(ds, shape, cl.device(), budget);
        if (!o.quiet)
            std::printf("threads: %u (given); film %s in %u band(s); device memory %s of %s "
                        "allowed\n",
                        *o.threads, format_bytes(plan.film()).c_str(), plan.film_bands(),
                        format_bytes(plan.total()).c_str(), allowed.c_str());
        return *o.threads;
    }
    ThreadChoice c = choose_threads(ds, shape, cl.device(), budget);
    if (!o.quiet)
        std::printf("threads: %u (auto: %u keep the device busy, reduced %ux to fit); film %s "
                    "in %u band(s); device memory %s of %s allowed\n",
                    c.threads, busy_threads(cl.device()), c.reduction,
                    format_bytes(c.plan.film()).c_str(), c.plan.film_bands(),
                    format_bytes(c.plan.total()).c_str(), allowed.c_str());
    return c.threads;
}

std::unique_ptr<Integrator> make_integrator(const RenderOptions& o, const ClContext& cl,
                                            const DeviceScene& ds) {
    std::uint32_t threads = fit_to_device(o, cl, ds);
    std::uint64_t max_alloc = device_budget(cl.device(), o.device_mem).max_alloc_bytes;
    if (o.method == Method::Pt)
        return std::make_unique<PathTracer>(cl, ds, o.seed, o.sampler, max_alloc);
    MltOptions m;
    m.max_alloc_bytes = max_alloc;
    m.threads = threads;
    m.proposals = o.proposals;
    m.large_step = *o.large_step;
    m.seed = o.seed;
    m.burn_in = o.burn_in;
    m.burn_in_iters = o.burn_in_iters;
    m.stuck_run = o.stuck_run;
    m.film_atomics64 = o.film_atomics64;
    return std::make_unique<MltRenderer>(cl, ds, m);
}

} // namespace

int run_render(const RenderOptions& o) {
    InterruptGuard interrupts; // from here on, a signal stops the render cleanly
    Clock::time_point t_setup = Clock::now();
    check_output_dirs(o.outs);
    if (!o.log.empty()) check_output_dirs({o.log}, "--log");
    Scene scene = load_scene(o.scene);
    if (o.width) scene.width = *o.width;
    if (o.height) scene.height = *o.height;
    if (o.depth) scene.depth = *o.depth;
    scene.roulette = o.roulette;
    std::unique_ptr<ConvergenceLog> log;
    if (!o.reference.empty())
        log = std::make_unique<ConvergenceLog>(o.reference, o.log, o.log_interval_s, scene.width,
                                               scene.height);
    DeviceScene ds = prepare_scene(scene);
    ClContext cl(o.device);
    if (o.profile) cl.emulate(emulate_profile(cl.device(), find_device_profile(*o.profile)));
    std::unique_ptr<Integrator> method = make_integrator(o, cl, ds);
    double setup_s = seconds_since(t_setup);

    Progress progress(!o.quiet);
    LoopLimits limits{o.spp, o.time_s, std::min(kPassSeconds, o.log_interval_s)};
    LoopResult r = render_loop(*method, limits, log.get(), progress);

    Image img = method->image();
    for (const std::string& f : o.outs)
        write_image(img, f);
    if (log) log->finish(r.render_s, method->spp_done(), img);
    if (!o.quiet) {
        std::printf("%s: %dx%d, depth %d, %s: %.2f s (+%.2f s setup), %s\n", o.scene.c_str(),
                    scene.width, scene.height, scene.depth, o.method == Method::Pt ? "pt" : "mlt",
                    r.render_s, setup_s, method->summary(r.render_s).c_str());
        if (log)
            std::printf("error against %s: mse %.6g rel_mse %.6g\n", o.reference.c_str(),
                        log->last().mse, log->last().rel_mse);
        for (const std::string& note : method->notes())
            std::printf("note: %s\n", note.c_str());
        if (scene.dropped_degenerate)
            std::printf("note: %d zero-area triangle(s) left out\n", scene.dropped_degenerate);
    }
    if (r.interrupted) {
        std::fprintf(stderr, "smallmlt: interrupted after %.2f s; the image so far is written\n",
                     r.render_s);
        return kExitInterrupted;
    }
    return 0;
}

} // namespace smallmlt
