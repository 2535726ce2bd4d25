#include "render/render_loop.hpp"

#include "base/clock.hpp"
#include "base/interrupt.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

namespace smallmlt {

namespace {

constexpr std::uint32_t kMaxPassUnits = 4096;

// Render time: wall time since the start less the time spent measuring.
class RenderClock {
  public:
    double now() const { return wall() - paused_s_; }
    template <class F> void pause_for(F&& f) {
        double t = wall();
        f();
        paused_s_ += wall() - t;
    }

  private:
    double wall() const { return seconds_since(t0_); }
    Clock::time_point t0_ = Clock::now();
    double paused_s_ = 0;
};

void show_progress(Progress& progress, const Integrator& m, const LoopLimits& limits,
                   std::uint64_t done, std::uint64_t target, double render_s) {
    std::string spp = std::to_string(int(m.spp_done()));
    if (limits.spp)
        progress.update(double(done) / double(target),
                        spp + "/" + std::to_string(*limits.spp) + " per pixel");
    else
        progress.update(render_s / *limits.time_s, spp + " per pixel");
}

} // namespace

LoopResult render_loop(Integrator& m, const LoopLimits& limits, ConvergenceLog* log,
                       Progress& progress, RankGroup& ranks) {
    RenderClock clock;
    m.prepare(ranks);
    std::uint64_t target =
        limits.spp ? m.units_for_spp(*limits.spp, ranks.rank(), ranks.size()) : 0;
    std::uint64_t done = 0;
    std::uint32_t batch = 1;
    LoopResult r;
    for (;;) {
        double now = clock.now();
        if (log && log->due(now) && m.spp_done() > 0)
            clock.pause_for([&] { log->record(now, m.spp_done(), m.image()); });
        // Every rank votes once per pass: with --spp when its share is done,
        // with --time rank 0's clock decides for all, once every rank has
        // rendered a pass: a prepare (MLT's burn-in) that outlasts --time
        // must not leave the image without its units.
        bool finished = m.finished() || (limits.spp && done >= target);
        bool vote =
            finished || (!limits.spp && (ranks.rank() != 0 || (done > 0 && now >= *limits.time_s)));
        if (ranks.any(interrupt_requested())) {
            r.interrupted = true;
            break;
        }
        if (ranks.all(vote)) break;
        ++r.passes;
        if (finished) { // others still render
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            continue;
        }
        show_progress(progress, m, limits, done, target, now);
        std::uint64_t n = limits.spp ? std::min<std::uint64_t>(batch, target - done) : batch;
        double t = clock.now();
        m.advance(std::uint32_t(n));
        done += n;
        double per_unit = std::max(clock.now() - t, 1e-4) / double(n);
        double next = limits.pass_s / per_unit;
        if (limits.time_s)
            next = std::min(next, std::max(1.0, (*limits.time_s - clock.now()) / per_unit));
        // At most twice the last pass: a unit's cost may come in lumps (the
        // split's OMC part renders in chunks), and a pass that happened to
        // cost nothing must not set the next to the largest.
        batch = std::uint32_t(std::clamp(next, 1.0, std::min(double(kMaxPassUnits), 2.0 * n)));
    }
    r.render_s = clock.now();
    progress.finish();
    return r;
}

} // namespace smallmlt
