// Memory budget: the plan predicts exactly what a render allocates, and the
// thread count follows the device memory and its largest allocation.
#include "base/error.hpp"
#include "device/memory_plan.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>

using namespace smallmlt;

namespace {

struct Case {
    const char* scene;
    std::uint32_t threads, proposals;
    int depth;
    Split split = Split::None;
};

// The MLT render of `c`: 2 rounds of burn-in.
MltOptions case_options(const Case& c) {
    MltOptions opt = test::plain_mlt();
    opt.threads = c.threads;
    opt.proposals = c.proposals;
    opt.burn_in_iters = 2;
    opt.split = c.split;
    return opt;
}

// Device bytes a full MLT render (burn-in, steps, image) allocates at its peak.
std::uint64_t mlt_peak(const DeviceScene& ds, const MltOptions& opt) {
    const ClContext& cl = test::cl();
    std::uint64_t before = cl.live_bytes();
    cl.reset_peak();
    {
        MltRenderer mlt(cl, ds, opt);
        mlt.prepare();
        mlt.step(1);
        mlt.image();
    }
    EXPECT_EQ(cl.live_bytes(), before) << "buffers leaked";
    return cl.peak_bytes() - before;
}

} // namespace

// A renderer that kept a chain state per thread with K proposals per chain
// would allocate more than the plan's N / K states.
TEST(MemoryPlan, PredictsWhatMltRendersAllocate) {
    for (Case c :
         {Case{"cornell-water", 1024, 1, 24}, Case{"cornell", 4096, 1, 3},
          Case{"cornell-glass", 704, 1, 16}, Case{"ajar", 64, 1, 1},
          Case{"cornell-water", 1024, 2, 24}, Case{"cornell", 4096, 4, 8},
          Case{"cornell-glass", 512, 8, 16}, Case{"cornell-water", 1024, 1, 24, Split::Direct},
          Case{"cornell", 4096, 4, 8, Split::Visible}}) {
        DeviceScene ds = prepare_scene(test::scene(c.scene, 24, 16, c.depth));
        const MltOptions opt = case_options(c);
        MemoryPlan plan = plan_mlt(ds, mlt_chain_shape(opt));
        EXPECT_EQ(plan.bytes(Buffer::Values),
                  std::uint64_t(c.threads / c.proposals) * sizeof(ChainValue));
        EXPECT_EQ(mlt_peak(ds, opt), plan.total())
            << c.scene << " N " << c.threads << " K " << c.proposals << " split "
            << split_name(c.split);
    }
}

TEST(MemoryPlan, PredictsWhatPathTracingAllocates) {
    DeviceScene ds = prepare_scene(test::scene("cornell-glass", 40, 30));
    const ClContext& cl = test::cl();
    std::uint64_t before = cl.live_bytes();
    cl.reset_peak();
    test::render_pt(ds, 1, 1);
    EXPECT_EQ(cl.peak_bytes() - before, plan_pt(ds).total());
}

// Proposals per chain divide the chain states, not the per-thread buffers.
TEST(MemoryPlan, ProposalsShareChainStates) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 16, 16));
    MemoryPlan k1 = plan_mlt(ds, ChainShape{4096, 1, false});
    MemoryPlan k4 = plan_mlt(ds, ChainShape{4096, 4, false});
    EXPECT_EQ(k4.bytes(Buffer::State) * 4, k1.bytes(Buffer::State));
    EXPECT_EQ(k4.bytes(Buffer::Values) * 4, k1.bytes(Buffer::Values));
    EXPECT_EQ(k4.bytes(Buffer::Luminance), k1.bytes(Buffer::Luminance));
}

// The burn-in keeps each thread's luminance (4 bytes) on the device, read
// back for the picks (src/render/start_picks.hpp); each chain its pick,
// (round, index).
TEST(MemoryPlan, BurnInKeepsALuminanceAThreadAndAPickAChain) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 16, 16));
    MemoryPlan p = plan_mlt(ds, ChainShape{4096, 2, false});
    EXPECT_EQ(p.bytes(Buffer::Luminance), 4096u * 4);
    EXPECT_EQ(p.bytes(Buffer::Picks), 2048u * 8); // (round, index) per chain
}

// Smaller budgets give fewer threads, and a render with the chosen count
// stays within the budget's fraction and its largest-allocation limit.
TEST(ThreadCount, FollowsTheDeviceMemory) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 128, 128));
    const DeviceInfo& dev = test::cl().device();
    std::uint32_t previous = ~0u;
    for (std::uint64_t mib : {256u, 64u, 16u}) {
        DeviceBudget budget = device_budget(dev, mib << 20);
        ThreadChoice c = choose_threads(ds, ChainShape{}, dev, budget);
        EXPECT_LE(c.threads, previous) << mib << " MiB";
        previous = c.threads;
        std::uint64_t peak = mlt_peak(ds, case_options(Case{"cornell-water", c.threads, 1, 0}));
        EXPECT_EQ(peak, c.plan.total());
        EXPECT_LE(double(peak), kMemoryFraction * double(budget.global_bytes)) << mib << " MiB";
        EXPECT_LE(c.plan.largest(), budget.max_alloc_bytes) << mib << " MiB";
    }
    EXPECT_LT(previous, busy_threads(dev)) << "16 MiB should force fewer threads";
}

// A CPU device runs on this machine's hardware threads: reporting more
// compute units than that (Mesa's llvmpipe reports 8 on 2 cores) gives no
// more threads; a GPU's count follows its compute units.
TEST(ThreadCount, CpuDeviceCountsThisMachinesCores) {
    DeviceInfo d;
    d.cpu = true;
    d.max_work_group = 1024;
    const std::uint32_t hw = std::max(1u, std::thread::hardware_concurrency());
    d.compute_units = hw;
    const std::uint32_t own = busy_threads(d);
    EXPECT_EQ(own, std::uint32_t(1)
                       << std::uint32_t(std::ceil(std::log2(hw * kCpuThreadsPerCore))));
    d.compute_units = 4 * hw;
    EXPECT_EQ(busy_threads(d), own);
    d.cpu = false;
    EXPECT_GT(busy_threads(d), own);
}

// Total memory to spare, but a single-buffer limit below the state buffer:
// the count drops until the largest buffer fits.
TEST(ThreadCount, RespectsTheLargestAllocation) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 64, 64));
    const DeviceInfo& dev = test::cl().device();
    DeviceBudget roomy{std::uint64_t(1) << 40, std::uint64_t(1) << 40, false};
    ThreadChoice free_choice = choose_threads(ds, ChainShape{}, dev, roomy);
    DeviceBudget capped = roomy;
    capped.max_alloc_bytes = free_choice.plan.largest() / 3;
    ThreadChoice c = choose_threads(ds, ChainShape{}, dev, capped);
    EXPECT_LT(c.threads, free_choice.threads);
    EXPECT_LE(c.plan.largest(), capped.max_alloc_bytes);
}

TEST(ThreadCount, TooLittleMemoryNamesWhatWouldDo) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 64, 64));
    DeviceBudget tiny = device_budget(test::cl().device(), std::uint64_t(64) << 10);
    try {
        choose_threads(ds, ChainShape{}, test::cl().device(), tiny);
        FAIL() << "64 KiB should not fit";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("it would take"), std::string::npos) << e.what();
    }
    ChainShape given;
    given.threads = 1u << 20;
    DeviceBudget small = device_budget(test::cl().device(), std::uint64_t(64) << 20);
    try {
        check_threads(ds, given, small);
        FAIL() << "2^20 threads should not fit in 64 MiB";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("threads fit"), std::string::npos) << e.what();
    }
}
