#include "device/memory_plan.hpp"

#include "base/bits.hpp"
#include "base/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <thread>

namespace smallmlt {

namespace {

template <typename T> std::uint64_t vector_bytes(const std::vector<T>& v) {
    return std::uint64_t(v.size()) * sizeof(T);
}

void add(MemoryPlan& p, Buffer kind, std::uint64_t bytes) {
    p.buffers.push_back({kind, 0, bytes});
}

void add_scene(MemoryPlan& p, const DeviceScene& ds) {
    add(p, Buffer::Triangles, vector_bytes(ds.tris));
    add(p, Buffer::Bvh, vector_bytes(ds.nodes));
    add(p, Buffer::Normals, vector_bytes(ds.normals));
    add(p, Buffer::Uvs, vector_bytes(ds.uvs));
    add(p, Buffer::Textures, vector_bytes(ds.textures));
    add(p, Buffer::Texels, vector_bytes(ds.texels));
    add(p, Buffer::Materials, vector_bytes(ds.materials));
    add(p, Buffer::Lights, vector_bytes(ds.lights));
}

std::uint64_t pixels(const DeviceScene& ds) {
    return std::uint64_t(ds.frame.width) * ds.frame.height;
}

bool is_chain_state(Buffer b) {
    return b == Buffer::State || b == Buffer::Values;
}

void add_film(MemoryPlan& p, std::uint64_t pixels, std::uint64_t bytes_per_pixel,
              std::uint64_t max_alloc) {
    FilmBands split = film_bands(pixels, bytes_per_pixel, max_alloc);
    for (std::uint32_t b = 0; b < split.bands; ++b) {
        std::uint64_t first = b * split.band_pixels;
        std::uint64_t n = std::min(split.band_pixels, pixels - first);
        p.buffers.push_back({Buffer::FilmBand, b, n * bytes_per_pixel});
    }
}

// Rows of per-work-group counters for `items` work-items.
std::uint64_t group_rows(std::uint64_t items) {
    return (items + kDefaultWorkGroup - 1) / kDefaultWorkGroup;
}

} // namespace

std::uint64_t MemoryPlan::total() const {
    std::uint64_t t = 0;
    for (const PlannedBuffer& b : buffers)
        t += device_alloc_bytes(b.bytes);
    return t;
}

std::uint64_t MemoryPlan::largest() const {
    std::uint64_t m = 0;
    for (const PlannedBuffer& b : buffers)
        m = std::max(m, device_alloc_bytes(b.bytes));
    return m;
}

const char* buffer_name(Buffer b) {
    switch (b) {
#define SMALLMLT_BUFFER_NAME(e, name)                                                              \
    case Buffer::e:                                                                                \
        return name;
        SMALLMLT_BUFFERS(SMALLMLT_BUFFER_NAME)
#undef SMALLMLT_BUFFER_NAME
    }
    return "?";
}

std::uint64_t MemoryPlan::bytes(Buffer kind) const {
    for (const PlannedBuffer& b : buffers)
        if (b.kind == kind) return b.bytes;
    throw std::logic_error(std::string("no planned buffer ") + buffer_name(kind));
}

std::uint64_t MemoryPlan::sum(bool chain_state) const {
    std::uint64_t t = 0;
    for (const PlannedBuffer& b : buffers)
        if (is_chain_state(b.kind) == chain_state) t += device_alloc_bytes(b.bytes);
    return t;
}

std::uint64_t MemoryPlan::film() const {
    std::uint64_t t = 0;
    for (const PlannedBuffer& b : buffers)
        if (b.kind == Buffer::FilmBand) t += device_alloc_bytes(b.bytes);
    return t;
}

std::uint32_t MemoryPlan::film_bands() const {
    return std::uint32_t(std::count_if(buffers.begin(), buffers.end(), [](const PlannedBuffer& b) {
        return b.kind == Buffer::FilmBand;
    }));
}

FilmBands film_bands(std::uint64_t pixels, std::uint64_t bytes_per_pixel, std::uint64_t max_alloc) {
    std::uint64_t fit = max_alloc / bytes_per_pixel / kDefaultWorkGroup * kDefaultWorkGroup;
    if (fit == 0)
        throw InputError("the device's largest allocation, " + format_bytes(max_alloc) +
                         ", cannot hold the film of one work-group of " +
                         std::to_string(kDefaultWorkGroup) + " pixels");
    FilmBands b;
    std::uint64_t whole = (pixels + kDefaultWorkGroup - 1) / kDefaultWorkGroup * kDefaultWorkGroup;
    b.band_pixels = std::min(fit, std::max<std::uint64_t>(whole, kDefaultWorkGroup));
    b.bands =
        std::uint32_t(std::max<std::uint64_t>(1, (pixels + b.band_pixels - 1) / b.band_pixels));
    return b;
}

std::uint64_t mlt_film_pixel_bytes(bool atomics64, std::uint32_t layers) {
    return 3 * std::uint64_t(layers) * (atomics64 ? sizeof(std::uint64_t) : sizeof(std::uint32_t));
}

std::uint64_t omc_scratch_pixels(std::uint64_t pixels) {
    std::uint64_t whole = (pixels + kDefaultWorkGroup - 1) / kDefaultWorkGroup * kDefaultWorkGroup;
    return std::min<std::uint64_t>(whole, 16384);
}

MemoryPlan plan_pt(const DeviceScene& ds, std::uint64_t max_alloc) {
    MemoryPlan p;
    add_scene(p, ds);
    add_film(p, pixels(ds), kPtFilmPixelBytes, max_alloc);
    add(p, Buffer::Stats, group_rows(pixels(ds)) * PT_STAT_COUNT * sizeof(std::uint64_t));
    return p;
}

MemoryPlan plan_mlt(const DeviceScene& ds, const ChainShape& shape, std::uint64_t max_alloc) {
    MemoryPlan p;
    add_scene(p, ds);
    std::uint64_t chains = shape.chains(), threads = shape.threads;
    std::uint64_t words = ds.layout.chain_words(shape.float32_states);
    add(p, Buffer::State, words * chains * 4);
    add(p, Buffer::Values, chains * sizeof(ChainValue));
    add_film(p, pixels(ds), mlt_film_pixel_bytes(shape.film_atomics64, shape.film_layers),
             max_alloc);
    add(p, Buffer::Stats, group_rows(threads) * MLT_STAT_COUNT * sizeof(std::uint64_t));
    // Each chain's start, (round, index) (src/render/start_picks.hpp).
    add(p, Buffer::Picks, chains * 2 * sizeof(std::uint32_t));
    add(p, Buffer::TargetWeights, shape.target_cells * sizeof(float));
    // The strata (src/render/strata.hpp): at most a tile per work-group, and
    // the group's tile.
    const std::uint64_t groups = group_rows(threads), tiles = shape.strata ? groups : 1;
    add(p, Buffer::StrataTiles, tiles * sizeof(FilmTile));
    add(p, Buffer::StrataWeights, tiles * sizeof(StratumWeights));
    add(p, Buffer::GroupTiles, groups * sizeof(std::uint32_t));
    // A burn-in round's luminances, read back for the picks.
    add(p, Buffer::Luminance, threads * sizeof(float));
    if (shape.omc_part) {
        // The OMC part's scratch band and counters (src/render/path_tracer.hpp).
        add(p, Buffer::OmcScratchBand, omc_scratch_pixels(pixels(ds)) * kPtFilmPixelBytes);
        add(p, Buffer::OmcStats, group_rows(pixels(ds)) * PT_STAT_COUNT * sizeof(std::uint64_t));
    }
    // The parts and pixel of each burn-in sample (cl/kernels/mlt.cl): for a
    // split, and for the two-stage target's weights.
    if (shape.omc_part || shape.target_cells > 1)
        add(p, Buffer::OmcSamples, threads * 8 * sizeof(float));
    return p;
}

void check_chain_shape(const ChainShape& shape) {
    std::uint32_t k = shape.proposals;
    if (!is_power_of_two(k) || k > kDefaultWorkGroup)
        throw UsageError("--proposals: " + std::to_string(k) + " is not a power of two up to " +
                         std::to_string(kDefaultWorkGroup));
    if (shape.threads % k)
        throw UsageError("--threads " + std::to_string(shape.threads) + " is not a multiple of " +
                         "--proposals " + std::to_string(k));
}

std::uint64_t texture_budget(const DeviceBudget& b) {
    return std::min(b.max_alloc_bytes, std::uint64_t(kTextureFraction * double(b.global_bytes)));
}

DeviceBudget device_budget(const DeviceInfo& dev, std::optional<std::uint64_t> device_mem) {
    DeviceBudget b{dev.global_mem_bytes, dev.max_alloc_bytes, false};
    if (device_mem) {
        b.global_bytes = std::min(*device_mem, dev.global_mem_bytes);
        b.max_alloc_bytes = std::min(dev.max_alloc_bytes, b.global_bytes / 4);
        b.emulated = true;
    }
    return b;
}

bool plan_fits(const MemoryPlan& plan, const DeviceBudget& b) {
    return double(plan.total()) <= kMemoryFraction * double(b.global_bytes) &&
           plan.largest() <= b.max_alloc_bytes;
}

std::uint64_t smallest_device_memory(const std::function<MemoryPlan(std::uint64_t)>& plan_at) {
    auto fits = [&](std::uint64_t m) {
        try {
            return plan_fits(plan_at(m / 4), DeviceBudget{m, m / 4, true});
        } catch (const InputError&) {
            return false; // the film cannot be split that finely
        }
    };
    std::uint64_t lo = 0, hi = std::uint64_t(1) << 50; // fits at hi, not at lo
    if (!fits(hi)) return hi;
    while (hi - lo > 1) {
        std::uint64_t mid = lo + (hi - lo) / 2;
        (fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

void require_work_group(const DeviceInfo& dev) {
    if (dev.max_work_group < kDefaultWorkGroup)
        throw InputError("device " + dev.name + " runs work-groups of at most " +
                         std::to_string(dev.max_work_group) + " work-items; smallmlt's kernels " +
                         "run in work-groups of " + std::to_string(kDefaultWorkGroup));
}

std::uint32_t busy_threads(const DeviceInfo& dev) {
    std::uint64_t per_unit =
        dev.cpu ? kCpuThreadsPerCore : std::max<std::uint64_t>(dev.max_work_group, 1) * 8;
    std::uint32_t units = std::max(1u, dev.compute_units);
    // A CPU device runs on this machine's cores, however many compute units
    // it reports (Mesa's llvmpipe reports 8 on 2 cores).
    if (dev.cpu) units = std::min(units, std::max(1u, std::thread::hardware_concurrency()));
    std::uint64_t want = std::uint64_t(units) * per_unit;
    std::uint32_t n = 1u << 10;
    while (n < want && n < (1u << 20))
        n <<= 1;
    return n;
}

namespace {

MemoryPlan plan_for(const DeviceScene& ds, ChainShape shape, std::uint32_t threads,
                    const DeviceBudget& budget) {
    shape.threads = threads;
    return plan_mlt(ds, shape, budget.max_alloc_bytes);
}

[[noreturn]] void too_small(const DeviceScene& ds, const ChainShape& shape,
                            const DeviceBudget& budget) {
    MemoryPlan smallest = plan_for(ds, shape, kMinThreads, budget);
    std::uint64_t needed = smallest_device_memory([&](std::uint64_t max_alloc) {
        return plan_for(ds, shape, kMinThreads, DeviceBudget{0, max_alloc, true});
    });
    throw InputError("not enough device memory: even " + std::to_string(kMinThreads) +
                     " threads need " + format_bytes(smallest.total()) + " (largest buffer " +
                     format_bytes(smallest.largest()) + "); the device allows " +
                     format_bytes(std::uint64_t(kMemoryFraction * double(budget.global_bytes))) +
                     " (max allocation " + format_bytes(budget.max_alloc_bytes) +
                     "); it would take " + format_bytes(needed) + " of device memory" +
                     (shape.film_layers > 1 ? " (--weights expected halves its film of " +
                                                  format_bytes(smallest.film()) + ")"
                                            : std::string()));
}

} // namespace

ThreadChoice choose_threads(const DeviceScene& ds, ChainShape shape, const DeviceInfo& dev,
                            const DeviceBudget& budget) {
    ThreadChoice c;
    std::uint32_t start = busy_threads(dev);
    for (std::uint32_t n = start; n >= kMinThreads; n /= 2) {
        c.plan = plan_for(ds, shape, n, budget);
        if (plan_fits(c.plan, budget)) {
            c.threads = n;
            c.reduction = start / n;
            return c;
        }
    }
    too_small(ds, shape, budget);
}

MemoryPlan check_threads(const DeviceScene& ds, const ChainShape& shape,
                         const DeviceBudget& budget) {
    MemoryPlan plan = plan_for(ds, shape, shape.threads, budget);
    if (plan_fits(plan, budget)) return plan;
    std::uint32_t most = max_threads(ds, shape, budget);
    if (most == 0) too_small(ds, shape, budget);
    throw UsageError("--threads " + std::to_string(shape.threads) + " needs " +
                     format_bytes(plan.total()) + " of device memory (largest buffer " +
                     format_bytes(plan.largest()) + "); at most " + std::to_string(most) +
                     " threads fit (or use --threads auto)");
}

std::uint32_t max_threads(const DeviceScene& ds, ChainShape shape, const DeviceBudget& budget) {
    if (plan_fits(plan_for(ds, shape, shape.threads, budget), budget)) return shape.threads;
    if (!plan_fits(plan_for(ds, shape, kMinThreads, budget), budget)) return 0;
    std::uint32_t lo = kMinThreads, hi = shape.threads; // fits at lo, not at hi
    while (hi - lo > 1) {
        std::uint32_t mid = lo + (hi - lo) / 2;
        (plan_fits(plan_for(ds, shape, mid, budget), budget) ? lo : hi) = mid;
    }
    return lo;
}

std::string format_bytes(std::uint64_t bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    double v = double(bytes);
    int u = 0;
    while (v >= 1024 && u < 4)
        v /= 1024, ++u;
    char buf[32];
    std::snprintf(buf, sizeof buf, u ? "%.1f %s" : "%.0f %s", v, units[u]);
    return buf;
}

} // namespace smallmlt
