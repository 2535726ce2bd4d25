#include "device/memory_plan.hpp"

#include "base/bits.hpp"
#include "base/error.hpp"
#include "device/scan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace smallmlt {

namespace {

template <typename T> std::uint64_t vector_bytes(const std::vector<T>& v) {
    return std::uint64_t(v.size()) * sizeof(T);
}

void add_scene(MemoryPlan& p, const DeviceScene& ds) {
    p.buffers.push_back({"triangles", vector_bytes(ds.tris), false});
    p.buffers.push_back({"bvh", vector_bytes(ds.nodes), false});
    p.buffers.push_back({"materials", vector_bytes(ds.materials), false});
    p.buffers.push_back({"lights", vector_bytes(ds.lights), false});
}

std::uint64_t pixels(const DeviceScene& ds) {
    return std::uint64_t(ds.frame.width) * ds.frame.height;
}

bool is_chain_state(const std::string& name) {
    return name == "state" || name == "values";
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

std::uint64_t MemoryPlan::bytes(const std::string& name) const {
    for (const PlannedBuffer& b : buffers)
        if (b.name == name) return b.bytes;
    throw std::logic_error("no planned buffer " + name);
}

std::uint64_t MemoryPlan::sum(bool chain_state) const {
    std::uint64_t t = 0;
    for (const PlannedBuffer& b : buffers)
        if (is_chain_state(b.name) == chain_state) t += device_alloc_bytes(b.bytes);
    return t;
}

MemoryPlan plan_pt(const DeviceScene& ds) {
    MemoryPlan p;
    add_scene(p, ds);
    p.buffers.push_back({"accumulator", pixels(ds) * 4 * sizeof(float), false});
    p.buffers.push_back({"ray counts", pixels(ds) * sizeof(std::uint64_t), false});
    return p;
}

MemoryPlan plan_mlt(const DeviceScene& ds, const ChainShape& shape, std::size_t scan_wg) {
    MemoryPlan p;
    add_scene(p, ds);
    std::uint64_t chains = shape.chains(), threads = shape.threads;
    std::uint64_t words = ds.layout.chain_words(shape.float32_states);
    p.buffers.push_back({"state", words * chains * 4, false});
    p.buffers.push_back({"values", chains * sizeof(ChainValue), false});
    p.buffers.push_back({"splat", pixels(ds) * 3 * sizeof(std::uint64_t), false});
    p.buffers.push_back({"stats", MLT_STAT_COUNT * sizeof(std::uint64_t), false});
    p.buffers.push_back({"longest run", sizeof(std::uint32_t), false});
    // Each chain's start, (round, index) (cl/burnin.cl).
    p.buffers.push_back({"picks", chains * 2 * sizeof(std::uint32_t), false});
    p.buffers.push_back({"luminance", threads * sizeof(float), true});
    // The burn-in's 64-bit fixed-point weights, scanned in place (cl/burnin.cl).
    p.buffers.push_back({"scan", threads * sizeof(std::uint64_t), true});
    // Several buffers; their sum counts as one entry (at least as big as each).
    p.buffers.push_back({"scan blocks", scan_bytes(threads, scan_wg, sizeof(std::uint64_t)), true});
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

std::uint32_t busy_threads(const DeviceInfo& dev) {
    std::uint64_t want = std::uint64_t(std::max(1u, dev.compute_units)) *
                         std::max<std::uint64_t>(dev.max_work_group, 1) * 8;
    std::uint32_t n = 1u << 10;
    while (n < want && n < (1u << 20))
        n <<= 1;
    return n;
}

namespace {

MemoryPlan plan_for(const DeviceScene& ds, ChainShape shape, std::uint32_t threads,
                    const DeviceInfo& dev) {
    shape.threads = threads;
    return plan_mlt(ds, shape, scan_work_group(dev));
}

// Smallest device memory on which `plan` fits.
std::uint64_t memory_needed(const MemoryPlan& plan, bool emulated) {
    std::uint64_t by_total = std::uint64_t(std::ceil(double(plan.total()) / kMemoryFraction));
    return emulated ? std::max(by_total, 4 * plan.largest()) : by_total;
}

[[noreturn]] void too_small(const MemoryPlan& smallest, const DeviceBudget& budget) {
    throw InputError("not enough device memory: even " + std::to_string(kMinThreads) +
                     " threads need " + format_bytes(smallest.total()) + " (largest buffer " +
                     format_bytes(smallest.largest()) + "); the device allows " +
                     format_bytes(std::uint64_t(kMemoryFraction * double(budget.global_bytes))) +
                     " (max allocation " + format_bytes(budget.max_alloc_bytes) +
                     "); it would take " + format_bytes(memory_needed(smallest, budget.emulated)) +
                     " of device memory");
}

} // namespace

ThreadChoice choose_threads(const DeviceScene& ds, ChainShape shape, const DeviceInfo& dev,
                            const DeviceBudget& budget) {
    ThreadChoice c;
    std::uint32_t start = busy_threads(dev);
    for (std::uint32_t n = start; n >= kMinThreads; n /= 2) {
        c.plan = plan_for(ds, shape, n, dev);
        if (plan_fits(c.plan, budget)) {
            c.threads = n;
            c.reduction = start / n;
            return c;
        }
    }
    too_small(plan_for(ds, shape, kMinThreads, dev), budget);
}

MemoryPlan check_threads(const DeviceScene& ds, const ChainShape& shape, const DeviceInfo& dev,
                         const DeviceBudget& budget) {
    MemoryPlan plan = plan_for(ds, shape, shape.threads, dev);
    if (plan_fits(plan, budget)) return plan;
    std::uint32_t most = max_threads(ds, shape, dev, budget);
    if (most == 0) too_small(plan_for(ds, shape, kMinThreads, dev), budget);
    throw UsageError("--threads " + std::to_string(shape.threads) + " needs " +
                     format_bytes(plan.total()) + " of device memory (largest buffer " +
                     format_bytes(plan.largest()) + "); at most " + std::to_string(most) +
                     " threads fit (or use --threads auto)");
}

std::uint32_t max_threads(const DeviceScene& ds, ChainShape shape, const DeviceInfo& dev,
                          const DeviceBudget& budget) {
    if (plan_fits(plan_for(ds, shape, shape.threads, dev), budget)) return shape.threads;
    if (!plan_fits(plan_for(ds, shape, kMinThreads, dev), budget)) return 0;
    std::uint32_t lo = kMinThreads, hi = shape.threads; // fits at lo, not at hi
    while (hi - lo > 1) {
        std::uint32_t mid = lo + (hi - lo) / 2;
        (plan_fits(plan_for(ds, shape, mid, dev), budget) ? lo : hi) = mid;
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
