// `smallmlt budget`: device memory of an MLT render for every bounce depth,
// from the memory plan alone (no kernel is built, nothing is allocated).
#include "app/cli.hpp"
#include "app/commands.hpp"
#include "base/error.hpp"
#include "device/device_profile.hpp"
#include "device/memory_plan.hpp"

#include <algorithm>
#include <cstdio>

namespace smallmlt {

namespace {

struct BudgetRow {
    int depth, bits_per_bounce;
    std::uint64_t chain_packed, chain_float32, chains, state, other, total, naive;
};

BudgetRow budget_row(DeviceScene& ds, int depth, const ChainShape& shape,
                     const DeviceBudget& budget) {
    SceneFeatures f = ds.layout.features;
    f.depth = depth;
    ds.layout = make_layout(f);
    ds.frame.depth = std::uint32_t(depth);
    MemoryPlan plan = plan_mlt(ds, shape, budget.max_alloc_bytes);
    BudgetRow r;
    r.depth = depth;
    r.bits_per_bounce = ds.layout.bounce_bits;
    r.chain_packed = 4ull * ds.layout.chain_words(false);
    r.chain_float32 = 4ull * ds.layout.vector_dims();
    r.chains = shape.chains();
    r.state = plan.sum(true);
    r.other = plan.sum(false);
    r.total = plan.total();
    // A naive store: current and proposal vectors as float32 for every thread.
    r.naive = 2 * r.chain_float32 * shape.threads;
    return r;
}

void print_rows(const std::vector<BudgetRow>& rows, BudgetFormat fmt) {
    if (fmt == BudgetFormat::Csv)
        std::printf("depth,bits_per_bounce,chain_bytes_packed,chain_bytes_float32,chains,"
                    "state_bytes,other_bytes,total_bytes,naive_float32_bytes,reduction\n");
    if (fmt == BudgetFormat::Table)
        std::printf("%5s %6s %12s %13s %8s %11s %11s %11s %14s %9s\n", "depth", "bits/b",
                    "B/chain pack", "B/chain fp32", "chains", "state", "other", "total",
                    "naive fp32 x+y", "reduction");
    if (fmt == BudgetFormat::Json) std::printf("[\n");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const BudgetRow& r = rows[i];
        double reduction = double(r.naive) / double(r.state);
        if (fmt == BudgetFormat::Csv)
            std::printf("%d,%d,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%.3f\n", r.depth,
                        r.bits_per_bounce, (unsigned long long)r.chain_packed,
                        (unsigned long long)r.chain_float32, (unsigned long long)r.chains,
                        (unsigned long long)r.state, (unsigned long long)r.other,
                        (unsigned long long)r.total, (unsigned long long)r.naive, reduction);
        else if (fmt == BudgetFormat::Table)
            std::printf("%5d %6d %12llu %13llu %8llu %11s %11s %11s %14s %8.1fx\n", r.depth,
                        r.bits_per_bounce, (unsigned long long)r.chain_packed,
                        (unsigned long long)r.chain_float32, (unsigned long long)r.chains,
                        format_bytes(r.state).c_str(), format_bytes(r.other).c_str(),
                        format_bytes(r.total).c_str(), format_bytes(r.naive).c_str(), reduction);
        else
            std::printf(
                "  {\"depth\": %d, \"bits_per_bounce\": %d, \"chain_bytes_packed\": %llu, "
                "\"chain_bytes_float32\": %llu, \"chains\": %llu, \"state_bytes\": %llu, "
                "\"other_bytes\": %llu, \"total_bytes\": %llu, \"naive_float32_bytes\": %llu, "
                "\"reduction\": %.3f}%s\n",
                r.depth, r.bits_per_bounce, (unsigned long long)r.chain_packed,
                (unsigned long long)r.chain_float32, (unsigned long long)r.chains,
                (unsigned long long)r.state, (unsigned long long)r.other,
                (unsigned long long)r.total, (unsigned long long)r.naive, reduction,
                i + 1 < rows.size() ? "," : "");
    }
    if (fmt == BudgetFormat::Json) std::printf("]\n");
}

// The film's share at the scene's depth, and the least device memory that
// renders this scene and film by MLT (at kMinThreads) and by PT.
void print_film(const DeviceScene& ds, const ChainShape& shape, const DeviceBudget& budget) {
    MemoryPlan mlt = plan_mlt(ds, shape, budget.max_alloc_bytes);
    ChainShape least = shape;
    least.threads = kMinThreads;
    std::uint64_t mlt_min = smallest_device_memory(
        [&](std::uint64_t max_alloc) { return plan_mlt(ds, least, max_alloc); });
    std::uint64_t pt_min =
        smallest_device_memory([&](std::uint64_t max_alloc) { return plan_pt(ds, max_alloc); });
    std::printf("film %ux%u: %s in %u band(s), %.1f%% of the MLT render's %s; the least "
                "device memory that renders it: %s by MLT (%u threads), %s by PT\n",
                ds.frame.width, ds.frame.height, format_bytes(mlt.film()).c_str(), mlt.film_bands(),
                100.0 * double(mlt.film()) / double(mlt.total()), format_bytes(mlt.total()).c_str(),
                format_bytes(mlt_min).c_str(), kMinThreads, format_bytes(pt_min).c_str());
}

// Each texture and its size on the device, within the textures' budget.
void print_textures(const Scene& scene, const DeviceBudget& budget, const std::string& halved) {
    if (scene.textures.empty()) return;
    std::uint64_t total = 0;
    for (const SceneTexture& t : scene.textures)
        total += t.bytes();
    std::printf("textures: %zu, %s of %s allowed (8-bit RGBA texels)\n", scene.textures.size(),
                format_bytes(total).c_str(), format_bytes(texture_budget(budget)).c_str());
    for (const SceneTexture& t : scene.textures)
        std::printf("  %s: %dx%d, %s%s\n", t.file.c_str(), t.width, t.height,
                    format_bytes(t.bytes()).c_str(),
                    t.halvings ? (" (halved " + std::to_string(t.halvings) + "x)").c_str() : "");
    if (!halved.empty()) std::printf("note: %s\n", halved.c_str());
}

} // namespace

int run_budget(const BudgetOptions& o) {
    Scene scene = load_scene(o.scene);
    print_scene_warnings(scene);
    int max_depth = o.depth.value_or(scene.depth); // rows 1..max_depth, or 0 alone
    scene.depth = max_depth;
    if (o.width) scene.width = *o.width;
    if (o.height) scene.height = *o.height;
    std::vector<DeviceInfo> devs = cl_list_devices();
    if (o.device >= int(devs.size()))
        throw UsageError("--device: index " + std::to_string(o.device) + " out of range");
    DeviceInfo dev = devs[o.device];
    if (o.profile) dev = emulate_profile(dev, find_device_profile(*o.profile));
    require_work_group(dev);
    DeviceBudget budget = device_budget(dev, o.device_mem);
    std::string halved = fit_scene_textures(scene, budget, o.texture_max);
    DeviceScene ds = prepare_scene(scene);
    ChainShape shape = mlt_chain_shape(o.mlt);
    if (o.threads) {
        shape.threads = *o.threads;
        check_chain_shape(shape);
        check_threads(ds, shape, budget);
    } else {
        shape.threads = choose_threads(ds, shape, dev, budget).threads;
        check_chain_shape(shape);
    }
    if (o.format == BudgetFormat::Table) {
        std::printf("%s on %s: %u threads%s, %u proposal(s) per chain; device memory %s, "
                    "max allocation %s%s\n",
                    o.scene.c_str(), dev.name.c_str(), shape.threads, o.threads ? "" : " (auto)",
                    shape.proposals, format_bytes(budget.global_bytes).c_str(),
                    format_bytes(budget.max_alloc_bytes).c_str(),
                    budget.emulated ? " (emulated)" : "");
        print_film(ds, shape, budget);
        print_textures(scene, budget, halved);
    }
    std::vector<BudgetRow> rows;
    for (int d = std::min(1, max_depth); d <= max_depth; ++d)
        rows.push_back(budget_row(ds, d, shape, budget));
    print_rows(rows, o.format);
    return 0;
}

} // namespace smallmlt
