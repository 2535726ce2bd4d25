#include "render_command.hpp"

#include "error.hpp"
#include "path_tracer.hpp"
#include "progress.hpp"
#include "scene.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <unistd.h>

namespace smallmlt {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Fails early, before a long render, if an output could not be written.
void check_output_dirs(const std::vector<std::string>& outs) {
    for (const std::string& f : outs) {
        std::size_t slash = f.find_last_of('/');
        std::string dir = slash == std::string::npos ? "." : f.substr(0, slash + 1);
        if (access(dir.c_str(), W_OK) != 0)
            throw UsageError("--out " + f + ": directory " + dir +
                             " does not exist or is not writable");
    }
}

constexpr double kPassSeconds = 0.25; // target duration of one kernel launch

} // namespace

int run_render(const RenderOptions& o) {
    Clock::time_point t_setup = Clock::now();
    check_output_dirs(o.outs);
    Scene scene = load_scene(o.scene);
    if (o.width) scene.width = *o.width;
    if (o.height) scene.height = *o.height;
    if (o.depth) scene.depth = *o.depth;
    DeviceScene ds = prepare_scene(scene);
    ClContext cl(o.device);
    PathTracer pt(cl, ds, o.seed);
    double setup_s = seconds_since(t_setup);

    Progress progress(!o.quiet);
    Clock::time_point t0 = Clock::now();
    std::uint32_t batch = 1;
    for (;;) {
        double elapsed = seconds_since(t0);
        std::uint32_t n = batch;
        if (o.spp) {
            if (pt.spp() >= *o.spp) break;
            n = std::min(n, *o.spp - pt.spp());
            progress.update(double(pt.spp()) / *o.spp,
                            std::to_string(pt.spp()) + "/" + std::to_string(*o.spp) + " spp");
        } else {
            if (elapsed >= *o.time_s) break;
            progress.update(elapsed / *o.time_s, std::to_string(pt.spp()) + " spp");
        }
        Clock::time_point tp = Clock::now();
        pt.add_samples(n);
        double pass_s = std::max(seconds_since(tp), 1e-4);
        double per_sample = pass_s / n;
        double next = kPassSeconds / per_sample;
        if (o.time_s)
            next = std::min(next, std::max(1.0, (*o.time_s - seconds_since(t0)) / per_sample));
        batch = std::uint32_t(std::clamp(next, 1.0, 4096.0));
    }
    double render_s = seconds_since(t0);
    progress.finish();

    Image img = pt.image();
    for (const std::string& f : o.outs)
        write_image(img, f);
    if (!o.quiet) {
        double paths = double(pt.spp()) * double(pt.pixels());
        std::printf("%s: %dx%d, %u spp, depth %d: %.2f s (+%.2f s setup), %.3f M paths/s, "
                    "%.3f M rays/s\n",
                    o.scene.c_str(), scene.width, scene.height, pt.spp(), scene.depth, render_s,
                    setup_s, paths / render_s * 1e-6, double(pt.rays()) / render_s * 1e-6);
        if (scene.dropped_degenerate)
            std::printf("note: %d zero-area triangle(s) left out\n", scene.dropped_degenerate);
    }
    return 0;
}

int run_devices() {
    std::vector<DeviceInfo> devs = cl_list_devices();
    for (std::size_t i = 0; i < devs.size(); ++i) {
        const DeviceInfo& d = devs[i];
        std::printf("%zu: %s (%s)\n   %s, %s\n   %u compute units, global memory %.1f MiB, "
                    "max allocation %.1f MiB, local memory %.1f KiB%s\n",
                    i, d.name.c_str(), d.platform_name.c_str(), d.version.c_str(),
                    d.c_version.c_str(), d.compute_units, d.global_mem_bytes / 1048576.0,
                    d.max_alloc_bytes / 1048576.0, d.local_mem_bytes / 1024.0,
                    d.int64_atomics ? ", 64-bit atomics" : "");
    }
    return 0;
}

} // namespace smallmlt
