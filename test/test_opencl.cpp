// OpenCL trouble that can be provoked on any device: a kernel that does not
// build reports its log with the real file names, a launch the device
// refuses names the kernel and its sizes, and a device without the 64-bit
// atomics MLT needs is refused with a way out. (No platform at all is
// checked from the command line: test/cli_test.sh, no_platform.)
#include "base/error.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <stdexcept>

using namespace smallmlt;

TEST(OpenCl, BuildFailurePrintsTheLogWithFileAndLine) {
    // A define that breaks the shared header: the log must point into it.
    std::string msg = test::input_error_of([] {
        test::cl().build({"cl/core/shared_types.h", "cl/core/rng.h"}, "#define u32 @\n");
    });
    EXPECT_NE(msg.find("kernel build failed (CL_BUILD_PROGRAM_FAILURE)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("cl/core/shared_types.h:"), std::string::npos) << msg;
}

// Compilers that ignore #line (NVIDIA's names every line "<kernel>:N") get
// their line numbers mapped back to the embedded file and its own line.
TEST(OpenCl, AnonymousLogLinesNameTheEmbeddedFile) {
    std::vector<SourceStart> starts = {{"cl/core/shared_types.h", 4}, {"cl/core/rng.h", 120}};
    EXPECT_EQ(cl_name_log_lines("<kernel>:83:5: error: x\n<kernel>:121:2: note\n<kernel>:2:1: w "
                                "<kernel>:zz <kernel>:7",
                                starts),
              "cl/core/shared_types.h:80:5: error: x\ncl/core/rng.h:2:2: note\n(defines):2:1: w "
              "<kernel>:zz <kernel>:7");
}

TEST(OpenCl, RefusedLaunchNamesKernelAndSizes) {
    ClProgram program(test::probe_program());
    ClKernel k(program.p, "probe_layout");
    // Its argument set, so that the work-group size is all that is wrong
    // (Mesa's OpenCL checks the arguments first).
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, 256 * sizeof(cl_uint));
    k.set_args(out);
    std::size_t too_big = test::cl().device().max_work_group * 2;
    std::string msg = test::input_error_of([&] { k.enqueue(test::cl(), too_big, too_big); });
    EXPECT_NE(msg.find("kernel probe_layout over " + std::to_string(too_big) + " work-items"),
              std::string::npos)
        << msg;
    // Either error is the specification's answer: the group is larger than
    // the device's groups and than its first dimension.
    EXPECT_TRUE(msg.find("CL_INVALID_WORK_GROUP_SIZE") != std::string::npos ||
                msg.find("CL_INVALID_WORK_ITEM_SIZE") != std::string::npos)
        << msg;
}

// A kernel's arguments are set all at once: too few or too many is an
// error naming the kernel, and a unit sets all of its arguments.
TEST(OpenCl, EveryArgumentOfAKernelIsSet) {
    DeviceScene ds = prepare_scene(test::scene("cornell", 8, 8, 2));
    auto error_of = [](const std::function<void()>& f) -> std::string {
        try {
            f();
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    ClProgram program(test::cl().build(pt_program_files(PtSampler::Sobol), ds.layout.defines()));
    ClKernel k(program.p, "pt_render");
    SceneBuffers scene(test::cl(), ds);
    ClBuffer accum(test::cl(), CL_MEM_READ_WRITE, 64 * 3 * sizeof(float));
    std::string few = error_of([&] { k.set_args(scene, cl_ulong(1)); });
    EXPECT_NE(few.find("kernel pt_render takes 19 arguments, 10 were set"), std::string::npos)
        << few;
    std::string many = error_of([&] {
        k.set_args(scene, cl_ulong(1), cl_uint(0), cl_uint(1), cl_uint(0), cl_uint(1), LatePixels{},
                   cl_uint(0), cl_uint(64), accum, accum, cl_uint(0));
    });
    // (the driver may refuse the extra argument's index first)
    EXPECT_NE(many.find("pt_render"), std::string::npos) << many;
    EXPECT_EQ(error_of([&] {
                  k.set_args(scene, cl_ulong(1), cl_uint(0), cl_uint(1), cl_uint(0), cl_uint(1),
                             LatePixels{}, cl_uint(0), cl_uint(64), accum, accum);
              }),
              "");
}

// MLT needs 64-bit atomics only for the 64-bit reference film.
TEST(OpenCl, OnlyThe64BitFilmNeedsInt64Atomics) {
    DeviceInfo d = test::cl().device();
    d.int64_atomics = true;
    MltOptions film64;
    film64.film_atomics64 = true;
    EXPECT_EQ(test::input_error_of([&] { mlt_require_device(d, film64); }), "");
    d.int64_atomics = false;
    EXPECT_EQ(test::input_error_of([&] { mlt_require_device(d, MltOptions()); }), "");
    std::string msg = test::input_error_of([&] { mlt_require_device(d, film64); });
    EXPECT_NE(msg.find("lacks cl_khr_int64_base_atomics"), std::string::npos) << msg;
    EXPECT_NE(msg.find("--film-atomics 64"), std::string::npos) << msg;
}

// The device's loop limit (DeviceInfo::loop_iteration_limit) is what its
// compiler does: a loop of 2^21 iterations, more than any limit times the
// widest unrolling, runs to its end exactly where the device has no limit.
TEST(OpenCl, LoopIterationLimitIsWhatTheDeviceDoes) {
    ClProgram program(test::probe_program());
    ClKernel k(program.p, "probe_loop_count");
    std::vector<cl_uint> ones(64, 1u);
    ClBuffer in(test::cl(), CL_MEM_READ_ONLY, ones.size() * sizeof(cl_uint), ones.data());
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, sizeof(cl_uint));
    const cl_uint n = 1u << 21;
    k.set_args(in, n, out);
    k.run(test::cl(), 1, 1);
    cl_uint r = 0;
    out.read(test::cl(), &r);
    std::uint32_t limit = test::cl().device().loop_iteration_limit;
    std::printf("%s: %u of %u iterations ran; known limit %u\n", test::cl().device().name.c_str(),
                r, n, limit);
    if (limit == 0)
        EXPECT_EQ(r, n) << "the device stops loops early, and nothing says so";
    else
        EXPECT_LT(r, n) << "the device is said to stop loops, and it does not";
}

// Mesa's llvmpipe warns "Treating load_kernel_arg in control flow as
// uniform, results may be incorrect" when it builds a kernel that reads an
// argument where work-items diverge, as every kernel here does: reads of
// scalar, 64-bit and struct arguments there are right, item by item.
TEST(OpenCl, ArgumentsReadWhereWorkItemsDivergeAreRight) {
    ClProgram program(test::probe_program());
    ClKernel k(program.p, "probe_divergent_args");
    const std::uint32_t n = 256;
    ClBuffer out(test::cl(), CL_MEM_WRITE_ONLY, n * sizeof(cl_uint));
    Frame f{};
    f.width = 640;
    f.depth = 9;
    f.num_lights = 77;
    TargetCells c{5, 13};
    const cl_uint a = 1000;
    const cl_ulong b = 0x0000002A00000007ull;
    k.set_args(out, a, b, f, c);
    k.run(test::cl(), n);
    std::vector<cl_uint> got(n);
    out.read(test::cl(), got.data());
    for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t r = 0;
        if (i % 7 == 3) {
            r = ~0u;
        } else {
            if (i % 3 == 1) r += a + f.depth;
            r += (i % 5) * (std::uint32_t(b >> 32) + c.columns + f.width);
            if (i & 1) r ^= std::uint32_t(b) + c.shift + f.num_lights;
        }
        ASSERT_EQ(got[i], r) << "work-item " << i;
    }
}
