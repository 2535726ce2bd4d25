// Device profiles (doc/devices.md): the device at hand, limited to each
// profile, renders cornell-water within the profile's memory, and renders
// it exactly as the unlimited device does with the same options: a profile
// changes the budget, the film's bands and what may compile, never the
// arithmetic. So each profile's image is the one the render tests
// (test/test_render_blocks.cpp) compare with PT. A profile without 64-bit
// atomics compiles no 64-bit atomic at all.
#include "base/error.hpp"
#include "device/device_profile.hpp"
#include "device/memory_plan.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace smallmlt;

namespace {

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(DeviceProfiles, EveryProfileRendersWithinItsMemoryAsTheDeviceDoes) {
    DeviceScene ds = prepare_scene(test::scene("cornell-water", 32, 32));
    MltOptions opt = test::plain_mlt();
    opt.threads = 1024;
    opt.burn_in_iters = 4;
    opt.film_pass_mutations = 4096;
    opt.seed = 61;
    std::vector<float> plain;
    {
        MltRenderer m(test::cl(), ds, opt);
        m.prepare();
        m.step(12);
        plain = m.image().rgb;
    }
    int rendered = 0;
    for (const DeviceProfile& p : device_profiles()) {
        DeviceInfo dev = emulate_profile(test::cl().device(), p);
        EXPECT_LE(dev.global_mem_bytes, p.global_mem_bytes) << p.name;
        EXPECT_EQ(dev.int64_atomics, p.int64_atomics && test::cl().device().int64_atomics);
        if (p.max_work_group < kDefaultWorkGroup) {
            std::string msg = error_of([&] { require_work_group(dev); });
            EXPECT_NE(msg.find("at most " + std::to_string(p.max_work_group) + " work-items"),
                      std::string::npos)
                << p.name << ": " << msg;
            continue;
        }
        DeviceBudget budget = device_budget(dev, std::nullopt);
        ThreadChoice auto_choice = choose_threads(ds, ChainShape{}, dev, budget);
        EXPECT_GE(auto_choice.threads, kMinThreads) << p.name;
        ClContext cl(0);
        cl.emulate(dev);
        MltRenderer m(cl, ds, opt);
        m.prepare();
        m.step(12);
        EXPECT_LE(double(cl.peak_bytes()), kMemoryFraction * double(budget.global_bytes)) << p.name;
        EXPECT_EQ(m.image().rgb, plain) << p.name;
        std::printf("%s: auto threads %u; 1,024 threads render as on the device itself\n",
                    p.name.c_str(), auto_choice.threads);
        ++rendered;
        if (dev.int64_atomics) continue;
        // The 64-bit film does not compile here, and MLT refuses to try.
        MltOptions wide = opt;
        wide.film_atomics64 = true;
        EXPECT_NE(error_of([&] { MltRenderer r(cl, ds, wide); }).find("leave out --film-atomics"),
                  std::string::npos);
        std::string build = error_of([&] {
            ClProgram prog(cl.build(mlt_program_files(), ds.layout.defines() +
                                                             "#define MLT_GROUP 64u\n"
                                                             "#define FILM_ATOMICS64 1\n"));
        });
        EXPECT_NE(build.find("needs_cl_khr_int64_base_atomics"), std::string::npos) << build;
    }
    EXPECT_GE(rendered, 3);
}
